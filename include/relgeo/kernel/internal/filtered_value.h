// relgeo/kernel/internal/filtered_value.h — a floating-point value with what
// bounds its rounding error: the first filter of the predicates on implicit
// points (a dynamic version of the semi-static filters of
// semi_static_filter.h, for polynomials too long to derive a constant for).
//
// A Filtered_value<T> carries v^ (the value computed in T), a magnitude m and
// a rounding count k. With M the exact evaluation of the same expression
// on the inputs' absolute values (sums of magnitudes; products of magnitudes,
// but at least lambda, the smallest normal of T), v the exact value and u
// the unit roundoff, round to nearest keeps the invariant
//     |v^ - v| <= gamma_k M,   |v^| <= (1 + gamma_k) M,   gamma_k = k u / (1 - k u)
// with k = 0 for an input (M = |v|) and
//   sum:      M = M_x + M_y,               k = max(k_x, k_y) + 1
//   product:  M = max(M_x M_y, lambda),    k = k_x + k_y + 1.
// Proof by induction (Higham, "Accuracy and Stability of Numerical
// Algorithms", Lemma 3.3): a sum's rounding is <= u |x^ + y^| (sums are
// exact in the subnormal range) and |x^ + y^| <= (1 + gamma) (M_x + M_y); a
// product's is <= u max(|x^ y^|, lambda) (half a subnormal ulp, u lambda,
// when it underflows) and |x^ y^ - x y| <= (gamma_a + gamma_b + gamma_a gamma_b)
// M_x M_y; then gamma_j + u (1 + gamma_j) <= gamma_(j+1).
// Two exact shortcuts keep exact zeros exact: a sum of two inputs that is 0
// is exact (x - x; sums do not underflow), and a product with an exact zero
// factor is exact; both give k = 0, m = 0 (m = 0 exactly when the value is
// an exact 0: the magnitudes of products are at least lambda).
// m is computed in T, rounding to nearest, so m >= M (1 - u)^k (at most k
// roundings along any path), and the final product below three more: the
// sign test separates v^ from e = m (k + 3) u (1 + 8 (k + 3) u) >= gamma_k M,
// valid while (k + 3) u <= 1/8 (k is a few hundred at most here). An overflow
// makes v^ or m infinite or NaN and the test fails (uncertain).
//
// About 4 instructions per operation, against about 10 for a running error
// bound and 20 for interval arithmetic. Assumes the default floating-point
// environment: callers evaluate it inside internal::in_default_fp_environment.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/floating_point.h"

namespace relgeo::internal {

template <class T>
struct Filtered_value {
  T value{};
  T magnitude{};  ///< m, computed M of the invariant |value - exact| <= gamma_k M
  int roundings = 0;  ///< k

  constexpr Filtered_value() = default;
  // An exact input, loaded in the caller's environment (a point's
  // coordinates): |v| from the sign bit, which no environment changes.
  constexpr Filtered_value(T v) : value(v), magnitude(magnitude_of(v)), roundings(0) {}  // NOLINT: exact
  constexpr Filtered_value(T v, T m, int k) : value(v), magnitude(m), roundings(k) {}

  static constexpr T u = std::numeric_limits<T>::epsilon() / 2;
  static constexpr T lambda = std::numeric_limits<T>::min();
  // A constant here, not numeric_limits' call in error_bound(): under
  // -frounding-math GCC converts the call's long double literal at run time,
  // an x87 store of a subnormal, which costs a microcode assist (about a
  // quarter of a gear's Boolean was spent on that one instruction).
  static constexpr T denorm_min = std::numeric_limits<T>::denorm_min();

  friend Filtered_value operator+(const Filtered_value& a, const Filtered_value& b) { return sum(a, b, a.value + b.value); }
  friend Filtered_value operator-(const Filtered_value& a, const Filtered_value& b) { return sum(a, b, a.value - b.value); }
  friend Filtered_value operator-(const Filtered_value& a) { return {-a.value, a.magnitude, a.roundings}; }
  friend Filtered_value operator*(const Filtered_value& a, const Filtered_value& b) {
    const T r = a.value * b.value;
    if (a.magnitude == 0 || b.magnitude == 0) return {r, 0, 0};  // an exact zero factor
    return {r, std::max(a.magnitude * b.magnitude, lambda), a.roundings + b.roundings + 1};
  }

  /// An upper bound of |value - exact| (infinite or NaN after an overflow).
  /// The last product can underflow (a magnitude near lambda): rounded to a
  /// subnormal it may lose up to half the smallest one, which the added
  /// denorm_min restores (it changes nothing above the subnormal range).
  T error_bound() const {
    const T ku = static_cast<T>(roundings + 3) * u;
    return magnitude * (ku * (1 + 8 * ku)) + denorm_min;
  }

  /// The exact sign when the bound separates the value from 0 (or the
  /// value is exact), `uncertain` otherwise.
  Certified_sign sign() const {
    if (roundings == 0) return value == value ? sign_of(value) : Certified_sign::uncertain;
    const T e = error_bound();
    if (value > e) return Certified_sign::positive;
    if (value < -e) return Certified_sign::negative;
    return Certified_sign::uncertain;
  }

 private:
  static Filtered_value sum(const Filtered_value& a, const Filtered_value& b, T r) {
    if ((a.roundings | b.roundings) == 0 && r == 0) return {r, 0, 0};  // x - x, exactly
    return {r, a.magnitude + b.magnitude, std::max(a.roundings, b.roundings) + 1};
  }
};

}  // namespace relgeo::internal
