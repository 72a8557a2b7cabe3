// The expansion arithmetic of kernel/internal/expansion.h against GMP
// rationals: every result has the exact value, is a nonoverlapping expansion
// in increasing magnitude without zeros, and has the sign of its last
// component; on random, cancelling, power-of-two and subnormal operands.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "relgeo/core/dyadic.h"
#include "relgeo/kernel/internal/expansion.h"

namespace relgeo::internal {
namespace {

template <std::size_t C>
mpq_class value_of(const Expansion<C>& e) {
  mpq_class s = 0;
  for (double x : e) s += exact_rational(x);
  return s;
}

// Exponents of the lowest and highest set bits of a nonzero double.
int lowest_bit(double x) {
  const Binary_parts p = binary_parts(x);
  return p.exponent + std::countr_zero(static_cast<std::uint64_t>(std::abs(p.mantissa)));
}
int highest_bit(double x) {
  const Binary_parts p = binary_parts(x);
  return p.exponent + std::bit_width(static_cast<std::uint64_t>(std::abs(p.mantissa))) - 1;
}

// The invariants every operation must keep.
template <std::size_t C>
::testing::AssertionResult well_formed(const Expansion<C>& e, const mpq_class& expected) {
  if (e.size() > C) return ::testing::AssertionFailure() << "size " << e.size() << " > capacity " << C;
  for (std::size_t i = 0; i < e.size(); ++i) {
    if (e[i] == 0 || !std::isfinite(e[i])) return ::testing::AssertionFailure() << "component " << i << " is " << e[i];
    if (i > 0 && lowest_bit(e[i]) <= highest_bit(e[i - 1]))
      return ::testing::AssertionFailure() << "components " << i - 1 << " and " << i << " overlap";
  }
  const mpq_class v = value_of(e);
  if (v != expected) return ::testing::AssertionFailure() << "value " << v << " != " << expected;
  const int s = sgn(v);
  if (to_int(e.sign()) != (s > 0 ? 1 : s < 0 ? -1 : 0)) return ::testing::AssertionFailure() << "wrong sign";
  // estimate() is within (n - 1) u of the magnitudes' sum (plus rounding of
  // that sum, covered by the factor 2).
  const mpq_class error = abs(mpq_class(exact_rational(e.estimate())) - v);
  const double n = static_cast<double>(e.size());
  if (error > exact_rational(2 * n * 0x1p-53 * e.magnitude()))
    return ::testing::AssertionFailure() << "estimate off by " << error;
  return ::testing::AssertionSuccess();
}

// Doubles of varied magnitude and significand: random 53-bit, powers of two,
// short significands (so sums tie and cancel), and their negatives.
class Operands {
 public:
  explicit Operands(std::uint64_t seed, int e_lo = -60, int e_hi = 60) : g_(seed), e_lo_(e_lo), e_hi_(e_hi) {}
  double next() {
    const int e = e_lo_ + static_cast<int>(g_() % static_cast<std::uint64_t>(e_hi_ - e_lo_ + 1));
    double m = 0;
    switch (g_() % 4) {
      case 0: m = static_cast<double>(g_() >> 11) * 0x1p-53; break;  // 53 random bits
      case 1: m = 1; break;                                            // power of two
      case 2: m = static_cast<double>(g_() % 8) + 1; break;            // 3 bits: ties
      default: m = static_cast<double>((g_() >> 11) | 1) * 0x1p-53;     // full significand
    }
    return (g_() % 2 ? -1 : 1) * std::ldexp(m, e);
  }
  std::mt19937_64& engine() { return g_; }

 private:
  std::mt19937_64 g_;
  int e_lo_, e_hi_;
};

// A random expansion of up to 12 components (grown from random doubles).
Expansion<12> random_expansion(Operands& o, mpq_class& value) {
  Expansion<12> e;
  value = 0;
  const int n = static_cast<int>(o.engine()() % 13);
  for (int i = 0; i < n; ++i) {
    const double x = o.next();
    value += exact_rational(x);
    e = Expansion<12>(e + x);  // at most i + 1 <= 12 components
  }
  return e;
}

TEST(Expansion, ConstructionAndSign) {
  EXPECT_TRUE(Expansion<1>().is_zero());
  EXPECT_EQ(Expansion<1>(0.0).size(), 0u);
  EXPECT_EQ(Expansion<1>(-0.0).size(), 0u);
  EXPECT_EQ(Expansion<1>(-3.0).sign(), Certified_sign::negative);
  EXPECT_EQ(Expansion<4>().sign(), Certified_sign::zero);
  const Expansion<2> s = exact_sum(1.0, 0x1p-60);
  EXPECT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0], 0x1p-60);
  EXPECT_EQ(s[1], 1.0);
  EXPECT_TRUE(exact_difference(0.1, 0.1).is_zero());
  EXPECT_TRUE(well_formed(exact_product(0.1, 0.3), mpq_class(exact_rational(0.1)) * exact_rational(0.3)));
}

TEST(Expansion, GrowSumScaleProductAreExact) {
  Operands o(20260501);
  for (int trial = 0; trial < 20000; ++trial) {
    mpq_class ve, vf;
    const Expansion<12> e = random_expansion(o, ve);
    const Expansion<12> f = random_expansion(o, vf);
    ASSERT_TRUE(well_formed(e, ve)) << trial;
    const double b = o.next();
    const mpq_class vb = exact_rational(b);
    ASSERT_TRUE(well_formed(e + b, ve + vb)) << trial;
    ASSERT_TRUE(well_formed(e - b, ve - vb)) << trial;
    ASSERT_TRUE(well_formed(e + f, ve + vf)) << trial;
    ASSERT_TRUE(well_formed(e - f, ve - vf)) << trial;
    ASSERT_TRUE(well_formed(e - e, mpq_class(0))) << trial;
    ASSERT_TRUE(well_formed(-e, -ve)) << trial;
    ASSERT_TRUE(well_formed(e * b, ve * vb)) << trial;
    ASSERT_TRUE(well_formed(e * f, ve * vf)) << trial;
    Expansion<12> c = e;
    c.compress();
    ASSERT_TRUE(well_formed(c, ve)) << trial;
    ASSERT_LE(c.size(), e.size());
  }
}

TEST(Expansion, NestedProductsOfDegreeSix) {
  // The shape of the coming indirect predicates: products of sums, nested.
  Operands o(77, -30, 30);
  for (int trial = 0; trial < 2000; ++trial) {
    double x[6];
    mpq_class q[6];
    for (int i = 0; i < 6; ++i) x[i] = o.next(), q[i] = exact_rational(x[i]);
    const auto d0 = exact_difference(x[0], x[1]), d1 = exact_difference(x[2], x[3]), d2 = exact_sum(x[4], x[5]);
    const auto p = (d0 * d1) * d2;       // degree 3, 32 components at most
    const auto sq = p * p;               // degree 6
    const mpq_class v = (q[0] - q[1]) * (q[2] - q[3]) * (q[4] + q[5]);
    ASSERT_TRUE(well_formed(p, v)) << trial;
    ASSERT_TRUE(well_formed(sq, v * v)) << trial;
    ASSERT_TRUE(well_formed(sq - p * p, mpq_class(0))) << trial;
  }
}

TEST(Expansion, SubnormalSumsAndLowestExactProducts) {
  // Sums are exact at any magnitude; products while the factors' lowest bits
  // sum to >= -1074 (here lowest bits 2^-537 * 2^-537, and 2^-1074 times an
  // odd 53-bit integer).
  Operands o(5, -1074, -1000);
  for (int trial = 0; trial < 5000; ++trial) {
    const double a = o.next(), b = o.next(), c = o.next();
    const mpq_class qa = exact_rational(a), qb = exact_rational(b), qc = exact_rational(c);
    ASSERT_TRUE(well_formed((exact_sum(a, b) + c) - exact_difference(c, a), qa + qb + qc - (qc - qa))) << trial;
  }
  const double h = std::ldexp(1.0 + 0x1p-52, -485);  // lowest bit 2^-537
  ASSERT_TRUE(well_formed(exact_product(h, h), mpq_class(exact_rational(h)) * exact_rational(h)));
  ASSERT_TRUE(well_formed(Expansion<1>(0x1p-1074) * 0x1.fffffffffffffp52,
                          mpq_class(exact_rational(0x1p-1074)) * exact_rational(0x1.fffffffffffffp52)));
}

TEST(Expansion, CompressKeepsTheValueInFewComponents) {
  // 1 + 2^-60 + ... grown one power of two at a time: many components that
  // compress into few.
  Expansion<64> e;
  mpq_class v = 0;
  for (int k = 0; k < 60; ++k) {
    const double x = std::ldexp(1.0, -k * 3);
    e = Expansion<64>(e + x);
    v += exact_rational(x);
  }
  ASSERT_TRUE(well_formed(e, v));
  e.compress();
  ASSERT_TRUE(well_formed(e, v));
  EXPECT_LE(e.size(), 4u);  // 180 bits of value in 53-bit components
}

}  // namespace
}  // namespace relgeo::internal
