// The expansion arithmetic of kernel/internal/expansion.h and
// dynamic_expansion.h against GMP rationals: every result has the exact value, is a nonoverlapping expansion
// in increasing magnitude without zeros, and has the sign of its last
// component; on random, cancelling, power-of-two and subnormal operands.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "relgeo/core/dyadic.h"
#include "relgeo/kernel/internal/determinants.h"
#include "relgeo/kernel/internal/exact_dyadic.h"
#include "relgeo/kernel/internal/expansion.h"
#include "relgeo/kernel/internal/filtered_predicate.h"

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

// Dynamic_expansion (internal/dynamic_expansion.h) and the scaling of the
// generic filtered predicate (internal/filtered_predicate.h).

::testing::AssertionResult well_formed(const Dynamic_expansion& e, const mpq_class& expected) {
  mpq_class v = 0;
  const double* previous = nullptr;
  for (const double& x : e) {
    if (x == 0 || !std::isfinite(x)) return ::testing::AssertionFailure() << "component " << x;
    if (previous && lowest_bit(x) <= highest_bit(*previous)) return ::testing::AssertionFailure() << "overlap";
    v += exact_rational(x);
    previous = &x;
  }
  if (v != expected) return ::testing::AssertionFailure() << "value " << v << " != " << expected;
  const int s = sgn(v);
  if (to_int(e.sign()) != (s > 0 ? 1 : s < 0 ? -1 : 0)) return ::testing::AssertionFailure() << "wrong sign";
  return ::testing::AssertionSuccess();
}

TEST(DynamicExpansion, RandomPolynomialsUpToDegreeTwelveAreExact) {
  // Random expression trees: leaves are doubles, each node a sum, difference
  // or product of two earlier values, up to degree 12 (the lengths grow far
  // beyond the small buffer).
  Operands o(2026, -40, 40);
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<Dynamic_expansion> e;
    std::vector<mpq_class> q;
    std::vector<int> degree;
    for (int i = 0; i < 6; ++i) {
      const double x = o.next();
      e.emplace_back(x), q.push_back(exact_rational(x)), degree.push_back(1);
    }
    for (int step = 0; step < 10; ++step) {
      const std::size_t a = o.engine()() % e.size(), b = o.engine()() % e.size();
      const int op = static_cast<int>(o.engine()() % 3);
      if (op == 2 && degree[a] + degree[b] > 12) continue;
      const Dynamic_expansion r = op == 0 ? e[a] + e[b] : (op == 1 ? e[a] - e[b] : e[a] * e[b]);
      const mpq_class v = op == 0 ? mpq_class(q[a] + q[b]) : (op == 1 ? mpq_class(q[a] - q[b]) : mpq_class(q[a] * q[b]));
      ASSERT_TRUE(well_formed(r, v)) << trial << " step " << step;
      e.push_back(r), q.push_back(v), degree.push_back(op == 2 ? degree[a] + degree[b] : std::max(degree[a], degree[b]));
    }
    const Dynamic_expansion& last = e.back();
    ASSERT_TRUE(well_formed(last * last - last * last, mpq_class(0)));  // exact cancellation: no component
    EXPECT_EQ((last * last - last * last).size(), 0u);
  }
}

TEST(DynamicExpansion, OverflowMakesTheSignUncertainAndStaysSo) {
  const Dynamic_expansion big(0x1p600);
  const Dynamic_expansion square = big * big;  // 2^1200: infinite
  EXPECT_EQ(square.sign(), Certified_sign::uncertain);
  EXPECT_EQ((square - square).sign(), Certified_sign::uncertain);           // inf - inf
  EXPECT_EQ((square * Dynamic_expansion(-1.0) + big).sign(), Certified_sign::uncertain);
  EXPECT_EQ((big * Dynamic_expansion(0x1p400)).sign(), Certified_sign::positive);  // 2^1000: finite
}

TEST(FilteredPredicate, ExpansionScalingAcceptsExactlyTheSpanItProves) {
  // Degree 3: shift 994 / 3 - 2 - 1 = 328 for inputs below 2^1; the lowest
  // set bit must stay at 2^-358 or above after it: 2^-686 before.
  const std::array<double, 2> edge{1.0, 0x1p-686}, beyond{1.0, 0x1p-687};
  EXPECT_TRUE(Expansion_scaling(edge, 3).exact());
  EXPECT_FALSE(Expansion_scaling(beyond, 3).exact());
  // Degree 28 (four TPI points): a 53-bit double spans 53 positions, within 71.
  const std::array<double, 1> full{0x1.fffffffffffffp0};
  EXPECT_TRUE(Expansion_scaling(full, 28).exact());
  const std::array<double, 2> wide{1.0, 0x1p-75};
  EXPECT_FALSE(Expansion_scaling(wide, 28).exact());
  // Scaling is by a power of two, exactly.
  const Expansion_scaling scale(edge, 3);
  EXPECT_EQ(*scale(0x1p-686).begin(), 0x1p-358);
}

TEST(FilteredPredicate, ExpansionsAgreeWithGmpUpToTheEdgeOfTheSpan) {
  // orientation_3 of the origin, q, r (20-bit significands, magnitude about
  // 1) and s = 2^-640 (a q + b r) moved off the plane by -1, 0 or 1 units of
  // 2^-661 per coordinate: bits from 2^-661 to 2^1, near the 687 positions
  // degree 3 allows, so the scaled products reach down to 2^-999 (normal
  // range ends at 2^-1022: close). Exact zeros included.
  std::mt19937_64 g(7);
  const auto significand = [&] { return std::ldexp(static_cast<double>((g() >> 44) | 1), -20) * (g() % 2 ? 1 : -1); };
  int decided = 0, zeros = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::array<double, 12> c{};
    for (int i = 3; i < 9; ++i) c[i] = significand();
    const double a = static_cast<double>(g() % 7) - 3, b = static_cast<double>(g() % 7) - 3;
    for (int i = 0; i < 3; ++i)
      c[9 + i] = std::ldexp(a * c[3 + i] + b * c[6 + i], -640) + std::ldexp(static_cast<double>(g() % 3) - 1, -661);
    const auto formula = [&c](const auto& to) {
      return certified_sign_of(orientation_3_determinant(to(c[0]), to(c[1]), to(c[2]), to(c[3]), to(c[4]), to(c[5]),
                                                         to(c[6]), to(c[7]), to(c[8]), to(c[9]), to(c[10]), to(c[11])));
    };
    const Certified_sign s = expansion_sign(c, 3, formula);
    if (!is_certain(s)) continue;
    ++decided;
    zeros += s == Certified_sign::zero;
    ASSERT_EQ(s, exact_orientation_3(c)) << trial;
  }
  EXPECT_EQ(decided, 20000);
  EXPECT_GT(zeros, 500);
}

}  // namespace
}  // namespace relgeo::internal
