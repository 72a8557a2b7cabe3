// relgeo/kernel/internal/error_bounded.h — floating-point values carrying a
// bound on their distance to the exact value (a running error analysis): the
// first filter of the predicates on implicit points.
//
// An Error_bounded<T> holds v^ (the value computed in T) and e with
// |v^ - v| <= e, v being the exact value of the same expression on the same
// inputs. Inputs are exact (e = 0). With u the unit roundoff of T and
// eta = 2 * (the smallest positive subnormal of T), round to nearest gives for
// each operation r^ = fl(x^ op y^):
//   sum/difference:  |r^ - (x op y)| <= e_x + e_y + u |r^|
//                    (the rounding error of a sum is <= u |r^|, and 0 when it
//                    underflows: subnormal sums are exact);
//   product:         |r^ - x y| <= |x^| e_y + |y^| e_x + e_x e_y + u |r^| + eta
//                    (|x y - x^ y^| <= |x^| e_y + |y^| e_x + e_x e_y; a
//                    product's rounding error is <= u |r^|, or <= eta/2 in the
//                    subnormal range).
// The bound e itself is computed in T, rounding to nearest: each of its at
// most 6 operations may make it smaller than the exact bound by a factor
// (1 + u), so after an expression of depth d the computed bound is at least
// the true one times (1 + u)^(-6 d). The sign test compares with
// e (1 + 1024 u) + tau: (1 + u)^(6 d) < 1 + 1024 u for every depth d <= 128
// (the implicit predicates have depth below 40), and tau (2^-1000 for double,
// 2^-120 for float) covers underflow inside the bound computation (at most a
// few thousand subnormal roundings of half the smallest subnormal each). An overflow makes v^ or
// e infinite or NaN, and the test then fails (uncertain).
//
// All of this assumes the default floating-point environment: callers
// evaluate inside internal::in_default_fp_environment (core/fp_environment.h).
#pragma once

#include <cmath>
#include <limits>

#include "relgeo/core/certified_sign.h"

namespace relgeo::internal {

template <class T>
struct Error_bounded {
  T value{};
  T error{};  ///< >= |value - exact value|

  constexpr Error_bounded() = default;
  constexpr Error_bounded(T v) : value(v), error(0) {}  // NOLINT: an input is exact
  constexpr Error_bounded(T v, T e) : value(v), error(e) {}

  static constexpr T u = std::numeric_limits<T>::epsilon() / 2;
  static constexpr T eta = 2 * std::numeric_limits<T>::denorm_min();

  friend Error_bounded operator+(const Error_bounded& a, const Error_bounded& b) {
    const T r = a.value + b.value;
    return {r, a.error + b.error + u * std::abs(r)};
  }
  friend Error_bounded operator-(const Error_bounded& a, const Error_bounded& b) {
    const T r = a.value - b.value;
    return {r, a.error + b.error + u * std::abs(r)};
  }
  friend Error_bounded operator-(const Error_bounded& a) { return {-a.value, a.error}; }
  friend Error_bounded operator*(const Error_bounded& a, const Error_bounded& b) {
    const T r = a.value * b.value;
    if (a.error == 0 && b.error == 0 && (a.value == 0 || b.value == 0)) return {r, 0};  // an exact zero factor
    return {r, std::abs(a.value) * b.error + std::abs(b.value) * a.error + a.error * b.error + u * std::abs(r) + eta};
  }

  /// The exact sign when the bound separates the value from 0, or when the
  /// value is exact (error 0: exact inputs, exact differences, exact zero
  /// factors); `uncertain` otherwise (also after an overflow).
  Certified_sign sign() const {
    if (error == 0 && value == value) return sign_of(value);
    constexpr T relative = 1 + 1024 * u;
    constexpr T absolute = std::numeric_limits<T>::digits <= 24 ? T(0x1p-120) : T(0x1p-1000);
    const T margin = error * relative + absolute;
    if (value > margin) return Certified_sign::positive;
    if (value < -margin) return Certified_sign::negative;
    return Certified_sign::uncertain;
  }
};

}  // namespace relgeo::internal
