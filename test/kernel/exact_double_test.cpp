// Exact_kernel::exact_double: the exact double value of a rational, or none;
// and the exact decoding of a double into mantissa and power of two.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/core/dyadic.h"

namespace relgeo {
namespace {

std::optional<double> value_of(const mpq_class& q) { return Exact_kernel::exact_double(q); }

TEST(ExactDouble, EveryDoubleComesBackBitForBit) {
  std::mt19937_64 random(7);
  for (int i = 0; i < 200000; ++i) {
    double d = std::bit_cast<double>(random());
    if (!std::isfinite(d)) continue;
    if (d == 0) d = 0.0;  // -0 has no rational: it comes back as +0
    const std::optional<double> back = value_of(mpq_class(d));
    ASSERT_TRUE(back.has_value()) << d;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(*back), std::bit_cast<std::uint64_t>(d)) << d;
  }
}

TEST(ExactDouble, RangeEnds) {
  constexpr double denorm_min = std::numeric_limits<double>::denorm_min();
  constexpr double max = std::numeric_limits<double>::max();
  for (double d : {0.0, 1.0, -1.0, 0.1, -3.5, denorm_min, -denorm_min, max, -max,
                   std::numeric_limits<double>::min(), std::ldexp(1.0, 63), std::ldexp(1.0, -63),
                   std::ldexp(1.0, 64), std::ldexp(1.0, -64), 9007199254740991.0 /* 2^53 - 1 */})
    EXPECT_EQ(value_of(mpq_class(d)), d) << d;
}

TEST(ExactDouble, NonDoublesAreRefused) {
  mpq_class tiny(1);
  mpq_div_2exp(tiny.get_mpq_t(), tiny.get_mpq_t(), 1075);  // half of the smallest subnormal
  mpq_class huge(1);
  mpq_mul_2exp(huge.get_mpq_t(), huge.get_mpq_t(), 1024);  // just above max
  const mpq_class odd54 = mpq_class(mpz_class(1) << 53) + 1;  // 54 significant bits
  EXPECT_FALSE(value_of(mpq_class(1, 3)).has_value());
  EXPECT_FALSE(value_of(mpq_class(-2, 5)).has_value());
  EXPECT_FALSE(value_of(tiny).has_value());
  EXPECT_FALSE(value_of(-tiny).has_value());
  EXPECT_FALSE(value_of(huge).has_value());
  EXPECT_FALSE(value_of(odd54).has_value());
  EXPECT_FALSE(value_of(odd54 / 1024).has_value());                  // one-limb path
  EXPECT_FALSE(value_of(odd54 / (mpz_class(1) << 70)).has_value());  // multi-limb path
  EXPECT_EQ(value_of(mpq_class(3, 1024)), 3.0 / 1024);
}

TEST(ExactDouble, PointsNeedBothCoordinates) {
  EXPECT_EQ(Exact_kernel::exact_double_point({mpq_class(1, 4), mpq_class(-2)}),
            (relgeo::Point_2<double>{0.25, -2.0}));
  EXPECT_FALSE(Exact_kernel::exact_double_point({mpq_class(1, 4), mpq_class(1, 3)}).has_value());
  EXPECT_FALSE(Exact_kernel::exact_double_point({mpq_class(1, 3), mpq_class(1, 4)}).has_value());
}

}  // namespace
}  // namespace relgeo

namespace relgeo::internal {
namespace {

TEST(BinaryParts, EveryDoubleIsItsMantissaTimesItsPowerOfTwo) {
  // Across the whole range, subnormals included, mantissas of 53 bits (wider
  // than a 32-bit long: there set_mpz loads them with mpz_import, with a
  // 64-bit long through mpz_set_si) — checked against GMP's own conversion.
  std::mt19937_64 g(53);
  for (int i = 0; i < 100000; ++i) {
    const int e = static_cast<int>(g() % 2098) - 1074;
    double v = std::ldexp(1.0 + static_cast<double>(g() >> 12) * 0x1p-52, e);
    if (!std::isfinite(v)) continue;
    if (g() & 1) v = -v;
    const Binary_parts p = binary_parts(v);
    ASSERT_LT(std::abs(p.mantissa), std::int64_t{1} << 53);
    mpz_class m;
    set_mpz(m.get_mpz_t(), p.mantissa);
    mpq_class r(m);
    mpz_class two_power = 1;
    two_power <<= static_cast<unsigned>(std::abs(p.exponent));
    if (p.exponent >= 0) r *= two_power;
    else r /= two_power;
    ASSERT_EQ(r, mpq_class(v)) << std::hexfloat << v;
    ASSERT_EQ(exact_rational(v), mpq_class(v)) << std::hexfloat << v;
  }
  EXPECT_EQ(exact_rational(0.0), 0);
  EXPECT_EQ(exact_rational(-0.0), 0);
  EXPECT_EQ(binary_parts(0x1p-1074).mantissa, 1);
  EXPECT_EQ(binary_parts(0x1p-1074).exponent, -1074);
  mpz_class big;
  set_mpz(big.get_mpz_t(), -(std::int64_t{1} << 52) - 12345);
  EXPECT_EQ(big, mpz_class("-4503599627382841"));
  // The ends of int64_t, whichever path loads them.
  set_mpz(big.get_mpz_t(), std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ(big, mpz_class("-9223372036854775808"));
  set_mpz(big.get_mpz_t(), std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(big, mpz_class("9223372036854775807"));
}

}  // namespace
}  // namespace relgeo::internal
