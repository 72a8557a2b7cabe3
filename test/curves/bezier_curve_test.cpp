// Planar Bezier curves: de Casteljau evaluation against the Bernstein sum,
// derivatives against the hodograph, subdivision — exactly, in rationals —
// and bad input.
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <random>

#include "relgeo/curves/bezier_curve.h"

namespace relgeo::test {
namespace {

using Q = mpq_class;
using Pq = Point_2<Q>;

/// n/d in canonical form (gmpxx's two-argument constructor does not
/// canonicalize, and arithmetic on non-canonical rationals is undefined).
Q frac(long n, long d) {
  Q q(n, d);
  q.canonicalize();
  return q;
}

Q binomial(std::size_t n, std::size_t k) {
  mpz_class b;
  mpz_bin_uiui(b.get_mpz_t(), n, k);
  return Q(b);
}
Q power(const Q& x, std::size_t k) {
  Q r = 1;
  for (std::size_t i = 0; i < k; ++i) r *= x;
  return r;
}
Pq bernstein(const std::vector<Pq>& p, const Q& t) {
  const std::size_t v = p.size() - 1;
  Pq r{0, 0};
  for (std::size_t i = 0; i <= v; ++i) {
    const Q w = binomial(v, i) * power(t, i) * power(1 - t, v - i);
    r.x += w * p[i].x;
    r.y += w * p[i].y;
  }
  return r;
}

std::vector<Pq> random_control_points(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> d(-50, 50);
  std::vector<Pq> p;
  for (std::size_t i = 0; i < n; ++i) p.push_back({frac(d(rng), 7), frac(d(rng), 3)});
  return p;
}

TEST(BezierCurve, DeCasteljauEqualsBernsteinExactly) {
  for (std::size_t v = 1; v <= 6; ++v) {
    const auto p = random_control_points(v + 1, static_cast<unsigned>(v));
    const Bezier_curve_2<Q> c(p);
    EXPECT_EQ(c.degree(), v);
    for (int k = 0; k <= 8; ++k) {
      const Q t = frac(k, 8);
      const Pq a = c.evaluate(t), b = bernstein(p, t);
      EXPECT_EQ(a.x, b.x);
      EXPECT_EQ(a.y, b.y);
    }
    EXPECT_EQ(c(Q(0)), p.front());  // interpolates its end points
    EXPECT_EQ(c(Q(1)), p.back());
  }
}

TEST(BezierCurve, DerivativesAreTheHodograph) {
  const auto p = random_control_points(5, 11);  // quartic
  const Bezier_curve_2<Q> c(p);
  const Bezier_curve_2<Q> h = c.derivative_curve();
  EXPECT_EQ(h.degree(), 3u);
  const Bezier_curve_2<Q> hh = h.derivative_curve();
  for (int k = 0; k <= 5; ++k) {
    const Q t = frac(k, 5);
    EXPECT_EQ(c.derivative(t, 1), h(t));
    EXPECT_EQ(c.derivative(t, 2), hh(t));
    EXPECT_EQ(c.derivative(t, 0), c(t));
    // R'(t) is the limit of difference quotients: for a polynomial of degree
    // 4, the symmetric quotient has error exactly (h^2/6) R'''(t) + O(h^4).
  }
  EXPECT_EQ(c.derivative(frac(1, 3), 5), (Pq{0, 0}));  // beyond the degree
  // the end tangents: R'(0) = v (R1 - R0)
  EXPECT_EQ(c.derivative(Q(0)).x, 4 * (p[1].x - p[0].x));
  const auto q = c.differences();
  ASSERT_EQ(q.size(), 4u);
  EXPECT_EQ(q[3].y, p[4].y - p[3].y);
  // double curves: derivative close to a difference quotient
  const Bezier_curve_2<double> d({{0, 0}, {1, 2}, {3, 3}, {4, 0}});
  const double t = 0.3, e = 1e-6;
  const auto dq = d.derivative(t);
  EXPECT_NEAR(dq.x, (d(t + e).x - d(t - e).x) / (2 * e), 1e-6);
  EXPECT_NEAR(dq.y, (d(t + e).y - d(t - e).y) / (2 * e), 1e-6);
  EXPECT_THROW((void)Bezier_curve_2<double>({{0, 0}, {1, 1}}).derivative_curve(), Invalid_input);
}

TEST(BezierCurve, SubdivisionReproducesTheCurveExactly) {
  const auto p = random_control_points(4, 3);
  const Bezier_curve_2<Q> c(p);
  for (const Q& t : {frac(1, 3), frac(1, 2), frac(5, 7)}) {
    const auto [left, right] = c.subdivide(t);
    EXPECT_EQ(left.control_points().back(), c(t));
    EXPECT_EQ(right.control_points().front(), c(t));
    for (int k = 0; k <= 6; ++k) {
      const Q s = frac(k, 6);
      EXPECT_EQ(left(s), c(t * s));
      EXPECT_EQ(right(s), c(t + (1 - t) * s));
    }
  }
  const Bezier_curve_2<Q> r = c.reversed();
  EXPECT_EQ(r(frac(1, 4)), c(frac(3, 4)));
}

TEST(BezierCurve, BadInput) {
  EXPECT_THROW((Bezier_curve_2<double>({{0, 0}})), Invalid_input);  // degree 0
  EXPECT_THROW((Bezier_curve_2<double>(std::vector<Point_2<double>>{})), Invalid_input);
  try {
    Bezier_curve_2<double>({{0, 0}});
  } catch (const Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("degree 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW((Bezier_curve_2<double>({{0, 0}, {std::nan(""), 1}})), Non_finite_input);
  EXPECT_THROW((Bezier_curve_2<double>({{0, 0}, {1, INFINITY}})), Non_finite_input);
}

}  // namespace
}  // namespace relgeo::test
