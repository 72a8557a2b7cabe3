// Fuzz harness: check_extrusion (relgeo/curves.h) on arbitrary closed Bezier
// contours under every relgeo kernel and hull algorithm.
//
// Input: byte 0 the kernel, byte 1 the hull algorithm (and bit 7: no
// prune), byte 2 the degree (1..4), byte 3 the relative uncertainty (a table
// of typical values, or raw bits), then control points as records: a new
// point (two fuzz_support.h coordinates), a duplicate, a point on the line
// through two earlier ones, an earlier point moved by a few ulps.
//
// Contract (doc/reliability.md, harness extrusion):
//  * a report or a relgeo::Error: Non_finite_input for NaN or infinite
//    points (or, under the float kernel, points beyond float's range),
//    Invalid_input for a chain that is not a closed contour of the degree or
//    an uncertainty that is negative or not finite;
//  * the verdict is sound: what kernel K certifies, the exact kernel (exact
//    hulls) certifies too, condition by condition, and what K refuses (the
//    condition fails for the stored data) the exact kernel does not certify.
//    Margins are measured on the hull K computed, which lies inside the
//    exact hull, so K's margin minus its backward error can only be smaller.
#include <algorithm>
#include <cmath>
#include <limits>

#include "fuzz_support.h"
#include "relgeo/curves.h"
#include "relgeo/kernel.h"

namespace {

using namespace relgeo;
using namespace relgeo::fuzz;

std::vector<Point_2<double>> decode_chain(Input& in) {
  std::vector<Point_2<double>> p;
  while (!in.empty() && p.size() < 96) {
    const std::uint8_t op = in.byte();
    if (p.empty() || op % 4 == 0) {
      const double x = in.coordinate();
      p.push_back({x, in.coordinate()});
    } else if (op % 4 == 1) {
      p.push_back(p[in.below(p.size())]);
    } else if (op % 4 == 2) {
      const auto a = p[in.below(p.size())], b = p[in.below(p.size())];
      const double t = static_cast<double>(static_cast<std::int8_t>(in.byte())) / 16.0;
      p.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    } else {
      auto a = p[in.below(p.size())];
      const int d = static_cast<std::int8_t>(in.byte()) % 4;
      for (int i = 0; i < std::abs(d); ++i) a.y = std::nextafter(a.y, d > 0 ? INFINITY : -INFINITY);
      p.push_back(a);
    }
  }
  return p;
}

template <class K, class Algorithm>
void check(const Bezier_contour& contour, const Extrusion_options& o, const Extrusion_report& exact) {
  const std::string who = K::name();
  Extrusion_report r;
  try {
    r = check_extrusion<K>(contour, o, K{}, Algorithm{});
  } catch (const Non_finite_input& e) {
    // A float kernel rounds the double points, beyond 3.4e38 to infinity.
    require(std::is_same_v<typename K::FT, float>, who + ": Non_finite_input for finite points: " + e.what());
    return;
  } catch (const std::exception& e) {
    require(false, who + ": check_extrusion refused what the exact kernel checked: " + e.what());
  }
  require(r.curves == exact.curves, who + ": same number of curves");
  for (std::size_t c = 0; c < 3; ++c) {
    const auto v = r.conditions[c].verdict, e = exact.conditions[c].verdict;
    require(v != Extrusion_verdict::certified || e == Extrusion_verdict::certified,
            who + ": certified a condition the exact kernel does not (condition " + std::to_string(c + 1) + ")");
    require(v != Extrusion_verdict::refused || e != Extrusion_verdict::certified,
            who + ": refused a condition the exact kernel certifies (condition " + std::to_string(c + 1) + ")");
  }
  require(r.verdict != Extrusion_verdict::certified || exact.verdict == Extrusion_verdict::certified,
          who + ": certified a contour the exact kernel does not");
}

template <class Algorithm>
void check_kernel(int kernel, const Bezier_contour& c, const Extrusion_options& o, const Extrusion_report& exact) {
  switch (kernel) {
    case 0: check<Naive_kernel<float>, Algorithm>(c, o, exact); break;
    case 1: check<Naive_kernel<double>, Algorithm>(c, o, exact); break;
    case 2: check<Naive_kernel<long double>, Algorithm>(c, o, exact); break;
    case 3: check<Failsafe_kernel<double>, Algorithm>(c, o, exact); break;
    case 4: check<Interval_kernel, Algorithm>(c, o, exact); break;
    case 5: check<Filtered_exact_kernel, Algorithm>(c, o, exact); break;
    default: check<Mpfr_kernel<53>, Algorithm>(c, o, exact);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  const int kernel = in.byte() % 7;
  const std::uint8_t mode = in.byte();
  const std::size_t degree = 1 + in.byte() % 4;
  static constexpr double deltas[] = {1e-3, 0, 1e-9, 1e-15, 0.25};
  const std::uint8_t d = in.byte();
  const Extrusion_options options{.relative_uncertainty = d < 250 ? deltas[d % 5] : in.raw_double(),
                                  .prune = (mode & 0x80) == 0};
  const auto chain = decode_chain(in);

  std::optional<Bezier_contour> contour;
  bool finite = true;
  for (const auto& p : chain) finite = finite && std::isfinite(p.x) && std::isfinite(p.y);
  try {
    contour = Bezier_contour::from_chain(chain, degree);
    require(finite, "from_chain accepted a non-finite point");
  } catch (const Non_finite_input&) {
    require(!finite, "from_chain: Non_finite_input for finite points");
    return 0;
  } catch (const Invalid_input&) {
    require(chain.empty() || chain.size() % degree != 0, "from_chain refused a closed chain of the degree");
    return 0;
  } catch (const std::exception& e) {
    require(false, std::string("from_chain: untyped ") + e.what());
  }

  // The oracle: exact predicates, exact hulls (monotone chain, the ground truth).
  Extrusion_report exact;
  const bool valid_options = options.relative_uncertainty >= 0 && std::isfinite(options.relative_uncertainty);
  try {
    exact = check_extrusion<Exact_kernel>(*contour, options, Exact_kernel{}, Monotone_chain_hull{});
    require(valid_options, "check_extrusion accepted a negative or non-finite uncertainty");
  } catch (const Non_finite_input& e) {
    // Finite control points whose hodograph (degree times differences,
    // in double) overflows: refused as non-finite. Allowed only near the
    // largest double.
    double largest = 0;
    for (const auto& p : chain) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
    require(largest > 0x1p-8 * std::numeric_limits<double>::max(),
            std::string("check_extrusion: Non_finite_input for finite points far from overflow: ") + e.what());
    return 0;
  } catch (const Invalid_input& e) {
    require(!valid_options, std::string("check_extrusion refused valid options: ") + e.what());
    return 0;
  } catch (const std::exception& e) {
    require(false, std::string("check_extrusion (exact): ") + e.what());
  }
  switch (mode % 3) {
    case 0: check_kernel<Graham_fortune_hull>(kernel, *contour, options, exact); break;
    case 1: check_kernel<Monotone_chain_hull>(kernel, *contour, options, exact); break;
    default: check_kernel<Graham_incremental_hull>(kernel, *contour, options, exact);
  }
  return 0;
}
