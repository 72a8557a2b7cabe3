// benchmark/hull/hull_benchmark_cgal.cpp — CGAL's planar hulls on Epick and
// Epeck, used directly (CGAL::ch_graham_andrew, CGAL::convex_hull_2), as peers
// of relgeo's algorithms. Own translation unit: Epeck is slow to compile.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/ch_graham_andrew.h>
#include <CGAL/convex_hull_2.h>

#include <iterator>

#include "hull_benchmark.h"
#include "relgeo/hull/cgal_convex_hull.h"

namespace relgeo_hull_bench {

namespace {

template <class CK>
Subject cgal_subject(relgeo::Cgal_hull_algorithm algorithm, std::string kernel_name,
                     std::size_t max_n) {
  using P = typename CK::Point_2;
  using Points = std::vector<P>;
  auto slot = std::make_shared<Prepared_slot<Points>>();
  auto build = [](const std::vector<relgeo::Point_2<double>>& in) {
    Points v;
    v.reserve(in.size());
    for (const auto& p : in) v.emplace_back(p.x, p.y);
    return v;
  };
  auto compute = [algorithm](const Points& pts) {
    Points out;
    if (algorithm == relgeo::Cgal_hull_algorithm::graham_andrew)
      CGAL::ch_graham_andrew(pts.begin(), pts.end(), std::back_inserter(out), CK());
    else
      CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(out), CK());
    return out;
  };
  Subject s;
  s.algorithm = algorithm == relgeo::Cgal_hull_algorithm::graham_andrew ? "CGAL::ch_graham_andrew"
                                                                          : "CGAL::convex_hull_2";
  s.kernel = std::move(kernel_name);
  s.runs = [max_n](const std::string&, std::size_t n) { return n <= max_n; };
  s.bench = [slot, build, compute](benchmark::State& state, const Input& in) {
    const Points& pts = slot->get(in, build);
    time_hull(state, pts, compute, [](const Points& r) { return r.size(); });
  };
  s.hull_indices = [slot, build, algorithm](const Input& in) {
    const Points& pts = slot->get(in, build);
    return relgeo::cgal_convex_hull<CK>(std::span<const P>(pts), algorithm).indices;
  };
  s.memory_probe = [build, compute](std::size_t n, std::size_t* input_bytes) {
    auto pts = std::make_shared<Points>();
    {
      const Input in = make_input("uniform", n, 1);
      *pts = build(in.points);
    }  // the double input is freed: the subject's points are the input
    *input_bytes = pts->size() * sizeof(P);
    return std::function<std::size_t()>([pts, compute] { return compute(*pts).size(); });
  };
  s.release = [slot] { slot->release(); };
  return s;
}

}  // namespace

std::vector<Subject> cgal_subjects() {
  using relgeo::Cgal_hull_algorithm;
  const std::size_t all = static_cast<std::size_t>(-1);
  return {
      cgal_subject<CGAL::Epick>(Cgal_hull_algorithm::graham_andrew, "Epick", all),
      cgal_subject<CGAL::Epick>(Cgal_hull_algorithm::convex_hull_2, "Epick", all),
      cgal_subject<CGAL::Epeck>(Cgal_hull_algorithm::graham_andrew, "Epeck", kEpeckMaxN),
      cgal_subject<CGAL::Epeck>(Cgal_hull_algorithm::convex_hull_2, "Epeck", kEpeckMaxN),
  };
}

}  // namespace relgeo_hull_bench
