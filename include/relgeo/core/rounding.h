// relgeo/core/rounding.h — directed rounding: one place for every "round this
// up (down) to a double" of the library.
//
// Three tools, from cheap to exact:
//  * next_up / next_down: the neighbouring double (an outer bound of any
//    value a round-to-nearest operation was one rounding away from);
//  * add_bounds, mul_bounds, add_up, mul_up, ...: one operation rounded to
//    nearest and moved outward only where its exact error (TwoSum,
//    TwoProduct) says it must be (Interval's arithmetic is built on them);
//  * round_rational / round_mpfr: a GMP rational or an MPFR value rounded
//    *once* to float, double or long double in a chosen direction, with the
//    target's precision and exponent range (subnormals included), through
//    MPFR. Rounding to nearest in two steps (to 53 bits, then to a subnormal)
//    can differ from rounding once; these never do.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <type_traits>

#include "relgeo/core/floating_point.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/internal/error_free.h"
#include "relgeo/core/mpfr_number.h"

namespace relgeo {

/// A rounding direction (IEEE's round to nearest, ties to even; toward -inf;
/// toward +inf).
enum class Rounding { to_nearest, downward, upward };

constexpr mpfr_rnd_t to_mpfr_rounding(Rounding r) noexcept {
  switch (r) {
    case Rounding::downward: return MPFR_RNDD;
    case Rounding::upward: return MPFR_RNDU;
    default: return MPFR_RNDN;
  }
}

/// The next double toward +inf (-inf): +inf (-inf) stays, NaN stays NaN.
inline double next_up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }
inline double next_down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }

/// A finite x moved up (down) by at least one ulp and at most two, without a
/// libm call: Rump, Zimmermann, Boldo, Melquiond, "Computing predecessor and
/// successor in rounding to nearest", BIT 49 (2009): fl(x + fl(phi |x| + eta))
/// >= succ(x) with phi = u (1 + 2u), eta = 2^-1074. Round to nearest only.
inline double step_up(double x) { return x + (0x1p-53 * (1 + 0x1p-52) * std::abs(x) + 0x1p-1074); }
inline double step_down(double x) { return x - (0x1p-53 * (1 + 0x1p-52) * std::abs(x) + 0x1p-1074); }

/// Lower and upper bounds of an operation on doubles, tight: the rounded
/// result itself on the side where it is exact or already outward (the exact
/// rounding error from TwoSum / TwoProduct), one step outward on the other.
/// Infinite results are kept (an overflow to +inf is an upper bound; its
/// lower bound is the largest finite double). Round to nearest without
/// FTZ/DAZ (callers hold a Default_fp_environment, core/fp_environment.h).
/// add_bounds and mul_bounds are always inlined: Interval's operations call
/// them twice each, and where GCC 12 left them out of line the elephant's
/// union against its moved copy took 0.1-0.3 ms longer (the intervals that
/// approximate its new points).
struct Double_bounds {
  double lo, hi;
};
[[gnu::always_inline]] inline Double_bounds add_bounds(double x, double y) {
  const auto [s, error] = internal::two_sum(x, y);
  if (!std::isfinite(s)) [[unlikely]] return {next_down(s), next_up(s)};
  return {error >= 0 ? s : step_down(s), error <= 0 ? s : step_up(s)};
}
[[gnu::always_inline]] inline Double_bounds mul_bounds(double x, double y) {
  const double p = x * y;
  if (x == 0 || y == 0) return {p, p};  // exact, also against infinities (then NaN)
  if (!std::isfinite(p) || std::abs(p) < 0x1p-960) [[unlikely]]  // no exact error there
    return {next_down(p), next_up(p)};
  const double e = internal::two_product_error(x, y, p);
  if (!std::isfinite(e)) [[unlikely]] return {step_down(p), step_up(p)};
  return {e >= 0 ? p : step_down(p), e <= 0 ? p : step_up(p)};
}
/// x / y (y != 0): exact quotients stay exact (fma check), others one step outward.
inline Double_bounds div_bounds(double x, double y) {
  const double d = x / y;
  // fma(d, y, -x) == 0 proves d y = x when nothing underflows.
  if (std::isfinite(d) && std::abs(x) >= 0x1p-900 && std::abs(d) >= 0x1p-900 && std::fma(d, y, -x) == 0)
    return {d, d};
  return {next_down(d), next_up(d)};
}
inline double add_up(double a, double b) { return add_bounds(a, b).hi; }
inline double add_down(double a, double b) { return add_bounds(a, b).lo; }
inline double sub_up(double a, double b) { return add_bounds(a, -b).hi; }
inline double sub_down(double a, double b) { return add_bounds(a, -b).lo; }
inline double mul_up(double a, double b) { return mul_bounds(a, b).hi; }
inline double mul_down(double a, double b) { return mul_bounds(a, b).lo; }
inline double div_up(double a, double b) { return div_bounds(a, b).hi; }
inline double div_down(double a, double b) { return div_bounds(a, b).lo; }
/// Bounds of sqrt(a), a >= 0 (the lower one never below 0).
inline double sqrt_up(double a) { return a <= 0 ? 0.0 : next_up(std::sqrt(a)); }
inline double sqrt_down(double a) { return a <= 0 ? 0.0 : std::max(0.0, next_down(std::sqrt(a))); }

namespace internal {

/// Runs f(mpfr_ptr result) with MPFR's exponent range set to T's (so that
/// overflow and subnormals happen where they happen in T), then rounds the
/// result once to T in direction `r`. Restores the thread's exponent range.
template <class T, class Set>
T round_once_to(Set set, Rounding r) {
  static_assert(std::is_floating_point_v<T>);
  constexpr int p = std::numeric_limits<T>::digits;
  constexpr long emin = std::numeric_limits<T>::min_exponent - p + 1;  // MPFR's exponent convention
  constexpr long emax = std::numeric_limits<T>::max_exponent;
  const mpfr_rnd_t rnd = to_mpfr_rounding(r);
  Mpfr_value v(p);
  const mpfr_exp_t saved_emin = mpfr_get_emin(), saved_emax = mpfr_get_emax();
  mpfr_set_emin(emin), mpfr_set_emax(emax);
  int t = set(v.get(), rnd);
  t = mpfr_check_range(v.get(), t, rnd);
  mpfr_subnormalize(v.get(), t, rnd);
  mpfr_set_emin(saved_emin), mpfr_set_emax(saved_emax);
  if constexpr (std::is_same_v<T, float>) return mpfr_get_flt(v.get(), rnd);
  else if constexpr (std::is_same_v<T, double>) return mpfr_get_d(v.get(), rnd);
  else return mpfr_get_ld(v.get(), rnd);
}

}  // namespace internal

/// q rounded once to T (float, double, long double) in direction r,
/// subnormals included; +-inf beyond T's range (or its largest finite value,
/// toward zero).
template <class T = double>
T round_rational(const mpq_class& q, Rounding r = Rounding::to_nearest) {
  return internal::round_once_to<T>([&](mpfr_ptr v, mpfr_rnd_t rnd) { return mpfr_set_q(v, q.get_mpq_t(), rnd); },
                                    r);
}

/// An MPFR value rounded once to T in direction r, subnormals included.
template <class T = double>
T round_mpfr(mpfr_srcptr x, Rounding r = Rounding::to_nearest) {
  return internal::round_once_to<T>([&](mpfr_ptr v, mpfr_rnd_t rnd) { return mpfr_set(v, x, rnd); }, r);
}

/// sqrt(q) of a rational q >= 0 rounded to a double in direction r (downward
/// or upward; to nearest: within one ulp). The square root is taken at
/// `bits` bits in the same direction, then rounded once more to double in
/// that direction, so a directed result is a true bound.
inline double sqrt_rational(const mpq_class& q, Rounding r, mpfr_prec_t bits = 128) {
  Mpfr_value v(bits);
  const mpfr_rnd_t rnd = to_mpfr_rounding(r);
  mpfr_set_q(v.get(), q.get_mpq_t(), rnd);
  mpfr_sqrt(v.get(), v.get(), rnd);
  return round_mpfr<double>(v.get(), r);
}

namespace internal {

/// The bits that hold a + b exactly, for exact MPFR values a and b: from
/// one above the higher leading bit (a carry) down to the lower last set bit
/// (mpfr_min_prec: the bits x needs). A zero adds nothing.
inline mpfr_prec_t exact_sum_bits(mpfr_srcptr a, mpfr_srcptr b) {
  if (mpfr_zero_p(a)) return std::max<mpfr_prec_t>(mpfr_min_prec(b), MPFR_PREC_MIN);
  if (mpfr_zero_p(b)) return std::max<mpfr_prec_t>(mpfr_min_prec(a), MPFR_PREC_MIN);
  const long top = std::max<long>(mpfr_get_exp(a), mpfr_get_exp(b)) + 1;
  const long low = std::min<long>(mpfr_get_exp(a) - mpfr_min_prec(a), mpfr_get_exp(b) - mpfr_min_prec(b));
  return static_cast<mpfr_prec_t>(top - low);
}

/// a + b, exactly.
inline Mpfr_value exact_sum(mpfr_srcptr a, mpfr_srcptr b) {
  Mpfr_value s(exact_sum_bits(a, b));
  mpfr_add(s.get(), a, b, MPFR_RNDN);  // exact at that precision
  return s;
}

/// x^2, exactly (twice the bits x needs).
inline Mpfr_value exact_square(mpfr_srcptr x) {
  Mpfr_value s(std::max<mpfr_prec_t>(2 * mpfr_min_prec(x), MPFR_PREC_MIN));
  mpfr_sqr(s.get(), x, MPFR_RNDN);
  return s;
}

/// A double as an MPFR value, exactly. \pre finite.
inline Mpfr_value exact_mpfr(double v) { return Mpfr_value(std::numeric_limits<double>::digits, v); }

/// The sum of the squares of the differences a_i - b_i of doubles, exactly:
/// every precision sized from the exponents of the values, however far apart
/// (a fixed precision is not enough: (2^500 + 2^-1074)^2 spans 3148 bits).
/// \pre finite values; the caller holds a Default_fp_environment (MPFR reads
/// doubles with floating-point instructions).
inline Mpfr_value exact_sum_of_squared_differences(std::span<const std::array<double, 2>> pairs) {
  Mpfr_value sum(MPFR_PREC_MIN);
  mpfr_set_zero(sum.get(), 1);
  for (const auto& [a, b] : pairs) {
    const Mpfr_value x = exact_mpfr(a), y = exact_mpfr(b);
    Mpfr_value difference(exact_sum_bits(x.get(), y.get()));
    mpfr_sub(difference.get(), x.get(), y.get(), MPFR_RNDN);
    sum = exact_sum(sum.get(), exact_square(difference.get()).get());
  }
  return sum;
}

}  // namespace internal

/// sqrt(x^2 + y^2 + z^2) rounded upward, in every floating-point
/// environment. In double with a relative margin of 2^-50 when every nonzero
/// |component| lies in [2^-500, 2^500] (at most 4 roundings, relative error
/// < 2.5 u, no underflow or overflow); otherwise from the exact sum of
/// squares in MPFR (internal::exact_sum_of_squared_differences). As
/// std::hypot: +inf when a component is infinite, else NaN when one is NaN.
inline double norm_up(double x, double y, double z = 0) {
  if (!all_finite(x, y, z)) [[unlikely]] {
    if (std::isinf(x) || std::isinf(y) || std::isinf(z)) return std::numeric_limits<double>::infinity();
    return std::numeric_limits<double>::quiet_NaN();
  }
  return internal::in_default_fp_environment([&] {
    const auto in_range = [](double v) { return v == 0 || (std::abs(v) >= 0x1p-500 && std::abs(v) <= 0x1p500); };
    if (in_range(x) && in_range(y) && in_range(z)) return std::sqrt(x * x + y * y + z * z) * (1 + 0x1p-50);
    const std::array<std::array<double, 2>, 3> components{{{x, 0.0}, {y, 0.0}, {z, 0.0}}};
    const Mpfr_value s = internal::exact_sum_of_squared_differences(components);
    Mpfr_value root(std::max<mpfr_prec_t>(s.precision(), 64));  // not fewer bits than the double it becomes
    mpfr_sqrt(root.get(), s.get(), MPFR_RNDU);
    return round_mpfr<double>(root.get(), Rounding::upward);
  });
}

}  // namespace relgeo
