// relgeo/linear/scalar_traits.h — the scalars of the linear-equation area:
// float, double, long double, relgeo::Mpfr_number<Bits> and GMP's mpq_class,
// made usable in Eigen matrices (Eigen::NumTraits) and by relgeo's exact
// error measures (exact conversion to rationals, correctly rounded
// conversion from rationals).
//
// Mpfr_number (relgeo/core/mpfr_number.h) offers +, -, *, /, unary -, ==,
// < and >; Eigen's expressions and LU decompositions also need compound
// assignment, <=, >=, abs and a few constants. They are supplied here as free
// functions in namespace relgeo (found by argument-dependent lookup), so the
// kernel header stays untouched.
#pragma once

#include <Eigen/Core>
#include <gmpxx.h>
#include <mpfr.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>

#include "relgeo/core/errors.h"
#include "relgeo/kernel/internal/semi_static_filter.h"
#include "relgeo/core/mpfr_number.h"

namespace relgeo {

// ---- what Mpfr_number lacks for Eigen ----------------------------------------

namespace internal {
/// Mutable access to the value of an Mpfr_number (it exposes only a const
/// pointer; the object itself is not const, so writing through it is defined).
template <int Bits>
mpfr_ptr mpfr_mutable(Mpfr_number<Bits>& v) {
  return const_cast<mpfr_ptr>(v.get());
}
}  // namespace internal

template <int Bits>
Mpfr_number<Bits>& operator+=(Mpfr_number<Bits>& a, const Mpfr_number<Bits>& b) {
  mpfr_add(internal::mpfr_mutable(a), a.get(), b.get(), MPFR_RNDN);
  return a;
}
template <int Bits>
Mpfr_number<Bits>& operator-=(Mpfr_number<Bits>& a, const Mpfr_number<Bits>& b) {
  mpfr_sub(internal::mpfr_mutable(a), a.get(), b.get(), MPFR_RNDN);
  return a;
}
template <int Bits>
Mpfr_number<Bits>& operator*=(Mpfr_number<Bits>& a, const Mpfr_number<Bits>& b) {
  mpfr_mul(internal::mpfr_mutable(a), a.get(), b.get(), MPFR_RNDN);
  return a;
}
template <int Bits>
Mpfr_number<Bits>& operator/=(Mpfr_number<Bits>& a, const Mpfr_number<Bits>& b) {
  mpfr_div(internal::mpfr_mutable(a), a.get(), b.get(), MPFR_RNDN);
  return a;
}
template <int Bits>
bool operator<=(const Mpfr_number<Bits>& a, const Mpfr_number<Bits>& b) {
  return mpfr_lessequal_p(a.get(), b.get());
}
template <int Bits>
bool operator>=(const Mpfr_number<Bits>& a, const Mpfr_number<Bits>& b) {
  return mpfr_greaterequal_p(a.get(), b.get());
}
/// |a| (exact).
template <int Bits>
Mpfr_number<Bits> abs(const Mpfr_number<Bits>& a) {
  Mpfr_number<Bits> r = a;
  mpfr_abs(internal::mpfr_mutable(r), a.get(), MPFR_RNDN);
  return r;
}
/// Square root, correctly rounded.
template <int Bits>
Mpfr_number<Bits> sqrt(const Mpfr_number<Bits>& a) {
  Mpfr_number<Bits> r;
  mpfr_sqrt(internal::mpfr_mutable(r), a.get(), MPFR_RNDN);
  return r;
}

// ---- scalar traits --------------------------------------------------------------

template <class S>
struct Is_mpfr_number : std::false_type {};
template <int Bits>
struct Is_mpfr_number<Mpfr_number<Bits>> : std::true_type {};

/// The scalars the linear area supports.
template <class S>
concept Linear_scalar = std::is_floating_point_v<S> || Is_mpfr_number<S>::value ||
                        std::is_same_v<S, mpq_class>;

/// What the linear area needs to know about a scalar S:
///  * `name()`            "float", "double", "long-double", "mpfr-BITS", "rational";
///  * `is_exact`          arithmetic without rounding (mpq_class);
///  * `is_dyadic`         every value is m * 2^e (all but mpq_class);
///  * `unit_roundoff`     u = 2^-p (0 when exact);
///  * `from_rational(q)`  q correctly rounded to S (to nearest, ties to even);
///  * `to_rational(s)`    the exact value of s (throws Non_finite_input for NaN/inf);
///  * `to_double(s)`      s rounded to the nearest double;
///  * `is_finite(s)`, `is_zero(s)`, `magnitude(s)` (|s| rounded to double).
template <class S>
struct Scalar_traits;

namespace internal {

/// Exact rational value of a finite binary floating-point number.
template <class T>
mpq_class rational_from_float(T v) {
  if (!std::isfinite(v)) throw Non_finite_input("scalar is NaN or infinite");
  if (v == 0) return mpq_class(0);
  int e = 0;
  T m = std::frexp(v, &e);  // v = m * 2^e, 0.5 <= |m| < 1
  constexpr int p = std::numeric_limits<T>::digits;
  m = std::ldexp(m, p);  // integer, |m| < 2^p
  e -= p;
  const bool neg = m < 0;
  if (neg) m = -m;
  // m < 2^64 for every IEEE type up to x87 extended: load it in two halves.
  const T high = std::floor(std::ldexp(m, -32));
  const auto hi = static_cast<std::uint64_t>(high);
  const auto lo = static_cast<std::uint64_t>(m - std::ldexp(high, 32));
  mpz_class z(static_cast<unsigned long>(hi));
  z <<= 32;
  z += static_cast<unsigned long>(lo);
  if (neg) z = -z;
  mpq_class q(z);
  if (e > 0) mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  else if (e < 0) mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  return q;
}

/// A rational correctly rounded to a binary floating-point type (through MPFR,
/// with the type's precision and exponent range, subnormals included). It
/// sets MPFR's exponent range for the conversion and restores it (MPFR keeps
/// that range per thread when built thread-safe, as Debian's is).
template <class T>
T float_from_rational(const mpq_class& q) {
  constexpr int p = std::numeric_limits<T>::digits;
  constexpr int emin_t = std::numeric_limits<T>::min_exponent - p + 1;
  constexpr int emax_t = std::numeric_limits<T>::max_exponent;
  mpfr_t v;
  mpfr_init2(v, p);
  const mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
  mpfr_set_emin(emin_t), mpfr_set_emax(emax_t);
  int t = mpfr_set_q(v, q.get_mpq_t(), MPFR_RNDN);
  t = mpfr_check_range(v, t, MPFR_RNDN);
  mpfr_subnormalize(v, t, MPFR_RNDN);
  mpfr_set_emin(emin), mpfr_set_emax(emax);
  T r;
  if constexpr (std::is_same_v<T, float>) r = mpfr_get_flt(v, MPFR_RNDN);
  else if constexpr (std::is_same_v<T, double>) r = mpfr_get_d(v, MPFR_RNDN);
  else r = mpfr_get_ld(v, MPFR_RNDN);
  mpfr_clear(v);
  return r;
}

}  // namespace internal

template <class T>
  requires std::is_floating_point_v<T>
struct Scalar_traits<T> {
  static std::string name() {
    if constexpr (std::is_same_v<T, float>) return "float";
    else if constexpr (std::is_same_v<T, double>) return "double";
    else return "long-double";
  }
  static constexpr bool is_exact = false;
  static constexpr bool is_dyadic = true;
  static constexpr int precision = std::numeric_limits<T>::digits;
  static constexpr double unit_roundoff = static_cast<double>(std::numeric_limits<T>::epsilon()) / 2;
  static T from_rational(const mpq_class& q) { return internal::float_from_rational<T>(q); }
  static T from_double(double d) { return static_cast<T>(d); }
  static mpq_class to_rational(T v) { return internal::rational_from_float(v); }
  static double to_double(T v) { return static_cast<double>(v); }
  static bool is_finite(T v) { return std::isfinite(v); }
  static bool is_zero(T v) { return v == 0; }
  static double magnitude(T v) { return std::abs(static_cast<double>(v)); }
};

template <int Bits>
struct Scalar_traits<Mpfr_number<Bits>> {
  using S = Mpfr_number<Bits>;
  static std::string name() { return "mpfr-" + std::to_string(Bits); }
  static constexpr bool is_exact = false;
  static constexpr bool is_dyadic = true;
  static constexpr int precision = Bits;
  static constexpr double unit_roundoff = internal::power_of_two<double>(-Bits);
  static S from_rational(const mpq_class& q) {
    S r;
    mpfr_set_q(internal::mpfr_mutable(r), q.get_mpq_t(), MPFR_RNDN);
    return r;
  }
  static S from_double(double d) { return S(d); }
  static mpq_class to_rational(const S& v) {
    if (!mpfr_number_p(v.get())) throw Non_finite_input("scalar is NaN or infinite");
    mpq_class q;
    mpfr_get_q(q.get_mpq_t(), v.get());
    return q;
  }
  static double to_double(const S& v) { return mpfr_get_d(v.get(), MPFR_RNDN); }
  static bool is_finite(const S& v) { return mpfr_number_p(v.get()) != 0; }
  static bool is_zero(const S& v) { return mpfr_zero_p(v.get()) != 0; }
  static double magnitude(const S& v) { return std::abs(mpfr_get_d(v.get(), MPFR_RNDN)); }
};

template <>
struct Scalar_traits<mpq_class> {
  static std::string name() { return "rational"; }
  static constexpr bool is_exact = true;
  static constexpr bool is_dyadic = false;
  static constexpr int precision = 0;  ///< unbounded
  static constexpr double unit_roundoff = 0;
  static mpq_class from_rational(const mpq_class& q) { return q; }
  static mpq_class from_double(double d) { return internal::rational_from_float(d); }
  static const mpq_class& to_rational(const mpq_class& v) { return v; }
  static double to_double(const mpq_class& v) { return internal::float_from_rational<double>(v); }
  static bool is_finite(const mpq_class&) { return true; }
  static bool is_zero(const mpq_class& v) { return sgn(v) == 0; }
  static double magnitude(const mpq_class& v) { return std::abs(to_double(v)); }
};

}  // namespace relgeo

// ---- Eigen::NumTraits ----------------------------------------------------------

namespace Eigen {

/// Mpfr_number<Bits> in Eigen matrices (LU decompositions, products...).
template <int Bits>
struct NumTraits<relgeo::Mpfr_number<Bits>> : GenericNumTraits<relgeo::Mpfr_number<Bits>> {
  using S = relgeo::Mpfr_number<Bits>;
  using Real = S;
  using NonInteger = S;
  using Nested = S;
  using Literal = S;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = HugeCost,
    AddCost = HugeCost,
    MulCost = HugeCost
  };
  static inline int digits10() { return static_cast<int>(Bits * 0.30102999566398120); }
  static inline int digits() { return Bits; }
  static inline S epsilon() {
    S e(1);
    mpfr_mul_2si(relgeo::internal::mpfr_mutable(e), e.get(), 1 - Bits, MPFR_RNDN);
    return e;
  }
  static inline S dummy_precision() {
    S e = epsilon();
    mpfr_mul_2si(relgeo::internal::mpfr_mutable(e), e.get(), Bits / 8, MPFR_RNDN);
    return e;
  }
  static inline S highest() {
    S h;
    mpfr_set_inf(relgeo::internal::mpfr_mutable(h), 1);
    mpfr_nextbelow(relgeo::internal::mpfr_mutable(h));
    return h;
  }
  static inline S lowest() { return -highest(); }
  static inline S infinity() {
    S h;
    mpfr_set_inf(relgeo::internal::mpfr_mutable(h), 1);
    return h;
  }
  static inline S quiet_NaN() {
    S h;
    mpfr_set_nan(relgeo::internal::mpfr_mutable(h));
    return h;
  }
};

/// GMP rationals in Eigen matrices (exact: epsilon() == 0). Beware of gmpxx
/// expression templates: never store `a * b` in `auto` (STYLE: Eigen's
/// TopicPitfalls applies to gmpxx too).
template <>
struct NumTraits<mpq_class> : GenericNumTraits<mpq_class> {
  using Real = mpq_class;
  using NonInteger = mpq_class;
  using Nested = mpq_class;
  using Literal = mpq_class;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = HugeCost,
    AddCost = HugeCost,
    MulCost = HugeCost
  };
  static inline mpq_class epsilon() { return mpq_class(0); }
  static inline mpq_class dummy_precision() { return mpq_class(0); }
  static inline int digits10() { return 0; }
  static inline mpq_class highest() = delete;
  static inline mpq_class lowest() = delete;
};

}  // namespace Eigen
