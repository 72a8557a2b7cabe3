// relgeo/kernel/floating_point.h — facts about IEEE types that kernels and
// their error bounds are derived from.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

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

/// A double >= the positive value v of a wider type, at most one ulp above it
/// (publishes error constants of long double kernels without rounding them down).
template <class T>
constexpr double round_up_to_double(T v) noexcept {
  double d = static_cast<double>(v);
  if (static_cast<T>(d) < v) d += d * 0x1p-52;  // adds at least one ulp of d
  return d;
}

}  // namespace relgeo
