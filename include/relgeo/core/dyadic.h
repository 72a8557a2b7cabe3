// relgeo/core/dyadic.h — binary floating-point values as the dyadic
// rationals m * 2^e they are: read from their bits, converted exactly to GMP
// rationals, and rationals recognised as dyadic.
//
// Reading the bits, not computing with the value (frexp, ldexp, a GMP or
// MPFR conversion, a comparison), gives the same answer in every
// floating-point environment: under denormals-are-zero every arithmetic
// instruction, conversions and comparisons included, reads a subnormal as 0.
#pragma once

#include <gmp.h>
#include <gmpxx.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
#include <type_traits>

#include "relgeo/core/errors.h"
#include "relgeo/core/floating_point.h"

namespace relgeo {

namespace internal {

/// v = mantissa * 2^exponent exactly, |mantissa| < 2^53.
struct Binary_parts {
  std::int64_t mantissa;
  int exponent;
};

/// The parts of a finite double (0 for +-0). \pre v is finite.
inline Binary_parts binary_parts(double v) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
  const int biased = static_cast<int>((bits >> 52) & 0x7FF);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  // Subnormals have no hidden bit and the exponent of the smallest normals.
  const std::uint64_t magnitude = biased == 0 ? fraction : fraction | (std::uint64_t{1} << 52);
  const int exponent = (biased == 0 ? 1 : biased) - 1075;
  const auto m = static_cast<std::int64_t>(magnitude);
  return {(bits >> 63) ? -m : m, exponent};
}

/// z = m, for any width of long (mpz_set_si takes a long; where long holds
/// m it is used: 4 ns against 29 for mpz_import, which the exact stages call
/// for each of their inputs).
inline void set_mpz(mpz_ptr z, std::int64_t m) {
  if constexpr (sizeof(long) >= sizeof(std::int64_t)) {
    mpz_set_si(z, static_cast<long>(m));
    return;
  }
  const std::uint64_t magnitude = m < 0 ? 0 - static_cast<std::uint64_t>(m) : static_cast<std::uint64_t>(m);
  mpz_import(z, 1, 1, sizeof magnitude, 0, 0, &magnitude);
  if (m < 0) mpz_neg(z, z);
}

/// The unsigned significand, its sign and power of two of a finite IEEE value
/// (float, double, x87 long double from their bits; other long doubles
/// through frexp).
struct Wide_binary_parts {
  std::uint64_t magnitude;
  bool negative;
  long exponent;
};
template <class T>
Wide_binary_parts wide_binary_parts(T v) {
  if constexpr (std::is_same_v<T, double>) {
    const Binary_parts p = binary_parts(v);
    return {static_cast<std::uint64_t>(std::abs(p.mantissa)), p.mantissa < 0 || std::signbit(v), p.exponent};
  } else if constexpr (std::is_same_v<T, float>) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
    const int biased = static_cast<int>((bits >> 23) & 0xFF);
    const std::uint32_t fraction = bits & ((std::uint32_t{1} << 23) - 1);
    const std::uint32_t magnitude = biased == 0 ? fraction : fraction | (std::uint32_t{1} << 23);
    return {magnitude, (bits >> 31) != 0, (biased == 0 ? 1 : biased) - 150};
  } else if constexpr (std::numeric_limits<T>::digits == 64) {
    const X87_parts p = x87_parts(v);  // explicit integer bit; exponent 0: denormal
    return {p.significand, p.sign, static_cast<long>(p.exponent == 0 ? 1 : p.exponent) - 16383 - 63};
  } else {
    static_assert(std::numeric_limits<T>::digits <= 64, "significands of up to 64 bits");
    int e = 0;
    const T m = std::frexp(std::abs(v), &e);  // |v| = m 2^e, 0.5 <= m < 1
    constexpr int p = std::numeric_limits<T>::digits;
    return {static_cast<std::uint64_t>(std::ldexp(m, p)), std::signbit(v), static_cast<long>(e) - p};
  }
}

}  // namespace internal

/// \brief A dyadic rational mantissa * 2^exponent, the form of every binary
/// floating-point and MPFR value. Normalised (odd mantissa, or 0 with
/// exponent 0) when built by the functions below.
struct Dyadic {
  mpz_class mantissa;
  long exponent = 0;
};

/// The exact value of a finite float, double or long double as a Dyadic.
/// \throws Non_finite_input for NaN and infinities.
template <class T>
  requires std::is_floating_point_v<T>
Dyadic dyadic_of(T v) {
  if (!std::isfinite(v)) throw Non_finite_input("exact value of a NaN or infinite number");
  const internal::Wide_binary_parts p = internal::wide_binary_parts(v);
  Dyadic d;
  if (p.magnitude == 0) return d;
  const int zeros = std::countr_zero(p.magnitude);
  const std::uint64_t odd = p.magnitude >> zeros;
  mpz_import(d.mantissa.get_mpz_t(), 1, 1, sizeof odd, 0, 0, &odd);
  if (p.negative) d.mantissa = -d.mantissa;
  d.exponent = p.exponent + zeros;
  return d;
}

/// q as a Dyadic when its denominator is a power of two, nullopt otherwise.
inline std::optional<Dyadic> dyadic_of(const mpq_class& q) {
  const mpz_srcptr den = q.get_den_mpz_t();
  const mp_bitcnt_t low = mpz_scan1(den, 0);
  if (mpz_sizeinbase(den, 2) != low + 1) return std::nullopt;  // not a power of two
  Dyadic d{q.get_num(), -static_cast<long>(low)};
  if (sgn(d.mantissa) != 0) {  // an odd mantissa keeps products small
    const mp_bitcnt_t tz = mpz_scan1(d.mantissa.get_mpz_t(), 0);
    mpz_fdiv_q_2exp(d.mantissa.get_mpz_t(), d.mantissa.get_mpz_t(), tz);
    d.exponent += static_cast<long>(tz);
  }
  return d;
}

/// m * 2^e as a rational (in lowest terms when m is odd or 0).
inline mpq_class to_rational(const mpz_class& m, long e) {
  mpq_class q(m);
  if (e > 0) mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  else if (e < 0) mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  return q;
}
inline mpq_class to_rational(const Dyadic& d) { return to_rational(d.mantissa, d.exponent); }

/// The exact rational value of a finite float, double or long double, read
/// from its bits (the same in every floating-point environment).
/// \throws Non_finite_input for NaN and infinities.
template <class T>
  requires std::is_floating_point_v<T>
mpq_class exact_rational(T v) {
  return to_rational(dyadic_of(v));
}

}  // namespace relgeo
