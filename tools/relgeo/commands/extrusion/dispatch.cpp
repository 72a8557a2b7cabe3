// tools/relgeo/commands/extrusion/dispatch.cpp — relgeo::check_extrusion
// under every kernel and hull algorithm (CGAL Epeck included).
#include <chrono>

#include "commands/extrusion/facade.h"
#include "commands/hull/facade.h"
#include "kernels/cgal_kernels.h"
#include "kernels/dispatch.h"
#include "relgeo/hull/cgal_convex_hull.h"

namespace relgeo::tool {

namespace {

/// CGAL::convex_hull_2 as a hull function object for Cgal_kernel<CK>.
struct Cgal_hull {
  template <class K>
  Hull_result<typename K::Point_2> operator()(std::span<const typename K::Point_2> p, const K& k) const {
    if constexpr (is_cgal_kernel_v<K>) return cgal_convex_hull<typename K::Cgal>(p, Cgal_hull_algorithm::convex_hull_2, k);
    else throw Usage_error("algorithm 'cgal' needs a cgal-* kernel");
  }
};

}  // namespace

Extrusion_report run_extrusion(std::string_view algorithm, std::string_view kernel, const Bezier_contour& contour,
                               const Extrusion_options& options, double* time_s, double min_seconds) {
  validate_hull_combination(algorithm, kernel);
  return with_kernel(kernel, [&]<class K>(const K& k) {
    auto once = [&]() -> Extrusion_report {
      if (algorithm == "graham-fortune") return check_extrusion<K>(contour, options, k, Graham_fortune_hull{});
      if (algorithm == "monotone-chain") return check_extrusion<K>(contour, options, k, Monotone_chain_hull{});
      if (algorithm == "graham-incremental") return check_extrusion<K>(contour, options, k, Graham_incremental_hull{});
      if constexpr (is_cgal_kernel_v<K>) return check_extrusion<K>(contour, options, k, Cgal_hull{});
      throw Usage_error("algorithm '" + std::string(algorithm) + "' cannot run under kernel '" + std::string(kernel) + "'");
    };
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    double best = -1;
    Extrusion_report rep;
    for (int runs = 0;; ++runs) {
      const auto t0 = Clock::now();
      Extrusion_report r = once();
      const auto t1 = Clock::now();
      const double t = std::chrono::duration<double>(t1 - t0).count();
      if (best < 0 || t < best) best = t;
      if (runs == 0) rep = std::move(r);
      if (std::chrono::duration<double>(t1 - start).count() >= min_seconds) break;
    }
    if (time_s) *time_s = best;
    return rep;
  });
}

}  // namespace relgeo::tool
