// Exact_kernel::exact_double: the exact double value of a rational, or none.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "relgeo/kernel/exact_kernel.h"

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
