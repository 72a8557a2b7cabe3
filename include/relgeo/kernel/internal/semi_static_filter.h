// relgeo/kernel/internal/semi_static_filter.h — Fortune's epsilon test for the
// orientation determinants in a binary floating-point type T, with a bound
// derived from the operands (semi-static), as in CGAL's Static_filters.
//
// Derivation (u = unit roundoff of T, gamma_n = n u / (1 - n u), Higham,
// "Accuracy and Stability of Numerical Algorithms", Lemma 3.1). Let a^ = fl(q.x - p.x)
// etc. be the computed differences, a^ = a (1 + d), |d| <= u; the exact
// determinant D and the computed one D^ are sums of the same monomials m of
// differences. Write each monomial in the computed differences, m^:
//   orientation_2: D^ = sum m^ (1 + t2), D = sum m^ (1 + t2'), 2 monomials,
//     |t2|, |t2'| <= gamma_2, each |m^| <= Mx My, Mx = max |x-differences^|
//     =>  |D^ - D| <= 4 gamma_2 Mx My.
//   orientation_3: each monomial goes through at most 5 roundings after the
//     differences (minor product, minor difference, outer product, two outer
//     sums) and 3 differences, 6 monomials, each |m^| <= Mx My Mz
//     =>  |D^ - D| <= 6 (gamma_5 + gamma_3) Mx My Mz.
// The test itself computes fl(fl(eps Mx) My) >= eps Mx My (1-u)^2 (and
// (1-u)^3 in 3D). So the sign of D^ is the exact sign whenever |D^| exceeds the
// computed bound, provided
//   eps_2 >= 4 gamma_2 / (1-u)^2          -> eps_2 = 8u (1 + 8u)  (exact in T)
//   eps_3 >= 6 (gamma_5 + gamma_3)/(1-u)^3 -> eps_3 = 49u           (exact in T)
// For double: eps_2 = 8.8817841970012563e-16 (CGAL's derivation gives the
// slightly larger 8.8872057372592798e-16), eps_3 = 5.4400928206632e-15.
//
// Underflow and overflow void the model fl(x op y) = (x op y)(1 + d). The
// filter therefore answers only when every maximum lies in [low, high]:
//  * high keeps every intermediate finite (the largest sum is < 2^max_exponent);
//  * low makes the absolute error of an underflowing product (at most half the
//    smallest subnormal, eta/2) negligible against the margin left between
//    eps and the exact constant (>= 32u^2 relative in 2D, >= u/2 in 3D).
// A maximum equal to 0 means every difference in that coordinate is exactly 0
// (fl(q - p) = 0 iff q = p), so D = 0 exactly; that case is answered `zero`
// when the computed D^ is 0 too (it is not 0 when an operand is NaN/Inf).
// Everything else (NaN, Inf, out-of-range magnitudes, |D^| <= bound) is
// `uncertain`.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "relgeo/kernel/certified_sign.h"
#include "relgeo/kernel/floating_point.h"
#include "relgeo/kernel/internal/determinants.h"

namespace relgeo::internal {

/// 2^k as a constant expression.
template <class T>
constexpr T power_of_two(int k) {
  T r = 1;
  for (; k > 0; --k) r *= 2;
  for (; k < 0; ++k) r /= 2;
  return r;
}

/// The constants of the epsilon test in type T (see the derivation above).
template <class T>
struct Orientation_filter_constants {
  static constexpr T u = unit_roundoff_v<T>;
  static constexpr T eps_2 = 8 * u * (1 + 8 * u);
  static constexpr T eps_3 = 49 * u;
  static constexpr int min_e = std::numeric_limits<T>::min_exponent;
  static constexpr int max_e = std::numeric_limits<T>::max_exponent;
  static constexpr int digits = std::numeric_limits<T>::digits;
  static constexpr T low_2 = power_of_two<T>((min_e + digits) / 2 + 16);
  static constexpr T high_2 = power_of_two<T>((max_e - 4) / 2);
  static constexpr T low_3 = power_of_two<T>((min_e + digits) / 3 + 16);
  static constexpr T high_3 = power_of_two<T>((max_e - 4) / 3);
};

/// Outcome of the epsilon test, computed without branches.
///  * decided: the range guards hold and |det| > bound: `sign` is the exact sign;
///  * otherwise exact_zero: all differences of one coordinate are 0 and det is
///    0, so the exact determinant is 0;
///  * otherwise the test cannot tell (`uncertain`).
struct Epsilon_test {
  Certified_sign sign;  ///< sign of the computed determinant
  bool decided;
  bool exact_zero;
  /// The certified answer. The branch on `decided` is the only one, and is
  /// well predicted on the usual inputs (nearly all decided).
  Certified_sign answer() const {
    if (decided) [[likely]]
      return sign;
    return exact_zero ? Certified_sign::zero : Certified_sign::uncertain;
  }
};

template <class T>
inline Epsilon_test epsilon_test(T det, T bound, bool in_range, T lo) {
  // x <= 0 stands for x == 0 on the non-negative |det| and lo (the same answer,
  // NaN included, with one flag test); & rather than && keeps it branch-free.
  const T abs_det = std::abs(det);
  return {sign_of(det), static_cast<bool>(in_range & (abs_det > bound)),
          static_cast<bool>((abs_det <= 0) & (lo <= 0))};
}

/// The epsilon test of orientation_2 in T.
template <class T>
inline Epsilon_test orientation_2_epsilon_test(T px, T py, T qx, T qy, T rx, T ry) {
  using C = Orientation_filter_constants<T>;
  const T det = orientation_2_determinant<T>(px, py, qx, qy, rx, ry);
  const T mx = std::max(std::abs(qx - px), std::abs(rx - px));
  const T my = std::max(std::abs(qy - py), std::abs(ry - py));
  const T lo = std::min(mx, my), hi = std::max(mx, my);
  return epsilon_test(det, C::eps_2 * mx * my, (lo >= C::low_2) & (hi <= C::high_2), lo);
}

/// The epsilon test of orientation_3 in T.
template <class T>
inline Epsilon_test orientation_3_epsilon_test(T px, T py, T pz, T qx, T qy, T qz, T rx, T ry,
                                               T rz, T sx, T sy, T sz) {
  using C = Orientation_filter_constants<T>;
  const T det =
      orientation_3_determinant<T>(px, py, pz, qx, qy, qz, rx, ry, rz, sx, sy, sz);
  const T mx = std::max({std::abs(qx - px), std::abs(rx - px), std::abs(sx - px)});
  const T my = std::max({std::abs(qy - py), std::abs(ry - py), std::abs(sy - py)});
  const T mz = std::max({std::abs(qz - pz), std::abs(rz - pz), std::abs(sz - pz)});
  const T lo = std::min({mx, my, mz}), hi = std::max({mx, my, mz});
  return epsilon_test(det, C::eps_3 * mx * my * mz, (lo >= C::low_3) & (hi <= C::high_3), lo);
}

/// Epsilon-tested sign of orientation_2 in T; `uncertain` when the test cannot
/// certify the sign of the computed determinant.
template <class T>
inline Certified_sign filtered_orientation_2(T px, T py, T qx, T qy, T rx, T ry) {
  return orientation_2_epsilon_test<T>(px, py, qx, qy, rx, ry).answer();
}

/// Epsilon-tested sign of orientation_3 in T.
template <class T>
inline Certified_sign filtered_orientation_3(T px, T py, T pz, T qx, T qy, T qz, T rx, T ry,
                                             T rz, T sx, T sy, T sz) {
  return orientation_3_epsilon_test<T>(px, py, pz, qx, qy, qz, rx, ry, rz, sx, sy, sz).answer();
}

}  // namespace relgeo::internal
