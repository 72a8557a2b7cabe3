// relgeo/core/floating_point.h — facts about IEEE types that kernels and
// their error bounds are derived from.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "relgeo/core/certified_sign.h"

namespace relgeo {

/// Unit roundoff u = 2^-p of a binary floating-point type with p significand
/// bits under round-to-nearest (2^-53 for double, 2^-24 for float, 2^-64 for
/// x86 long double).
template <class T>
  requires std::is_floating_point_v<T>
inline constexpr T unit_roundoff_v = std::numeric_limits<T>::epsilon() / 2;

/// True when every argument is a finite number (no NaN, no infinity).
template <class... T>
constexpr bool all_finite(T... v) noexcept {
  return (std::isfinite(v) && ...);
}

/// |v| from its sign bit, in every floating-point environment: the
/// expression `v < 0 ? -v : v` compares, and under denormals-are-zero a
/// comparison reads a negative subnormal as 0 and keeps it negative.
template <class T>
  requires std::is_floating_point_v<T>
constexpr T magnitude_of(T v) noexcept {
  if constexpr (sizeof(T) == 8 || sizeof(T) == 4) {
    using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
    return std::bit_cast<T>(static_cast<Bits>(std::bit_cast<Bits>(v) & (~Bits{0} >> 1)));
  } else {
    return std::signbit(v) ? -v : v;  // x87 (no DAZ) or software long double: a sign-bit test, no comparison
  }
}

/// A double >= the positive value v of a wider type, at most one ulp above it
/// (publishes error constants of long double kernels without rounding them down).
template <class T>
constexpr double round_up_to_double(T v) noexcept {
  double d = static_cast<double>(v);
  if (static_cast<T>(d) < v) d += d * 0x1p-52;  // adds at least one ulp of d
  return d;
}

namespace internal {

/// The fields of an x87 80-bit long double (sign, 15-bit biased exponent,
/// 64-bit significand with its explicit integer bit).
struct X87_parts {
  bool sign;
  unsigned exponent;
  std::uint64_t significand;
};
template <class T>
inline X87_parts x87_parts(T v) {
  static_assert(std::numeric_limits<T>::digits == 64, "x87 extended precision");
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof(T));
  std::uint64_t significand = 0;
  std::uint16_t sign_exponent = 0;
  std::memcpy(&significand, bytes, 8);
  std::memcpy(&sign_exponent, bytes + 8, 2);
  return {(sign_exponent >> 15) != 0, sign_exponent & 0x7FFFu, significand};
}

/// Whether a and b are the same value, decided on their bits (a comparison
/// instruction would read two different subnormals as equal under DAZ).
/// \pre a and b are finite.
template <class T>
inline bool same_value(T a, T b) {
  if constexpr (sizeof(T) == 8 || sizeof(T) == 4) {
    using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
    constexpr Bits magnitude = ~Bits{0} >> 1;
    const Bits x = std::bit_cast<Bits>(a), y = std::bit_cast<Bits>(b);
    return x == y || ((x | y) & magnitude) == 0;  // equal, or +0 and -0
  } else if constexpr (std::numeric_limits<T>::digits == 64) {
    // x87 long double: its own arithmetic has no FTZ/DAZ, but the compiler may
    // compare two long doubles converted from doubles as the doubles (SSE,
    // where DAZ applies), so the value is read from its bits here too.
    const X87_parts x = x87_parts(a), y = x87_parts(b);
    return (x.sign == y.sign && x.exponent == y.exponent && x.significand == y.significand) ||
           (x.significand == 0 && y.significand == 0);
  } else {
    return a == b;  // e.g. binary128 long double, in software
  }
}

/// Certified comparison of two IEEE values: `uncertain` when either is NaN or
/// infinite. Float and double are compared on their bits (ordered as
/// integers), because a comparison instruction reads two different subnormals
/// as equal under denormals-are-zero (core/fp_environment.h).
template <class T>
inline Certified_sign compare_certified(T a, T b) {
  if (!all_finite(a, b)) return Certified_sign::uncertain;
  if constexpr (sizeof(T) == 8 || sizeof(T) == 4) {
    if (same_value(a, b)) return Certified_sign::zero;  // also +0 and -0
    using Int = std::conditional_t<sizeof(T) == 8, std::int64_t, std::int32_t>;
    constexpr Int magnitude = std::numeric_limits<Int>::max();
    // Sign-magnitude bits to an order-preserving two's complement key.
    const auto key = [](T v) {
      const Int i = std::bit_cast<Int>(v);
      return i ^ ((i >> (8 * sizeof(Int) - 1)) & magnitude);
    };
    return key(a) < key(b) ? Certified_sign::negative : Certified_sign::positive;
  } else if constexpr (std::numeric_limits<T>::digits == 64) {
    // x87 long double, on its bits as well (see same_value): finite values
    // order as (exponent, significand), reversed for negative ones.
    if (same_value(a, b)) return Certified_sign::zero;
    const X87_parts x = x87_parts(a), y = x87_parts(b);
    const bool x_negative = x.sign && x.significand != 0, y_negative = y.sign && y.significand != 0;
    if (x_negative != y_negative) return x_negative ? Certified_sign::negative : Certified_sign::positive;
    const bool smaller_magnitude = x.exponent != y.exponent ? x.exponent < y.exponent : x.significand < y.significand;
    return smaller_magnitude != x_negative ? Certified_sign::negative : Certified_sign::positive;
  } else {
    if (a < b) return Certified_sign::negative;
    return b < a ? Certified_sign::positive : Certified_sign::zero;
  }
}

}  // namespace internal
}  // namespace relgeo
