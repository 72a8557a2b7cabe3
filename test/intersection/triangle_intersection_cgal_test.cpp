// intersect_triangles and do_intersect_triangles against CGAL's Epeck
// (do_intersect and intersection of Triangle_3) on 10^6 pairs in random,
// near-degenerate, touching and coplanar families: certified kernels agree
// whenever they decide (exact ones always decide), the intersection's points
// are CGAL's exactly, and the naive kernel is wrong on the hard families.
#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <vector>

#include "relgeo/analysis/triangle_pair_workloads.h"
#include "relgeo/intersection/triangle_intersection.h"
#include "relgeo/kernel.h"
#include "support/soundness_data.h"

namespace relgeo {
namespace {

using Epeck = CGAL::Epeck;
using Kind = Triangle_intersection_kind;

Epeck::Triangle_3 cgal_triangle(const analysis::Triangle_coordinates& t) {
  const auto p = [&](int i) { return Epeck::Point_3(t[i][0], t[i][1], t[i][2]); };
  return {p(0), p(1), p(2)};
}

template <class K>
std::array<typename K::Point_3, 3> triangle(const K& k, const analysis::Triangle_coordinates& t) {
  const auto p = k.construct_point_3_object();
  return {p(t[0][0], t[0][1], t[0][2]), p(t[1][0], t[1][1], t[1][2]), p(t[2][0], t[2][1], t[2][2])};
}

struct Family {
  analysis::Triangle_pair_workload w;
  std::vector<bool> intersect;  // CGAL Epeck
};

const std::vector<Family>& families() {
  static const std::vector<Family> data = [] {
    std::vector<Family> out;
    const auto n = static_cast<std::size_t>(250000 * test::test_scale()) + 100;
    for (auto& w : analysis::triangle_pair_workloads(n, 2026)) {
      Family f{std::move(w), {}};
      for (const auto& p : f.w.pairs) f.intersect.push_back(CGAL::do_intersect(cgal_triangle(p.a), cgal_triangle(p.b)));
      out.push_back(std::move(f));
    }
    return out;
  }();
  return data;
}

struct Tally {
  std::size_t pairs = 0, undecided = 0, wrong = 0, intersecting = 0;
};

template <class K>
Tally check(const Family& f, bool fast) {
  const K k;
  Tally t;
  for (std::size_t i = 0; i < f.w.pairs.size(); ++i) {
    const auto a = triangle(k, f.w.pairs[i].a), b = triangle(k, f.w.pairs[i].b);
    ++t.pairs;
    t.intersecting += f.intersect[i];
    std::optional<bool> answer;
    if (fast) {
      answer = do_intersect_triangles(a, b, k);
    } else {
      const auto r = intersect_triangles(a, b, k);
      if (!r.perturbations.empty()) {  // a fail-safe answer about moved vertices: not this input's
        ++t.undecided;
        continue;
      }
      if (r.kind != Kind::undecided) answer = r.kind != Kind::disjoint;
    }
    if (!answer) ++t.undecided;
    else if (*answer != f.intersect[i]) ++t.wrong;
  }
  std::printf("[ %-18s ] %-9s %-10s %8zu pairs %8zu intersect %8zu undecided %8zu wrong\n", K::name().c_str(),
              fast ? "do_inter." : "intersect", f.w.name.c_str(), t.pairs, t.intersecting, t.undecided, t.wrong);
  return t;
}

template <class K>
void expect_sound(bool never_undecided) {
  for (const auto& f : families())
    for (bool fast : {true, false}) {
      const Tally t = check<K>(f, fast);
      EXPECT_EQ(t.wrong, 0u) << K::name() << " " << f.w.name;
      if (never_undecided) {
        EXPECT_EQ(t.undecided, 0u) << K::name() << " " << f.w.name;
      }
    }
}

TEST(TriangleIntersectionCgal, FilteredExactAgreesWithEpeck) { expect_sound<Filtered_exact_kernel>(true); }
TEST(TriangleIntersectionCgal, IntervalAgreesWhenItDecides) { expect_sound<Interval_kernel>(false); }
TEST(TriangleIntersectionCgal, FailsafeAgreesWhenItDecides) { expect_sound<Failsafe_kernel<double>>(false); }

// The families are hard: rounded predicates get some pairs wrong.
TEST(TriangleIntersectionCgal, TheNearFamilyIsHardForTheNaiveKernel) {
  std::size_t wrong = 0;
  for (const auto& f : families())
    if (f.w.name == "near") wrong += check<Naive_kernel<float>>(f, true).wrong;
  EXPECT_GT(wrong, 0u);
}

// The points themselves, exactly, against CGAL's intersection (every 25th pair).
mpq_class exact_value(const Epeck::FT& x) {
  std::ostringstream s;
  s << CGAL::exact(x);
  return mpq_class(s.str());
}
std::array<mpq_class, 3> exact_point(const Epeck::Point_3& p) { return {exact_value(p.x()), exact_value(p.y()), exact_value(p.z())}; }

TEST(TriangleIntersectionCgal, ThePointsAreCgalsExactly) {
  const Exact_kernel k;
  const auto approximate = k.approximate_point_3_object();
  (void)approximate;
  std::size_t compared = 0;
  for (const auto& f : families())
    for (std::size_t i = 0; i < f.w.pairs.size(); i += 25) {
      const auto& pair = f.w.pairs[i];
      const auto r = intersect_triangles(triangle(k, pair.a), triangle(k, pair.b), k);
      const auto c = CGAL::intersection(cgal_triangle(pair.a), cgal_triangle(pair.b));
      ASSERT_EQ(r.kind == Kind::disjoint, !c) << f.w.name << " " << i;
      if (!c) continue;
      std::vector<std::array<mpq_class, 3>> expected;
      if (const auto* p = boost::get<Epeck::Point_3>(&*c)) expected = {exact_point(*p)};
      else if (const auto* s = boost::get<Epeck::Segment_3>(&*c)) expected = {exact_point(s->source()), exact_point(s->target())};
      else if (const auto* t = boost::get<Epeck::Triangle_3>(&*c))
        expected = {exact_point(t->vertex(0)), exact_point(t->vertex(1)), exact_point(t->vertex(2))};
      else for (const auto& q : boost::get<std::vector<Epeck::Point_3>>(*c)) expected.push_back(exact_point(q));
      // CGAL may list a polygon's collinear points; relgeo keeps every distinct point too.
      std::vector<std::array<mpq_class, 3>> ours;
      for (const auto& p : r.points) ours.push_back({p.point.x, p.point.y, p.point.z});
      const auto sorted_unique = [](std::vector<std::array<mpq_class, 3>> v) {
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
        return v;
      };
      const auto e = sorted_unique(expected), o = sorted_unique(ours);
      // Every CGAL point is ours; ours beyond CGAL's lie on its polygon's edges (collinear vertices).
      for (const auto& x : e) EXPECT_TRUE(std::binary_search(o.begin(), o.end(), x)) << f.w.name << " pair " << i;
      if (e.size() <= 2) {
        EXPECT_EQ(o, e) << f.w.name << " pair " << i;
      }
      ++compared;
    }
  std::printf("[ exact vs CGAL ] %zu intersections compared point by point\n", compared);
}

}  // namespace
}  // namespace relgeo
