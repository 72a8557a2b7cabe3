// intersect_triangles and do_intersect_triangles against CGAL's Epeck
// (do_intersect and intersection of Triangle_3) on 10^6 pairs in random,
// near-degenerate, touching and coplanar families: certified kernels agree
// whenever they decide (exact ones always decide), the intersection's points
// are CGAL's exactly, and the naive kernel is wrong on the hard families.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <sstream>
#include <vector>

#include "relgeo/analysis/triangle_pair_workloads.h"
#include "relgeo/intersection/triangle_intersection.h"
#include "relgeo/kernel.h"
#include "relgeo/mesh/internal/face_pair_predicates.h"
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

// Integer corners in {0..3}^3: corners on the other triangle's plane, on
// its edges' lines and shared coordinates abound, where the cut comparison
// (intersection/internal/cut_overlap.h) must still be exact. The three
// tests built on it agree with CGAL on every pair: do_intersect_triangles,
// intersect_triangles, and the self-intersection search's pair test (two
// faces sharing no vertex meet iff the closed triangles do).
TEST(TriangleIntersectionCgal, GridTrianglesAgreeWithEpeck) {
  std::mt19937 rng(30);
  std::uniform_int_distribution<int> coordinate(0, 3);
  const Filtered_exact_kernel k;
  const auto n = static_cast<std::size_t>(200000 * test::test_scale()) + 1000;
  std::size_t tested = 0, meeting = 0, corner_on_plane = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::array<Point_3<double>, 6> p;
    std::array<Epeck::Point_3, 6> e;
    for (int j = 0; j < 6; ++j) {
      const int x = coordinate(rng), y = coordinate(rng), z = coordinate(rng);
      p[j] = {double(x), double(y), double(z)};
      e[j] = Epeck::Point_3(x, y, z);
    }
    const Epeck::Triangle_3 ta(e[0], e[1], e[2]), tb(e[3], e[4], e[5]);
    if (ta.is_degenerate() || tb.is_degenerate()) continue;
    ++tested;
    const bool truth = CGAL::do_intersect(ta, tb);
    meeting += truth;
    const std::array<Point_3<double>, 3> a{p[0], p[1], p[2]}, b{p[3], p[4], p[5]};
    const std::optional<bool> fast = do_intersect_triangles(a, b, k);
    ASSERT_TRUE(fast.has_value()) << i;
    ASSERT_EQ(*fast, truth) << "do_intersect_triangles, pair " << i;
    const Kind kind = intersect_triangles(a, b, k).kind;
    ASSERT_EQ(kind != Kind::disjoint, truth) << "intersect_triangles, pair " << i;
    const auto o = k.orientation_3_object();
    int on_plane = 0;
    for (int j = 0; j < 3; ++j) on_plane += certainly(o(a[0], a[1], a[2], b[j]), Certified_sign::zero);
    corner_on_plane += on_plane == 1 || on_plane == 2;
    const internal::Maybe meet = internal::triangles_meet(k, {&a[0], &a[1], &a[2]}, {&b[0], &b[1], &b[2]});
    ASSERT_TRUE(meet.has_value()) << i;
    ASSERT_EQ(*meet, truth) << "triangles_meet, pair " << i;
  }
  // Both answers occur in number, and so do the degenerate cuts (a corner of
  // one triangle on the other's plane, the planes not equal).
  EXPECT_GT(meeting, tested / 10);
  EXPECT_GT(tested - meeting, tested / 10);
  EXPECT_GT(corner_on_plane, tested / 10);
}

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
