// Exact signed distances and separations of convex hulls (the margins of the
// extruded-object conditions): against a brute-force exact oracle on random
// and near-degenerate sets, degenerate hulls, and the rounding directions.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "relgeo/curves/convex_separation.h"

namespace relgeo::test {
namespace {

using P = Point_2<double>;

// Oracle: min over ALL vertex-to-edge pairs, in rationals, no filter.
mpq_class brute_distance(const std::vector<P>& a, const std::vector<P>& b) {
  const auto ha = exact_hull(a), hb = exact_hull(b);
  std::optional<mpq_class> best;
  for (int pass = 0; pass < 2; ++pass) {
    const auto& p = pass ? ha : hb;
    const auto& q = pass ? hb : ha;
    for (const auto& v : p)
      for (std::size_t i = 0; i < q.size(); ++i) {
        mpq_class d = internal::squared_distance_to_segment(v, q[i], q[(i + 1) % q.size()]);
        if (!best || d < *best) best = d;
      }
  }
  return *best;
}
// Oracle for disjointness of hulls with >= 3 vertices: a separating edge normal.
bool brute_disjoint(const std::vector<P>& a, const std::vector<P>& b) {
  const auto ha = exact_hull(a), hb = exact_hull(b);
  for (int pass = 0; pass < 2; ++pass) {
    const auto& h = pass ? hb : ha;
    for (std::size_t i = 0; i < h.size(); ++i) {
      const mpq_class nx = -(mpq_class(h[(i + 1) % h.size()].y) - h[i].y), ny = mpq_class(h[(i + 1) % h.size()].x) - h[i].x;
      auto range = [&](const std::vector<P>& s) {
        mpq_class lo = nx * s[0].x + ny * s[0].y, hi = lo;
        for (const auto& v : s) {
          const mpq_class t = nx * v.x + ny * v.y;
          if (t < lo) lo = t;
          if (t > hi) hi = t;
        }
        return std::pair{lo, hi};
      };
      const auto [alo, ahi] = range(ha);
      const auto [blo, bhi] = range(hb);
      if (ahi < blo || bhi < alo) return true;
    }
  }
  return false;
}

std::vector<P> random_polygon(std::mt19937_64& rng, double cx, double cy, double r, int n) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<P> p;
  for (int i = 0; i < n; ++i) p.push_back({cx + r * u(rng), cy + r * u(rng)});
  return p;
}

TEST(ConvexSeparation, AgreesWithBruteForceOnRandomAndNearTouchingSets) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  int disjoint = 0, overlapping = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double scale = trial % 3 == 0 ? 1e10 : trial % 3 == 1 ? 1.0 : 1e-8;
    const double offset = trial % 5 == 0 ? 1e6 * scale : 0;  // far from the origin: cancellation
    const auto a = random_polygon(rng, offset, offset, scale, 3 + trial % 6);
    // b: shifted copy at a random distance, sometimes just touching or overlapping
    const double gap = (trial % 4 == 0) ? 0 : std::ldexp(u(rng), -(trial % 50)) * scale;
    const auto b = random_polygon(rng, offset + 1.7 * scale + gap, offset + u(rng) * scale, scale, 3 + trial % 5);
    const Signed_distance s = hull_separation(a, b);
    const bool dis = brute_disjoint(a, b);
    if (dis) {
      ++disjoint;
      ASSERT_EQ(s.side, 1) << trial;
      EXPECT_EQ(s.squared, brute_distance(a, b)) << trial;
      EXPECT_LE(mpq_class(s.lower()) * s.lower(), s.squared);
      EXPECT_GE(mpq_class(s.upper()) * s.upper(), s.squared);
      EXPECT_GT(s.lower(), 0);
    } else {
      ++overlapping;
      EXPECT_LE(s.side, 0) << trial;
      EXPECT_LE(s.upper(), 0);
    }
    // distance from the origin (and from a point near the hull) to conv(a)
    for (const P p : {P{0, 0}, P{a[0].x + 1e-9 * scale, a[0].y}}) {
      const Signed_distance d = signed_distance_to_hull(a, p);
      const auto h = exact_hull(a);
      const Polygon_side side = locate(h, p);
      if (side == Polygon_side::outside) {
        ASSERT_EQ(d.side, 1);
        EXPECT_EQ(d.squared, squared_distance(h, p)) << trial;
      } else {
        EXPECT_EQ(d.side, side == Polygon_side::inside ? -1 : 0);
      }
    }
  }
  EXPECT_GT(disjoint, 1000);
  EXPECT_GT(overlapping, 100);
}

TEST(ConvexSeparation, DegenerateHulls) {
  const std::vector<P> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  // a point inside: depth = distance to the nearest side
  EXPECT_EQ(signed_distance_to_hull(square, {0.25, 0.5}).squared, mpq_class(1, 16));
  EXPECT_EQ(signed_distance_to_hull(square, {0.25, 0.5}).side, -1);
  EXPECT_EQ(signed_distance_to_hull(square, {0.25, 0.5}).lower(), -0.25);
  EXPECT_EQ(signed_distance_to_hull(square, {1, 0.5}).side, 0);  // on an edge
  EXPECT_EQ(signed_distance_to_hull(square, {3, 5}).squared, mpq_class(4 + 16));
  // segments
  const std::vector<P> seg = {{-1, 0}, {1, 0}};
  EXPECT_EQ(signed_distance_to_hull(seg, {0, 0}).side, 0);  // on it: no inside
  EXPECT_EQ(signed_distance_to_hull(seg, {0, 2}).squared, 4);
  // two collinear disjoint segments: the separating direction is along them
  const Signed_distance cs = hull_separation(std::vector<P>{{0, 0}, {1, 0}}, std::vector<P>{{3, 0}, {5, 0}});
  EXPECT_EQ(cs.side, 1);
  EXPECT_EQ(cs.squared, 4);
  // collinear overlapping segments touch (no interior): 0
  EXPECT_EQ(hull_separation(std::vector<P>{{0, 0}, {2, 0}}, std::vector<P>{{1, 0}, {5, 0}}).side, 0);
  // crossing segments: no interior, but separating them takes a translation
  // by sqrt(2) (along the normal of either)
  const Signed_distance x = hull_separation(std::vector<P>{{0, 0}, {2, 2}}, std::vector<P>{{0, 2}, {2, 0}});
  EXPECT_EQ(x.side, -1);
  EXPECT_EQ(x.squared, 2);
  // a segment ending on another one: touching
  EXPECT_EQ(hull_separation(std::vector<P>{{0, 0}, {2, 2}}, std::vector<P>{{1, 1}, {2, 0}}).side, 0);
  // squares sharing a corner, sharing an edge, overlapping by 1/4
  const std::vector<P> corner = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  EXPECT_EQ(hull_separation(square, corner).side, 0);
  const std::vector<P> edge = {{1, 0}, {2, 0}, {2, 1}, {1, 1}};
  EXPECT_EQ(hull_separation(square, edge).side, 0);
  const std::vector<P> overlap = {{0.75, 0.5}, {2, 0.5}, {2, 2}, {0.75, 2}};
  const Signed_distance o = hull_separation(square, overlap);
  EXPECT_EQ(o.side, -1);
  EXPECT_EQ(o.squared, mpq_class(1, 16));  // push right by 1/4
  EXPECT_EQ(o.lower(), -0.25);
  // identical points
  EXPECT_EQ(hull_separation(std::vector<P>{{1, 1}}, std::vector<P>{{1, 1}}).side, 0);
  EXPECT_EQ(hull_separation(std::vector<P>{{1, 1}}, std::vector<P>{{4, 5}}).squared, 25);
  EXPECT_THROW((void)hull_separation(std::vector<P>{}, square), Invalid_input);
  EXPECT_THROW((void)signed_distance_to_hull(std::vector<P>{}, {0, 0}), Invalid_input);
}

TEST(ConvexSeparation, DirectedSquareRoots) {
  // A signed distance's value is rounded outward on either side.
  for (const mpq_class& q : {mpq_class(2), mpq_class(1, 3), mpq_class(0), mpq_class(mpq_class(1, 10) * mpq_class(1, 10))}) {
    const Signed_distance apart{1, q}, overlapping{-1, q};
    const double lo = apart.lower(), hi = apart.upper();
    EXPECT_LE(mpq_class(lo) * lo, q);
    EXPECT_GE(mpq_class(hi) * hi, q);
    EXPECT_LE(hi, std::nextafter(std::nextafter(lo, INFINITY), INFINITY));  // within 2 ulps
    EXPECT_EQ(overlapping.lower(), -hi);
    EXPECT_EQ(overlapping.upper(), -lo);
  }
  EXPECT_EQ((Signed_distance{1, mpq_class(4)}.lower()), 2.0);
  EXPECT_EQ((Signed_distance{1, mpq_class(4)}.upper()), 2.0);
}

}  // namespace
}  // namespace relgeo::test
