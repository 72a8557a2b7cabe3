// NURBS curves and surfaces: evaluation and derivatives exact under
// mpq_class (against closed forms), enclosures under Interval, double close
// to exact, and bad data refused with typed errors. (OpenCASCADE is the
// second oracle: occt_evaluation_test.cpp.)
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <random>

#include "joining/surface_fixtures.h"
#include "relgeo/core/interval.h"
#include "relgeo/core/mpfr_number.h"
#include "relgeo/surfaces/nurbs_curve.h"
#include "relgeo/surfaces/nurbs_surface.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;
using Q = mpq_class;

// a/b in lowest terms (gmpxx's two-argument constructor does not
// canonicalise, and comparisons of non-canonical rationals are wrong).
Q frac(long a, long b) {
  Q q(a, b);
  q.canonicalize();
  return q;
}

// Bernstein polynomial B_{i,n}(t) in exact arithmetic.
Q bernstein(int i, int n, const Q& t) {
  Q r = internal::binomial(n, i);
  for (int k = 0; k < i; ++k) r *= t;
  for (int k = 0; k < n - i; ++k) r *= Q(1) - t;
  return r;
}
Q bernstein_or_zero(int i, int n, const Q& t) { return i < 0 || i > n ? Q(0) : bernstein(i, n, t); }

// A Bezier patch (one span) as a B-spline.
Nurbs_surface<double> bezier_patch(std::mt19937_64& rng, int p, int q) {
  std::vector<double> U(p + 1, 0.0), V(q + 1, 0.0);
  U.insert(U.end(), p + 1, 1.0), V.insert(V.end(), q + 1, 1.0);
  std::uniform_int_distribution<int> c(-64, 64);
  std::vector<Point_3<double>> P;
  for (int i = 0; i <= p; ++i)
    for (int j = 0; j <= q; ++j) P.push_back({i + c(rng) / 128.0, j + c(rng) / 128.0, c(rng) / 32.0});
  return Nurbs_surface<double>(p, q, U, V, p + 1, q + 1, P);
}

TEST(NurbsSurface, BezierPatchAndDerivativesAreExactUnderRationals) {
  std::mt19937_64 rng(1);
  for (int trial = 0; trial < 6; ++trial) {
    const int p = 1 + trial % 4, q = 1 + (trial * 3) % 5;
    const Nurbs_surface<double> sd = bezier_patch(rng, p, q);
    const Nurbs_surface<Q> s = sd.convert<Q>();
    for (const auto& [u, v] : {std::pair{frac(1, 3), frac(5, 7)}, std::pair{Q(0), Q(1)}, std::pair{frac(3, 4), frac(1, 9)}}) {
      const Surface_derivatives<Q> d = s.derivatives(u, v, 2);
      // Closed forms: S = sum P_ij B_i B_j; Su = p sum (P_i+1,j - P_ij) B_i,p-1 B_j; ...
      Vector_3<Q> S{0, 0, 0}, Su{0, 0, 0}, Sv{0, 0, 0}, Suu{0, 0, 0}, Suv{0, 0, 0}, Svv{0, 0, 0};
      for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) {
          const Vector_3<Q> P = internal::to_vector(s.control_point(i, j));
          // d/du B_{i,p} = p (B_{i-1,p-1} - B_{i,p-1})
          const Q bu = bernstein(i, p, u), bv = bernstein(j, q, v);
          const Q du = Q(p) * (bernstein_or_zero(i - 1, p - 1, u) - bernstein_or_zero(i, p - 1, u));
          const Q dv = Q(q) * (bernstein_or_zero(j - 1, q - 1, v) - bernstein_or_zero(j, q - 1, v));
          const Q duu = p < 2 ? Q(0)
                              : Q(Q(p * (p - 1)) *
                                  (bernstein_or_zero(i - 2, p - 2, u) - Q(2) * bernstein_or_zero(i - 1, p - 2, u) +
                                   bernstein_or_zero(i, p - 2, u)));
          const Q dvv = q < 2 ? Q(0)
                              : Q(Q(q * (q - 1)) *
                                  (bernstein_or_zero(j - 2, q - 2, v) - Q(2) * bernstein_or_zero(j - 1, q - 2, v) +
                                   bernstein_or_zero(j, q - 2, v)));
          for (int c = 0; c < 3; ++c) {
            S[c] += bu * bv * P[c], Su[c] += du * bv * P[c], Sv[c] += bu * dv * P[c];
            Suu[c] += duu * bv * P[c], Suv[c] += du * dv * P[c], Svv[c] += bu * dvv * P[c];
          }
        }
      EXPECT_EQ(internal::to_vector(d.point), S);
      EXPECT_EQ(d.du, Su);
      EXPECT_EQ(d.dv, Sv);
      EXPECT_EQ(d.duu, Suu);
      EXPECT_EQ(d.duv, Suv);
      EXPECT_EQ(d.dvv, Svv);
    }
  }
}

TEST(NurbsSurface, RationalCylinderIsExactlyOnTheCylinderWithExactDerivatives) {
  const Nurbs_surface<Q> cyl = quarter_cylinder().convert<Q>();
  for (int k = 0; k <= 16; ++k) {
    const Q u = frac(k, 16), v = frac(16 - k, 9);
    const Surface_derivatives<Q> d = cyl.derivatives(u, v, 2);
    const Q &x = d.point.x, &y = d.point.y;
    EXPECT_EQ(x * x + y * y, 1);                       // on the circle
    EXPECT_EQ(d.point.z, Q(Q(2) * v));                       // linear along z
    EXPECT_EQ(x * d.du[0] + y * d.du[1], 0);           // tangent orthogonal to the radius
    EXPECT_EQ(x * d.duu[0] + d.du[0] * d.du[0] + y * d.duu[1] + d.du[1] * d.du[1], 0);  // (x^2+y^2)'' = 0
    EXPECT_EQ(d.dv, (Vector_3<Q>{0, 0, 2}));
    EXPECT_EQ(d.duv, (Vector_3<Q>{0, 0, 0}));
    // x = (1-t^2)/(1+t^2) exactly.
    EXPECT_EQ(x, Q(Q(1) - u * u) / Q(Q(1) + u * u));
    const Vector_3<Q> n = normal_direction(d);
    EXPECT_EQ(n[2], 0);
    EXPECT_GT(n[0] * x + n[1] * y, 0);  // outward normal, as the control net is ordered
  }
}

TEST(NurbsSurface, PartitionOfUnityAndKnotContinuityUnderRationals) {
  std::mt19937_64 rng(2);
  for (int trial = 0; trial < 8; ++trial) {
    const int p = 1 + trial % 5;
    const std::size_t n = static_cast<std::size_t>(p) + 1 + trial % 4 + 2;
    const std::vector<double> Ud = random_knots(rng, p, n);
    std::vector<Q> U;
    for (double k : Ud) U.push_back(Q(k));
    for (int s = 0; s <= 20; ++s) {
      const Q u = frac(s, 20);
      const std::size_t span = internal::find_span<Q>(p, U, n, u);
      internal::Small_buffer<Q> N;
      internal::basis_derivatives<Q>(span, u, p, 2, U, N);
      Q sum = 0, dsum = 0, ddsum = 0;
      for (int j = 0; j <= p; ++j) sum += N[j], dsum += N[(p + 1) + j], ddsum += N[2 * (p + 1) + j];
      EXPECT_EQ(sum, 1);
      EXPECT_EQ(dsum, 0);
      EXPECT_EQ(ddsum, 0);
    }
    // C^(p-m) continuity at an interior knot of multiplicity m: the two
    // neighbouring spans' polynomials agree at the knot (value; first
    // derivative when m < p).
    const std::vector<double> W;
    std::vector<Point_2<Q>> P;
    for (std::size_t i = 0; i < n; ++i) P.push_back({Q(static_cast<long>(i * i % 7)), Q(static_cast<long>(i % 3))});
    const Nurbs_curve<Q, 2> c(p, U, P);
    for (std::size_t k = p + 1; k < n; ++k) {
      if (U[k] == U[k - 1]) continue;
      std::size_t m = 1;
      while (k + m < U.size() && U[k + m] == U[k]) ++m;
      internal::Small_buffer<Q> left, right;
      internal::basis_derivatives<Q>(k - 1, U[k], p, 1, U, left);   // span ending at U[k]
      internal::basis_derivatives<Q>(k + m - 1, U[k], p, 1, U, right);  // span starting at U[k]
      for (int order = 0; order <= (static_cast<int>(m) < p ? 1 : 0); ++order) {
        Q a = 0, b = 0;
        for (int j = 0; j <= p; ++j) {
          a += left[order * (p + 1) + j] * P[k - 1 - p + j].x;
          b += right[order * (p + 1) + j] * P[k + m - 1 - p + j].x;
        }
        EXPECT_EQ(a, b) << "degree " << p << " knot " << k << " order " << order;
      }
    }
  }
}

TEST(NurbsSurface, IntervalEvaluationEnclosesEveryExactValueOfTheBox) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 10; ++trial) {
    const Nurbs_surface<double> sd = random_surface(rng, 1 + trial % 4, 1 + (trial + 1) % 4, 7, 6, trial % 2 == 1);
    const Nurbs_surface<Interval> si = sd.convert<Interval>();
    const Nurbs_surface<Q> sq = sd.convert<Q>();
    std::uniform_real_distribution<double> r(-0.05, 1.05);  // also a little outside (extrapolation)
    for (int b = 0; b < 10; ++b) {
      const double u0 = r(rng), v0 = 3 * r(rng) - 1, w = b % 2 ? 0.0 : 0.03;
      const Surface_derivatives<Interval> e = si.derivatives(Interval(u0, u0 + w), Interval(v0, v0 + w), 2);
      for (int s = 0; s <= 4; ++s) {
        const Q u = Q(u0) + Q(w) * frac(s, 4), v = Q(v0) + Q(w) * frac(4 - s, 4);
        const Surface_derivatives<Q> x = sq.derivatives(u, v, 2);
        const auto inside = [](const Interval& i, const Q& q) { return Q(i.inf()) <= q && q <= Q(i.sup()); };
        EXPECT_TRUE(inside(e.point.x, x.point.x) && inside(e.point.y, x.point.y) && inside(e.point.z, x.point.z));
        for (int c = 0; c < 3; ++c) {
          EXPECT_TRUE(inside(e.du[c], x.du[c]) && inside(e.dv[c], x.dv[c]));
          EXPECT_TRUE(inside(e.duu[c], x.duu[c]) && inside(e.duv[c], x.duv[c]) && inside(e.dvv[c], x.dvv[c]));
        }
      }
      if (w == 0) {
        EXPECT_LT(e.point.x.sup() - e.point.x.inf(), 1e-12);  // point boxes stay tight
      }
    }
  }
}

TEST(NurbsSurface, DoubleAndMpfrAreCloseToExact) {
  std::mt19937_64 rng(4);
  double worst = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const Nurbs_surface<double> sd = random_surface(rng, 1 + trial % 5, 1 + (trial * 2) % 5, 9, 8, trial % 3 == 0);
    const Nurbs_surface<Q> sq = sd.convert<Q>();
    const Nurbs_surface<Mpfr_number<200>> sm = sd.convert<Mpfr_number<200>>();
    std::uniform_real_distribution<double> r(0, 1);
    for (int s = 0; s < 20; ++s) {
      const double u = r(rng), v = 3 * r(rng) - 1;
      const auto d = sd.derivatives(u, v, 2);
      const auto x = sq.derivatives(Q(u), Q(v), 2);
      const auto m = sm.derivatives(u, v, 2);
      const double scale = 1 + std::abs(x.point.z.get_d());
      worst = std::max(worst, std::abs(d.point.z - x.point.z.get_d()) / scale);
      EXPECT_NEAR(d.duv[2], x.duv[2].get_d(), 1e-9 * (1 + std::abs(x.duv[2].get_d())));
      const Q mpfr_error = Number_traits<Mpfr_number<200>>::to_rational(m.dvv[1]) - x.dvv[1];
      EXPECT_LT(std::abs(mpfr_error.get_d()), 1e-50 * (1 + std::abs(x.dvv[1].get_d())));
    }
  }
  EXPECT_LT(worst, 1e-13);
}

TEST(NurbsCurve, RationalCircleAndDerivativesExact) {
  const Nurbs_curve<Q, 2> c = quarter_circle().convert<Q>();
  for (int k = 0; k <= 10; ++k) {
    const Q t = frac(k, 10);
    const auto d = c.derivatives(t, 2);
    EXPECT_EQ(d[0][0] * d[0][0] + d[0][1] * d[0][1], 1);
    EXPECT_EQ(d[0][0] * d[1][0] + d[0][1] * d[1][1], 0);
    // y = 2t/(1+t^2): y' = 2(1-t^2)/(1+t^2)^2
    EXPECT_EQ(d[1][1], Q(Q(2) * (Q(1) - t * t)) / Q((Q(1) + t * t) * (Q(1) + t * t)));
  }
  // A space curve and its exact interval enclosure.
  std::mt19937_64 rng(5);
  // Narrow parameter intervals, and one wide interval over several spans
  // (whose rational pieces are bisected until the weights' enclosure is
  // positive).
  const Nurbs_curve_3<double> s = random_curve<3>(rng, 3, 9, true);
  const auto sq = s.convert<Q>();
  const auto si = s.convert<Interval>();
  const auto wide = si.derivatives(Interval(0.2, 2.7), 1);
  for (int k = 0; k < 125; ++k) {
    const double t0 = 0.2 + k / 50.0;
    const auto e = si.derivatives(Interval(t0, t0 + 1.0 / 64), 1);
    const auto x = sq.derivatives(Q(t0) + frac(k % 5, 320), 1);
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(Q(wide[0][c].inf()) <= x[0][c] && x[0][c] <= Q(wide[0][c].sup()));
    for (int c = 0; c < 3; ++c) {
      EXPECT_LE(Q(e[0][c].inf()), x[0][c]);
      EXPECT_GE(Q(e[0][c].sup()), x[0][c]);
      EXPECT_LE(Q(e[1][c].inf()), x[1][c]);
      EXPECT_GE(Q(e[1][c].sup()), x[1][c]);
    }
  }
}

TEST(NurbsSurface, ExtrapolationContinuesTheEndSpans) {
  const Nurbs_surface<double> s = quarter_cylinder();
  const auto a = s.evaluate(-1e-9, 0.5), b = s.evaluate(0, 0.5);
  EXPECT_NEAR(a.x, b.x, 1e-8);
  EXPECT_NEAR(a.y, b.y, 1e-8);
  EXPECT_LT(a.y, b.y);  // continues below u = 0
}

TEST(NurbsBadInput, InconsistentDataIsRefusedWithTypedErrors) {
  const std::vector<Point_3<double>> P4{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}};
  const std::vector<double> U{0, 0, 1, 1};
  EXPECT_NO_THROW(Nurbs_surface<double>(1, 1, U, U, 2, 2, P4));
  EXPECT_THROW(Nurbs_surface<double>(0, 1, {0, 1}, U, 2, 2, P4), Invalid_spline);        // degree 0
  EXPECT_THROW(Nurbs_surface<double>(1, 1, {0, 0, 1}, U, 2, 2, P4), Invalid_spline);     // knot count
  EXPECT_THROW(Nurbs_surface<double>(1, 1, {0, 1, 0, 1}, U, 2, 2, P4), Invalid_spline);  // decreasing
  EXPECT_THROW(Nurbs_surface<double>(1, 1, {1, 1, 1, 1}, U, 2, 2, P4), Invalid_spline);  // empty domain
  EXPECT_THROW(Nurbs_surface<double>(1, 1, U, U, 2, 3, P4), Invalid_spline);             // net size
  EXPECT_THROW(Nurbs_surface<double>(1, 1, U, U, 2, 2, P4, {1, 1, 0, 1}), Invalid_spline);  // weight 0
  EXPECT_THROW(Nurbs_surface<double>(1, 1, U, U, 2, 2, P4, {1, 1, -2, 1}), Invalid_spline);
  EXPECT_THROW(Nurbs_surface<double>(1, 1, U, U, 2, 2, P4, {1, 1}), Invalid_spline);
  auto nan = P4;
  nan[2].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Nurbs_surface<double>(1, 1, U, U, 2, 2, nan), Invalid_spline);
  // Interior multiplicity above the degree: discontinuous.
  EXPECT_THROW(Nurbs_curve_2<double>(1, {0, 0, 0.5, 0.5, 1, 1}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}), Invalid_spline);
  EXPECT_NO_THROW(Nurbs_curve_2<double>(2, {0, 0, 0, 0.5, 0.5, 1, 1, 1}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 2}}));
  // All control points on a line: no tangent plane anywhere.
  const std::vector<Point_3<double>> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  EXPECT_THROW(Nurbs_surface<double>(1, 1, U, U, 2, 2, line), Degenerate_surface);
  try {
    Nurbs_surface<double>(1, 1, U, U, 2, 2, line);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Error_code::invalid_input);
  }
  // A collapsed edge (a triangle as a bilinear patch): no normal at the apex.
  const Nurbs_surface<double> apex(1, 1, U, U, 2, 2, {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  EXPECT_THROW((void)unit_normal(apex.derivatives(0.0, 0.5)), Degenerate_surface);
  EXPECT_NO_THROW((void)unit_normal(apex.derivatives(0.5, 0.5)));
}

}  // namespace
