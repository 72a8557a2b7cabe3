// Interval arithmetic: every result encloses the exact result of the exact
// operands (checked with GMP rationals), exact operations stay exact.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "relgeo/core/interval.h"
#include "support/exact_oracle.h"

namespace relgeo {
namespace {

using test::encloses;

double random_double(std::mt19937_64& g) {
  // Random sign, exponent in [-1074, 1000] and mantissa: covers subnormals.
  const int e = static_cast<int>(g() % 2075) - 1074;
  const double m = 1.0 + static_cast<double>(g() >> 12) * 0x1p-52;
  const double v = std::ldexp(m, e);
  return (g() & 1) ? -v : v;
}

TEST(Interval, PointOperationsEncloseTheExactResult) {
  std::mt19937_64 g(7);
  for (int i = 0; i < 200000; ++i) {
    const double a = random_double(g);
    const double b = (i % 3 == 0) ? std::ldexp(a, static_cast<int>(g() % 8)) : random_double(g);
    const Interval A(a), B(b);
    const mpq_class qa(a), qb(b);
    ASSERT_TRUE(encloses(A + B, qa + qb)) << a << " + " << b;
    ASSERT_TRUE(encloses(A - B, qa - qb)) << a << " - " << b;
    ASSERT_TRUE(encloses(A * B, qa * qb)) << a << " * " << b;
  }
}

TEST(Interval, ProductNextToTheOverflowThresholdIsAnEnclosure) {
  // fl(xy) within 2^-26 of DBL_MAX: without FMA, Dekker's split of the
  // exact error overflowed and the product was reported as [p, up(p)]
  // although the exact product is below p.
  const double x = 0x1.c386bbc204f8ap+511, y = 0x1.22495982d9b23p+512;
  const Interval p = Interval(x) * Interval(y);
  const mpq_class exact = mpq_class(x) * mpq_class(y);
  EXPECT_LT(exact, mpq_class(x * y)) << "the case rounds up";
  EXPECT_TRUE(encloses(p, exact)) << p.inf() << " " << p.sup();
  EXPECT_TRUE(std::isfinite(p.sup()));
}

TEST(Interval, ProductsOverTheWholeExponentRangeAreTightEnclosures) {
  // For every exponent of the product, from the subnormals to the overflow
  // threshold (the exponents of the factors split at random), random
  // mantissas and signs: exact product (GMP) inside, width a few ulps.
  std::mt19937_64 g(11);
  std::size_t checked = 0;
  for (int t = -1074; t <= 1023; ++t) {
    for (int k = 0; k < 48; ++k) {
      const int ex = std::clamp(static_cast<int>(g() % 1600) - 800, t - 1022, t + 1074);
      const double mx = 1.0 + static_cast<double>(g() >> 12) * 0x1p-52;
      const double my = 1.0 + static_cast<double>(g() >> 12) * 0x1p-52;
      double x = std::ldexp(mx, ex), y = std::ldexp(my, t - ex);
      if (!std::isfinite(x) || !std::isfinite(y) || x == 0 || y == 0) continue;
      if (g() & 1) x = -x;
      if (g() & 1) y = -y;
      const Interval p = Interval(x) * Interval(y);
      const mpq_class exact = mpq_class(x) * mpq_class(y);
      ASSERT_TRUE(encloses(p, exact)) << std::hexfloat << x << " * " << y;
      if (std::isfinite(p.inf()) && std::isfinite(p.sup())) {
        const double scale = std::max(std::abs(p.inf()), std::abs(p.sup()));
        const double ulp = std::max(std::nextafter(scale, INFINITY) - scale, 0x1p-1074);
        ASSERT_LE(p.sup() - p.inf(), 4 * ulp) << std::hexfloat << x << " * " << y;
      }
      ++checked;
    }
  }
  // And products right below the overflow threshold (within 2^-20 of
  // DBL_MAX), where the error-free product needs care.
  std::size_t near_overflow = 0;
  for (int k = 0; k < 20000; ++k) {
    const int ex = static_cast<int>(g() % 1000) - 500;
    const double mx = 1.0 + static_cast<double>(g() >> 12) * 0x1p-52;
    const double target = 2.0 - static_cast<double>(g() >> 44) * 0x1p-40;  // in (2 - 2^-20, 2]
    const double x = std::ldexp(mx, ex), y = std::ldexp(target / mx, 1023 - ex);
    if (!std::isfinite(x * y)) continue;
    const Interval p = Interval(x) * Interval(-y);
    ASSERT_TRUE(encloses(p, -(mpq_class(x) * mpq_class(y)))) << std::hexfloat << x << " * " << -y;
    ++near_overflow;
  }
  EXPECT_GT(checked, 90000u);
  EXPECT_GT(near_overflow, 5000u);
}

TEST(Interval, WideOperationsEncloseAllEndpointCombinations) {
  std::mt19937_64 g(9);
  std::uniform_real_distribution<double> d(-10, 10);
  for (int i = 0; i < 50000; ++i) {
    double a0 = d(g), a1 = d(g), b0 = d(g), b1 = d(g);
    if (a0 > a1) std::swap(a0, a1);
    if (b0 > b1) std::swap(b0, b1);
    const Interval A(a0, a1), B(b0, b1);
    for (double x : {a0, a1})
      for (double y : {b0, b1}) {
        ASSERT_TRUE(encloses(A * B, mpq_class(x) * mpq_class(y)));
        ASSERT_TRUE(encloses(A + B, mpq_class(x) + mpq_class(y)));
        ASSERT_TRUE(encloses(A - B, mpq_class(x) - mpq_class(y)));
      }
  }
}

TEST(Interval, ExactOperationsStayPoints) {
  EXPECT_TRUE((Interval(12.0) - Interval(0.5)).is_point());   // exact difference
  EXPECT_TRUE((Interval(11.5) * Interval(2.0)).is_point());   // exact product
  EXPECT_EQ((Interval(3.0) - Interval(3.0)).sign(), Certified_sign::zero);
  EXPECT_EQ((Interval(0.0) * Interval(1e300, 1e301)).sign(), Certified_sign::zero);
  EXPECT_FALSE((Interval(0.1) * Interval(0.1)).is_point());   // inexact product is widened
}

TEST(Interval, NanAndInfinityAreNeverDefinite) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ((Interval(nan) + Interval(1.0)).sign(), Certified_sign::uncertain);
  EXPECT_EQ((Interval(nan) * Interval(0.0)).sign(), Certified_sign::uncertain);
  EXPECT_EQ((Interval(inf) - Interval(inf)).sign(), Certified_sign::uncertain);
  EXPECT_EQ(compare(Interval(1.0, 2.0), Interval(1.5)), Certified_sign::uncertain);
  EXPECT_EQ(compare(Interval(1.0, 2.0), Interval(2.5)), Certified_sign::negative);
}

}  // namespace
}  // namespace relgeo
