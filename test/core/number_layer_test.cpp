// The number layer (core/number_traits.h, rounding.h, dyadic.h,
// mpfr_number.h): exact values read from bits, single and directed rounding
// of rationals and MPFR values checked against GMP, bounds of every number
// type, interval division, MPFR value semantics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "relgeo/core/number_traits.h"
#include "support/fp_environments.h"

namespace relgeo {
namespace {

// A rational strictly between a and b whose distance to a is `fraction` of
// the gap (0 < fraction < 1).
mpq_class between(double a, double b, const mpq_class& fraction) {
  return exact_rational(a) + (exact_rational(b) - exact_rational(a)) * fraction;
}

TEST(NumberLayer, ExactValuesFromTheBitsOfEveryIeeeType) {
  EXPECT_EQ(exact_rational(0x1p-1074), mpq_class(1) / (mpz_class(1) << 1074));
  EXPECT_EQ(exact_rational(-0x1.8p-1073), -mpq_class(3) / (mpz_class(1) << 1074));
  EXPECT_EQ(exact_rational(std::numeric_limits<float>::denorm_min()), mpq_class(1) / (mpz_class(1) << 149));
  EXPECT_EQ(exact_rational(-1.5f), mpq_class(-3, 2));
  EXPECT_EQ(exact_rational(std::numeric_limits<double>::max()),
            mpq_class(((mpz_class(1) << 53) - 1) << 971));
  std::mt19937_64 rng(7);
  for (int i = 0; i < 20000; ++i) {
    const double d = std::bit_cast<double>(rng());
    if (!std::isfinite(d)) continue;
    ASSERT_EQ(exact_rational(d), mpq_class(d)) << std::hexfloat << d;
    const long double l = static_cast<long double>(d) * (1 + 0x1p-60L);
    const Dyadic y = dyadic_of(l);
    ASSERT_TRUE(d == 0 || mpz_odd_p(y.mantissa.get_mpz_t()));
    ASSERT_EQ(round_rational<long double>(to_rational(y)), l);
  }
  EXPECT_THROW(exact_rational(std::nan("")), Non_finite_input);
  EXPECT_THROW(dyadic_of(std::numeric_limits<float>::infinity()), Non_finite_input);
}

TEST(NumberLayer, RationalsAreDyadicExactlyWhenTheirDenominatorIsAPowerOfTwo) {
  ASSERT_TRUE(dyadic_of(mpq_class(12, 32)).has_value());
  EXPECT_EQ(dyadic_of(mpq_class(12, 32))->mantissa, 3);
  EXPECT_EQ(dyadic_of(mpq_class(12, 32))->exponent, -3);
  EXPECT_FALSE(dyadic_of(mpq_class(1, 3)).has_value());
  EXPECT_EQ(to_rational(*dyadic_of(mpq_class(0))), 0);
}

// Rounding to nearest in two steps (53 bits with an unbounded exponent, then
// to the subnormal grid) is wrong on this rational; round_rational rounds once.
TEST(NumberLayer, RationalsRoundOnceIntoTheSubnormalRange) {
  // Just above the midpoint of 2^-1074 and 2*2^-1074, by less than 2^-53 of it.
  const mpq_class q = between(0x1p-1074, 0x1p-1073, mpq_class(1, 2) + mpq_class(1) / (mpz_class(1) << 80));
  EXPECT_EQ(round_rational<double>(q), 0x1p-1073);
  // Just below the midpoint: the two-step route lands on the midpoint itself,
  // which then ties to even (2^-1073); rounded once it goes down.
  Mpfr_value twice(53);
  const mpq_class r = between(0x1p-1074, 0x1p-1073, mpq_class(1, 2) - mpq_class(1) / (mpz_class(1) << 80));
  mpfr_set_q(twice.get(), r.get_mpq_t(), MPFR_RNDN);
  EXPECT_EQ(mpfr_get_d(twice.get(), MPFR_RNDN), 0x1p-1073) << "the two-step rounding this layer avoids";
  EXPECT_EQ(round_rational<double>(r), 0x1p-1074);
  EXPECT_EQ(round_rational<float>(mpq_class(1, 3)), 1.0f / 3.0f);
}

TEST(NumberLayer, DirectedRoundingBracketsTheExactValue) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> exponent(-1100, 1100);
  for (int i = 0; i < 5000; ++i) {
    const mpq_class q = mpq_class(static_cast<long>(rng() >> 12) + 1, static_cast<long>(rng() >> 13) + 1) *
                        (exponent(rng) >= 0 ? mpq_class(mpz_class(1) << (exponent(rng) & 1023))
                                            : mpq_class(1) / (mpz_class(1) << (-exponent(rng) & 1023)));
    const double lo = round_rational<double>(q, Rounding::downward);
    const double hi = round_rational<double>(q, Rounding::upward);
    const double near = round_rational<double>(q);
    ASSERT_LE(exact_rational(lo), q);
    if (std::isfinite(hi)) {
      ASSERT_GE(exact_rational(hi), q);
    }
    ASSERT_TRUE(near == lo || near == hi);
    ASSERT_TRUE(lo == hi || next_up(lo) == hi);
    EXPECT_EQ(lower_double(q), lo);
    EXPECT_EQ(upper_double(q), hi);
    const Mpfr_number<90> m(q);
    ASSERT_LE(exact_rational(lower_double(m)), Number_traits<Mpfr_number<90>>::to_rational(m));
    if (std::isfinite(upper_double(m))) {
      ASSERT_GE(exact_rational(upper_double(m)), Number_traits<Mpfr_number<90>>::to_rational(m));
    }
  }
}

TEST(NumberLayer, OperationBoundsEncloseTheExactResult) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-1070, 1020);
  for (int i = 0; i < 20000; ++i) {
    const double x = std::ldexp(mantissa(rng), exponent(rng)), y = std::ldexp(mantissa(rng), exponent(rng) / 2);
    const mpq_class qx = exact_rational(x), qy = exact_rational(y);
    const auto check = [&](Double_bounds b, const mpq_class& exact, const char* what) {
      if (std::isfinite(b.lo)) {
        ASSERT_LE(exact_rational(b.lo), exact) << what << std::hexfloat << x << " " << y;
      }
      if (std::isfinite(b.hi)) {
        ASSERT_GE(exact_rational(b.hi), exact) << what << std::hexfloat << x << " " << y;
      }
    };
    check(add_bounds(x, y), qx + qy, "+");
    check(mul_bounds(x, y), qx * qy, "*");
    if (y != 0) check(div_bounds(x, y), qx / qy, "/");
  }
  EXPECT_EQ(add_bounds(0.5, 0.25).lo, 0.75);  // exact results are not widened
  EXPECT_EQ(mul_bounds(3.0, 0.5).hi, 1.5);
  EXPECT_EQ(div_bounds(1.0, 4.0).lo, 0.25);
  EXPECT_LT(div_bounds(1.0, 3.0).lo, div_bounds(1.0, 3.0).hi);
}

TEST(NumberLayer, IntervalDivisionEnclosesAndRefusesZeroDivisors) {
  const Interval q = Interval(1.0) / Interval(3.0);
  EXPECT_LE(exact_rational(q.inf()), mpq_class(1, 3));
  EXPECT_GE(exact_rational(q.sup()), mpq_class(1, 3));
  EXPECT_TRUE((Interval(6.0) / Interval(3.0)).is_point());
  const Interval w = Interval(1.0, 2.0) / Interval(-4.0, -2.0);
  EXPECT_LE(w.inf(), -1.0);
  EXPECT_GE(w.sup(), -0.25);
  EXPECT_THROW(Interval(1.0) / Interval(-1.0, 1.0), Precondition_violation);
  EXPECT_EQ(min(Interval(1, 3), Interval(2, 4)), Interval(1, 3));
  EXPECT_EQ(max(Interval(1, 3), Interval(2, 4)), Interval(2, 4));
}

TEST(NumberLayer, SignsAndBoundsOfEveryNumberType) {
  EXPECT_EQ(certified_sign(0x1p-1074), Certified_sign::positive);
  EXPECT_EQ(certified_sign(-0.0), Certified_sign::zero);
  EXPECT_EQ(certified_sign(std::nan("")), Certified_sign::uncertain);
  EXPECT_EQ(certified_sign(-std::numeric_limits<float>::infinity()), Certified_sign::negative);
  EXPECT_EQ(certified_sign(Interval(-1, 1)), Certified_sign::uncertain);
  EXPECT_EQ(certified_sign(Interval(0x1p-1074, 1)), Certified_sign::positive);
  EXPECT_EQ(certified_sign(mpq_class(-1, 7)), Certified_sign::negative);
  EXPECT_EQ(certified_sign(Mpfr_number<20>(0)), Certified_sign::zero);
  EXPECT_FALSE(is_finite_number(Interval(0, std::numeric_limits<double>::infinity())));
  EXPECT_TRUE(is_interval_v<Interval>);
  EXPECT_FALSE(is_interval_v<double>);
  const long double third = 1.0L / 3;
  EXPECT_LT(lower_double(third), upper_double(third));
  EXPECT_LE(static_cast<long double>(lower_double(third)), third);
  EXPECT_GE(static_cast<long double>(upper_double(third)), third);
  EXPECT_EQ(nearest_double(Interval(1, 3)), 2.0);
  // Subnormal points stay themselves (fuzz/corpus/hull/regression_interval_subnormal_point).
  EXPECT_EQ(nearest_double(Interval(-0x1p-1074)), -0x1p-1074);
  EXPECT_EQ(nearest_double(Interval(0x1p-1074, 0x3p-1074)), 0x2p-1074);
  const double max = std::numeric_limits<double>::max();
  EXPECT_EQ(nearest_double(Interval(max / 2, max)), 0.75 * max);  // no overflow of the sum
  EXPECT_EQ(Number_traits<Mpfr_number<64>>::name(), "mpfr-64");
  EXPECT_EQ(Number_traits<float>::unit_roundoff, 0x1p-24);
}

// A subnormal's sign read under denormals-are-zero: the comparison
// instructions see 0, the bits do not.
TEST(NumberLayer, SignsDoNotDependOnTheFloatingPointEnvironment) {
  for (const auto& s : test::non_default_fp_environments()) {
    const test::Scoped_fp_environment caller(s);
    volatile double tiny = 0x1p-1074;
    EXPECT_EQ(certified_sign(static_cast<double>(tiny)), Certified_sign::positive) << s.name;
    EXPECT_EQ(certified_sign(-static_cast<double>(tiny)), Certified_sign::negative) << s.name;
    EXPECT_EQ(exact_rational(static_cast<double>(tiny)), mpq_class(1) / (mpz_class(1) << 1074)) << s.name;
  }
}

// norm_up is an upper bound of the exact norm, and the nearest double above
// it off the fast range: its squares are summed exactly whatever the
// exponents (a fixed 2200 bits rounded norm_up(2^600, 2^-1074) down to
// 2^600), in every floating-point environment.
TEST(NumberLayer, NormUpBoundsTheExactNormAtEveryScale) {
  const auto squared = [](double x, double y, double z) -> mpq_class {
    const mpq_class a = exact_rational(x), b = exact_rational(y), c = exact_rational(z);
    return a * a + b * b + c * c;
  };
  EXPECT_GT(norm_up(0x1p600, 0x1p-1074), 0x1p600);
  EXPECT_EQ(norm_up(0x1p600, 0x1p-1074), next_up(0x1p600));
  EXPECT_EQ(norm_up(0x1p-1074, 0, 0), 0x1p-1074);
  EXPECT_EQ(norm_up(3 * 0x1p700, 4 * 0x1p700), 5 * 0x1p700);  // exact: the MPFR path rounds a 5 to itself
  // Non-finite components, as std::hypot (a fuzzing finding of the exact path).
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(norm_up(inf, 1), inf);
  EXPECT_EQ(norm_up(1, -inf, nan), inf);
  EXPECT_TRUE(std::isnan(norm_up(nan, 0x1p-1074)));
  std::mt19937_64 rng(20261127);
  const auto value = [&rng] {
    const int e = static_cast<int>(rng() % 2098) - 1074;
    const double v = std::ldexp(1.0 + static_cast<double>(rng() >> 12) * 0x1p-52, std::min(e, 1020));
    return (rng() & 1) ? -v : v;
  };
  std::vector<test::Fp_environment_setting> settings = test::non_default_fp_environments();
  settings.insert(settings.begin(), {"default", false, false, FE_TONEAREST});
  for (const auto& setting : settings)
    for (int i = 0; i < 3000; ++i) {
      const double x = value(), y = value(), z = i % 3 == 0 ? 0.0 : value();
      const double n = [&] {
        const test::Scoped_fp_environment environment(setting);
        return norm_up(x, y, z);
      }();
      const mpq_class s = squared(x, y, z);
      if (!std::isfinite(n)) {  // only when the norm is beyond the largest double
        EXPECT_GT(s, squared(std::numeric_limits<double>::max(), 0, 0)) << x << " " << y << " " << z;
        continue;
      }
      const mpq_class above = exact_rational(n);
      EXPECT_GE(above * above, s) << setting.name << ": " << x << " " << y << " " << z;
      // The nearest double above off the fast range (every nonzero |v| in
      // [2^-500, 2^500]), within 2^-48 relative on it.
      const auto in_range = [](double v) { return v == 0 || (std::abs(v) >= 0x1p-500 && std::abs(v) <= 0x1p500); };
      const bool fast = in_range(x) && in_range(y) && in_range(z);
      const mpq_class below = fast ? exact_rational(n) / (1 + mpq_class(1, mpz_class(1) << 48))
                                   : exact_rational(next_down(n));
      EXPECT_LT(below * below, s) << setting.name << ": " << x << " " << y << " " << z;
    }
}

TEST(NumberLayer, MpfrNumbersAreValuesWithCompleteArithmetic) {
  Mpfr_number<60> a(1), b(3);
  Mpfr_number<60> c = a;
  c /= b;
  c *= b;
  EXPECT_TRUE(c <= a && c >= a - ldexp(Mpfr_number<60>(1), -58));
  Mpfr_number<60> d = std::move(c);
  EXPECT_FALSE(d != d);
  EXPECT_EQ(abs(-b), b);
  EXPECT_EQ(sqrt(Mpfr_number<60>(9)), b);
  Mpfr_number<60> r(mpq_class(1, 3), MPFR_RNDU);
  EXPECT_GT(Number_traits<Mpfr_number<60>>::to_rational(r), mpq_class(1, 3));
  Mpfr_value v(200, 0.5);
  Mpfr_value w = v;
  mpfr_mul_2si(w.get(), w.get(), 1, MPFR_RNDN);
  EXPECT_EQ(mpfr_get_d(v.get(), MPFR_RNDN), 0.5);
  EXPECT_EQ(mpfr_get_d(w.get(), MPFR_RNDN), 1.0);
  EXPECT_EQ(w.precision(), 200);
}

}  // namespace
}  // namespace relgeo
