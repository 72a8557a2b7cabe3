// relgeo/core/number_traits.h — what the library knows about a number type,
// in one place: the number layer every area asks instead of testing a type
// for `inf()` or `get_d()`.
//
// Number_traits<T> is specialised for the number types of relgeo's kernels
// and scalars — float, double, long double, relgeo::Interval,
// relgeo::Mpfr_number<Bits>, GMP's mpq_class — and has a generic fallback for
// any other ordered field with an ADL `to_double` (CGAL's Gmpq, Lazy_exact_nt
// ...). Every specialisation answers:
//
//  | member                  | meaning                                                        |
//  |-------------------------|----------------------------------------------------------------|
//  | kind                    | floating_point, interval, mpfr, rational, other                 |
//  | is_interval             | values are enclosures (signs may be uncertain)                  |
//  | is_exact                | arithmetic without rounding (mpq_class)                         |
//  | is_dyadic               | every value is m 2^e (binary floating point, MPFR)              |
//  | precision               | significand bits (0: unbounded or not applicable)               |
//  | unit_roundoff           | u = 2^-precision as a double (0 when exact)                     |
//  | name()                  | "double", "interval", "mpfr-64", "rational" ...                |
//  | is_finite(x)            | no NaN or infinity (for intervals: in either endpoint)          |
//  | sign(x)                 | Certified_sign: exact for point types, uncertain for an        |
//  |                         | interval containing 0 or for NaN                                |
//  | lower(x), upper(x)      | doubles with lower(x) <= value <= upper(x) (directed rounding)  |
//  | to_double(x)            | nearest double (an interval's midpoint)                         |
//  | from_double(d)          | d in T (rounded to nearest where T is narrower)                 |
//  | from_rational(q, r)     | q rounded once in direction r (intervals: the enclosure)        |
//  | to_rational(x)          | the exact value (not for intervals); throws Non_finite_input    |
//
// The free functions below (certified_sign, lower_double, upper_double,
// nearest_double, is_finite_number, is_interval_v) are the spelling the
// algorithms use.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <cmath>
#include <concepts>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/dyadic.h"
#include "relgeo/core/errors.h"
#include "relgeo/core/interval.h"
#include "relgeo/core/mpfr_number.h"
#include "relgeo/core/rounding.h"

namespace relgeo {

enum class Number_kind { floating_point, interval, mpfr, rational, other };

namespace internal {
// Unqualified calls, found by argument-dependent lookup (CGAL::to_double and
// CGAL::to_interval for CGAL's number types).
template <class T>
double to_double_by_adl(const T& x) {
  return static_cast<double>(to_double(x));
}
template <class T>
concept Has_adl_interval = requires(const T& x) {
  { to_interval(x).first } -> std::convertible_to<double>;
};
}  // namespace internal

/// The number layer's facts about T (see the file comment); the primary
/// template is the generic fallback for other exact ordered fields. Their
/// bounds come from an ADL `to_interval` (CGAL's, certified) when there is
/// one; otherwise from one ulp around `to_double`.
template <class T, class Enable = void>
struct Number_traits {
  static constexpr Number_kind kind = Number_kind::other;
  static constexpr bool is_interval = false;
  static constexpr bool is_exact = true;
  static constexpr bool is_dyadic = false;
  static constexpr int precision = 0;
  static constexpr double unit_roundoff = 0;
  static std::string name() { return "other"; }
  static bool is_finite(const T&) { return true; }
  static Certified_sign sign(const T& x) {
    if (x > T(0)) return Certified_sign::positive;
    return x < T(0) ? Certified_sign::negative : Certified_sign::zero;
  }
  static double to_double(const T& x) { return internal::to_double_by_adl(x); }
  static double lower(const T& x) {
    if constexpr (internal::Has_adl_interval<T>) return to_interval(x).first;
    else return next_down(internal::to_double_by_adl(x));
  }
  static double upper(const T& x) {
    if constexpr (internal::Has_adl_interval<T>) return to_interval(x).second;
    else return next_up(internal::to_double_by_adl(x));
  }
  static T from_double(double d) { return T(d); }
};

/// float, double, long double.
template <class T>
struct Number_traits<T, std::enable_if_t<std::is_floating_point_v<T>>> {
  static constexpr Number_kind kind = Number_kind::floating_point;
  static constexpr bool is_interval = false;
  static constexpr bool is_exact = false;
  static constexpr bool is_dyadic = true;
  static constexpr int precision = std::numeric_limits<T>::digits;
  static constexpr double unit_roundoff = static_cast<double>(std::numeric_limits<T>::epsilon()) / 2;
  static std::string name() {
    if constexpr (std::is_same_v<T, float>) return "float";
    else if constexpr (std::is_same_v<T, double>) return "double";
    else return "long-double";
  }
  static bool is_finite(T x) { return std::isfinite(x); }
  /// The exact sign; NaN is uncertain. Decided on the bits (no comparison
  /// instruction, which reads a subnormal as 0 under denormals-are-zero).
  static Certified_sign sign(T x) {
    if (std::isnan(x)) return Certified_sign::uncertain;
    if (std::isinf(x)) return std::signbit(x) ? Certified_sign::negative : Certified_sign::positive;
    if constexpr (std::is_same_v<T, double> || std::is_same_v<T, float> ||
                  std::numeric_limits<T>::digits == 64) {
      const internal::Wide_binary_parts p = internal::wide_binary_parts(x);
      if (p.magnitude == 0) return Certified_sign::zero;
      return p.negative ? Certified_sign::negative : Certified_sign::positive;
    } else {
      return sign_of(x);
    }
  }
  static double to_double(T x) { return static_cast<double>(x); }
  static double lower(T x) {
    if constexpr (sizeof(T) <= sizeof(double)) return static_cast<double>(x);
    else {
      const double d = static_cast<double>(x);
      return static_cast<T>(d) > x ? next_down(d) : d;
    }
  }
  static double upper(T x) {
    if constexpr (sizeof(T) <= sizeof(double)) return static_cast<double>(x);
    else {
      const double d = static_cast<double>(x);
      return static_cast<T>(d) < x ? next_up(d) : d;
    }
  }
  static T from_double(double d) { return static_cast<T>(d); }
  static T from_rational(const mpq_class& q, Rounding r = Rounding::to_nearest) { return round_rational<T>(q, r); }
  static mpq_class to_rational(T x) { return exact_rational(x); }
};

/// relgeo::Interval: enclosures.
template <>
struct Number_traits<Interval> {
  static constexpr Number_kind kind = Number_kind::interval;
  static constexpr bool is_interval = true;
  static constexpr bool is_exact = false;
  static constexpr bool is_dyadic = true;
  static constexpr int precision = 53;
  static constexpr double unit_roundoff = 0x1p-53;
  static std::string name() { return "interval"; }
  static bool is_finite(const Interval& x) { return std::isfinite(x.inf()) && std::isfinite(x.sup()); }
  static Certified_sign sign(const Interval& x) { return x.sign(); }
  /// The midpoint, rounded once where the sum does not overflow: halving the
  /// bounds first rounds subnormals away (a point interval at 2^-1074 gave 0;
  /// found by fuzz/hull).
  static double to_double(const Interval& x) {
    if (x.inf() == x.sup()) return x.inf();
    const double sum = x.inf() + x.sup();
    return std::isfinite(sum) ? 0.5 * sum : 0.5 * x.inf() + 0.5 * x.sup();
  }
  static double lower(const Interval& x) { return x.inf(); }
  static double upper(const Interval& x) { return x.sup(); }
  static Interval from_double(double d) { return Interval(d); }
  /// The tightest double enclosure of q (a point when q is a double); the
  /// direction is ignored: an interval always encloses.
  static Interval from_rational(const mpq_class& q, Rounding = Rounding::to_nearest) {
    const double lo = round_rational<double>(q, Rounding::downward);
    const double hi = round_rational<double>(q, Rounding::upward);
    return Interval(lo, hi);
  }
};

namespace internal {
/// 2^-n for 0 <= n <= 1074, at compile time (std::ldexp is constexpr in GCC
/// only): halving is exact down to the smallest subnormal.
constexpr double negative_power_of_two(int n) {
  double x = 1.0;
  for (int i = 0; i < n; ++i) x *= 0.5;
  return x;
}
}  // namespace internal

/// relgeo::Mpfr_number<Bits>.
template <int Bits>
struct Number_traits<Mpfr_number<Bits>> {
  using T = Mpfr_number<Bits>;
  static constexpr Number_kind kind = Number_kind::mpfr;
  static constexpr bool is_interval = false;
  static constexpr bool is_exact = false;
  static constexpr bool is_dyadic = true;
  static constexpr int precision = Bits;
  static constexpr double unit_roundoff = Bits <= 1074 ? internal::negative_power_of_two(Bits) : 0x1p-1074;
  static std::string name() { return "mpfr-" + std::to_string(Bits); }
  static bool is_finite(const T& x) { return x.is_finite(); }
  static Certified_sign sign(const T& x) {
    if (x.is_nan()) return Certified_sign::uncertain;
    return static_cast<Certified_sign>((x.sign() > 0) - (x.sign() < 0));
  }
  static double to_double(const T& x) { return round_mpfr<double>(x.get(), Rounding::to_nearest); }
  static double lower(const T& x) { return round_mpfr<double>(x.get(), Rounding::downward); }
  static double upper(const T& x) { return round_mpfr<double>(x.get(), Rounding::upward); }
  static T from_double(double d) { return T(d); }
  static T from_rational(const mpq_class& q, Rounding r = Rounding::to_nearest) { return T(q, to_mpfr_rounding(r)); }
  static mpq_class to_rational(const T& x) {
    if (!x.is_finite()) throw Non_finite_input("exact value of a NaN or infinite number");
    mpq_class q;
    mpfr_get_q(q.get_mpq_t(), x.get());
    return q;
  }
};

/// GMP rationals: exact.
template <>
struct Number_traits<mpq_class> {
  static constexpr Number_kind kind = Number_kind::rational;
  static constexpr bool is_interval = false;
  static constexpr bool is_exact = true;
  static constexpr bool is_dyadic = false;
  static constexpr int precision = 0;
  static constexpr double unit_roundoff = 0;
  static std::string name() { return "rational"; }
  static bool is_finite(const mpq_class&) { return true; }
  static Certified_sign sign(const mpq_class& x) { return static_cast<Certified_sign>(sgn(x)); }
  static double to_double(const mpq_class& x) { return round_rational<double>(x, Rounding::to_nearest); }
  static double lower(const mpq_class& x) { return round_rational<double>(x, Rounding::downward); }
  static double upper(const mpq_class& x) { return round_rational<double>(x, Rounding::upward); }
  static mpq_class from_double(double d) { return exact_rational(d); }
  static mpq_class from_rational(const mpq_class& q, Rounding = Rounding::to_nearest) { return q; }
  static const mpq_class& to_rational(const mpq_class& x) { return x; }
};

/// Whether T's values are enclosures (relgeo::Interval).
template <class T>
inline constexpr bool is_interval_v = Number_traits<T>::is_interval;

/// The certified sign of a number: exact for point types, `uncertain` for an
/// interval containing 0 and for NaN.
template <class T>
Certified_sign certified_sign(const T& x) {
  return Number_traits<T>::sign(x);
}
/// A double <= x (the largest the layer can certify).
template <class T>
double lower_double(const T& x) {
  return Number_traits<T>::lower(x);
}
/// A double >= x.
template <class T>
double upper_double(const T& x) {
  return Number_traits<T>::upper(x);
}
/// The nearest double (an interval's midpoint).
template <class T>
double nearest_double(const T& x) {
  return Number_traits<T>::to_double(x);
}
/// No NaN or infinity.
template <class T>
bool is_finite_number(const T& x) {
  return Number_traits<T>::is_finite(x);
}

}  // namespace relgeo
