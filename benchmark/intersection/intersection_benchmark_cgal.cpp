// The CGAL subjects of relgeo_intersection_benchmark: Epick's and Epeck's
// do_intersect(Triangle_3, Triangle_3), and Epeck's line-plane intersection
// followed by an orientation (construct, then test).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "intersection_benchmark.h"

namespace relgeo_bench {
namespace {

void epeck_lpi_orientation(benchmark::State& state, const std::string& family) {
  using K = CGAL::Epeck;
  std::vector<std::array<K::Point_3, 8>> pts;
  for (const auto& q : lpi_queries(family)) {
    std::array<K::Point_3, 8> a;
    for (int i = 0; i < 8; ++i) a[i] = K::Point_3(q.v[i][0], q.v[i][1], q.v[i][2]);
    pts.push_back(a);
  }
  for (auto _ : state)
    for (const auto& a : pts) {
      const auto x = CGAL::intersection(K::Line_3(a[0], a[1]), K::Plane_3(a[2], a[3], a[4]));
      const K::Point_3* p = boost::get<K::Point_3>(&*x);
      benchmark::DoNotOptimize(CGAL::orientation(a[5], a[6], a[7], *p));
    }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * pts.size()));
}

template <class K>
void cgal_triangle_pair(benchmark::State& state, const std::string& family) {
  std::vector<std::array<typename K::Triangle_3, 2>> pairs;
  for (const auto& p : triangle_pairs(family)) {
    const auto t = [](const relgeo::analysis::Triangle_coordinates& c) {
      return typename K::Triangle_3(typename K::Point_3(c[0][0], c[0][1], c[0][2]),
                                    typename K::Point_3(c[1][0], c[1][1], c[1][2]),
                                    typename K::Point_3(c[2][0], c[2][1], c[2][2]));
    };
    pairs.push_back({t(p.a), t(p.b)});
  }
  for (auto _ : state)
    for (const auto& t : pairs) benchmark::DoNotOptimize(CGAL::do_intersect(t[0], t[1]));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * pairs.size()));
}

}  // namespace

void register_cgal_subjects() {
  for (const std::string family : {"random", "on-plane"})
    register_subject("lpi_orientation/" + family + "/CGAL::Epeck", epeck_lpi_orientation, family);
  for (const std::string family : {"random", "near", "touching", "coplanar"}) {
    register_subject("triangle_pair/" + family + "/CGAL::Epick", cgal_triangle_pair<CGAL::Epick>, family);
    register_subject("triangle_pair/" + family + "/CGAL::Epeck", cgal_triangle_pair<CGAL::Epeck>, family);
  }
}

}  // namespace relgeo_bench
