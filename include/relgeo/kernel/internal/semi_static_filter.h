// relgeo/kernel/internal/semi_static_filter.h — Fortune's epsilon test for the
// orientation determinants in a binary floating-point type T, with a bound
// derived from the operands (semi-static), as in CGAL's Static_filters, but
// valid in every floating-point environment a caller can set (core/fp_environment.h):
// any IEEE rounding mode, flush-to-zero and denormals-are-zero.
//
// Model (u = unit roundoff of T, v = 2u, lambda = the smallest positive normal
// of T). Every operation gives fl(x op y) = (x op y)(1 + d) + e with |d| <= v
// (one ulp: round to nearest has |d| <= u, the directed modes |d| < 2u) and
// |e| <= lambda (a result flushed to zero, or a subnormal rounding error); a
// subnormal input read as zero (DAZ) changes it by less than lambda. So a
// computed coordinate difference is a^ = a (1 + d) + e_a with |e_a| <= 3.01
// lambda. gamma_n = n v / (1 - n v) (Higham, "Accuracy and Stability of
// Numerical Algorithms", Lemma 3.1, which allows the 1/(1+d) factors below).
//
// Let Mx = max |computed x-differences| etc. Write the exact determinant D and
// the computed D^ in the computed differences (a = (a^ - e_a) / (1 + d_a)):
//   orientation_2: 2 monomials, each through 2 roundings after its 2
//     differences: |D^ - D| <= 4 gamma_2 Mx My + 6.1 lambda (Mx + My) + 3.2 lambda.
//   orientation_3: 6 monomials, each through at most 5 roundings after its 3
//     differences (minor product, minor difference, outer product, two outer
//     sums): |D^ - D| <= 6 (gamma_5 + gamma_3) Mx My Mz
//                         + 20 lambda (Mx My + My Mz + Mx Mz) + 10 lambda (Mx + My + Mz) + 6 lambda.
// The test computes its bound fl(fl(eps Mx) My) >= eps Mx My (1-v)^2 (and
// (1-v)^3 in 3D; no underflow there, by the range guard below). So the sign of
// D^ is the exact sign whenever |D^| exceeds the computed bound, provided, with
// L a lower bound of every maximum (the range guard),
//   eps_2 (1-v)^2 - 4 gamma_2            >= 12.2 lambda / L + 3.2 lambda / L^2
//   eps_3 (1-v)^3 - 6 (gamma_5 + gamma_3) >= 60 lambda / L + 30 lambda / L^2 + 6 lambda / L^3.
// eps_2 = 16u (1 + 16u) and eps_3 = 97u leave about 32 v^2 and v / 2 on the
// left (exact in T); low_2 and low_3 make the right-hand sides smaller still
// (test/kernel/filter_bound_test.cpp checks both inequalities exactly).
// For double: eps_2 = 1.7763568394002532e-15, eps_3 = 1.0769163338864018e-14,
// twice CGAL's constants, which assume round to nearest.
//
// Range guard: the filter answers only when every maximum lies in [low, high]:
// high keeps every intermediate finite (the largest sum is < 2^max_exponent;
// under directed rounding an overflow may give the largest finite value
// instead of infinity, still above high); low is the L above. Outside, and
// for |D^| <= bound, the test does not decide; an exact degeneracy (every
// coordinate of one axis the same, so D = 0) is then recognised by comparing
// the coordinates' bits, which no environment can disturb (exactly_degenerate).
// Everything else (NaN, Inf, out-of-range magnitudes) is `uncertain`.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/floating_point.h"
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
  static constexpr T eps_2 = 16 * u * (1 + 16 * u);
  static constexpr T eps_3 = 97 * u;
  static constexpr int min_e = std::numeric_limits<T>::min_exponent;
  static constexpr int max_e = std::numeric_limits<T>::max_exponent;
  static constexpr int digits = std::numeric_limits<T>::digits;
  static constexpr T low_2 = power_of_two<T>((min_e - 1) / 2 + digits + 8);
  static constexpr T high_2 = power_of_two<T>((max_e - 4) / 2);
  static constexpr T low_3 = power_of_two<T>((min_e + 2 * digits) / 3 + 8);
  static constexpr T high_3 = power_of_two<T>((max_e - 4) / 3);
};

/// Outcome of the epsilon test, computed without branches: when `decided`
/// (the range guards hold and |det| > bound), `sign` is the exact sign.
struct Epsilon_test {
  Certified_sign sign;  ///< sign of the computed determinant
  bool decided;
};

template <class T>
[[gnu::always_inline]] inline Epsilon_test epsilon_test(T det, T bound, bool in_range) {
  // & rather than && keeps it branch-free.
  return {sign_of(det), static_cast<bool>(in_range & (std::abs(det) > bound))};
}

/// Whether every point has the same first, or the same second (or third)
/// coordinate, so that the orientation determinant is exactly 0: the exact
/// degeneracies the epsilon test leaves undecided (its range guard needs
/// nonzero differences). Finite coordinates only (NaN and Inf give false).
template <class T>
inline bool exactly_degenerate_2(T px, T py, T qx, T qy, T rx, T ry) {
  if (!all_finite(px, py, qx, qy, rx, ry)) return false;
  return (same_value(px, qx) && same_value(px, rx)) || (same_value(py, qy) && same_value(py, ry));
}
template <class T>
inline bool exactly_degenerate_3(T px, T py, T pz, T qx, T qy, T qz, T rx, T ry, T rz, T sx, T sy,
                                 T sz) {
  if (!all_finite(px, py, pz, qx, qy, qz, rx, ry, rz, sx, sy, sz)) return false;
  return (same_value(px, qx) && same_value(px, rx) && same_value(px, sx)) ||
         (same_value(py, qy) && same_value(py, ry) && same_value(py, sy)) ||
         (same_value(pz, qz) && same_value(pz, rz) && same_value(pz, sz));
}

/// The epsilon test of orientation_2 in T.
template <class T>
inline Epsilon_test orientation_2_epsilon_test(T px, T py, T qx, T qy, T rx, T ry) {
  using C = Orientation_filter_constants<T>;
  const T det = orientation_2_determinant<T>(px, py, qx, qy, rx, ry);
  const T mx = std::max(std::abs(qx - px), std::abs(rx - px));
  const T my = std::max(std::abs(qy - py), std::abs(ry - py));
  const T lo = std::min(mx, my), hi = std::max(mx, my);
  return epsilon_test(det, C::eps_2 * mx * my, (lo >= C::low_2) & (hi <= C::high_2));
}

/// The epsilon test of orientation_3(p, q, r, s) in T for several points s
/// against one plane (p, q, r): what does not depend on s (the minors, the
/// maxima of q - p and r - p) computed once; the same operations as for one
/// s, so the same answers. Its parts are always inlined: at -O1 GCC 12 left
/// some out of line, and a call of the filtered kernel's functor took three
/// times as long (doc/kernels.md, "A plain loop over the functor").
template <class T>
class Orientation_3_plane_epsilon_test {
 public:
  [[gnu::always_inline]] Orientation_3_plane_epsilon_test(T px, T py, T pz, T qx, T qy, T qz, T rx, T ry, T rz)
      : minors_(px, py, pz, qx, qy, qz, rx, ry, rz),
        mx_(std::max(std::abs(qx - px), std::abs(rx - px))),
        my_(std::max(std::abs(qy - py), std::abs(ry - py))),
        mz_(std::max(std::abs(qz - pz), std::abs(rz - pz))) {}
  [[gnu::always_inline]] Epsilon_test operator()(T sx, T sy, T sz) const {
    using C = Orientation_filter_constants<T>;
    const T det = minors_.determinant(sx, sy, sz);
    const T mx = std::max(mx_, std::abs(sx - minors_.px));
    const T my = std::max(my_, std::abs(sy - minors_.py));
    const T mz = std::max(mz_, std::abs(sz - minors_.pz));
    const T lo = std::min(std::min(mx, my), mz), hi = std::max(std::max(mx, my), mz);
    return epsilon_test(det, C::eps_3 * mx * my * mz, (lo >= C::low_3) & (hi <= C::high_3));
  }

 private:
  Orientation_3_minors<T> minors_;
  T mx_, my_, mz_;
};

/// The epsilon test of orientation_3 in T.
template <class T>
[[gnu::always_inline]] inline Epsilon_test orientation_3_epsilon_test(T px, T py, T pz, T qx, T qy, T qz, T rx, T ry,
                                                                      T rz, T sx, T sy, T sz) {
  return Orientation_3_plane_epsilon_test<T>(px, py, pz, qx, qy, qz, rx, ry, rz)(sx, sy, sz);
}

/// Epsilon-tested sign of orientation_2 in T; `uncertain` when the test cannot
/// certify the sign of the computed determinant.
template <class T>
inline Certified_sign filtered_orientation_2(T px, T py, T qx, T qy, T rx, T ry) {
  const Epsilon_test t = orientation_2_epsilon_test<T>(px, py, qx, qy, rx, ry);
  if (t.decided) [[likely]]  // the only branch, well predicted on usual input
    return t.sign;
  return exactly_degenerate_2(px, py, qx, qy, rx, ry) ? Certified_sign::zero : Certified_sign::uncertain;
}

/// Epsilon-tested sign of orientation_3 in T.
template <class T>
inline Certified_sign filtered_orientation_3(T px, T py, T pz, T qx, T qy, T qz, T rx, T ry,
                                             T rz, T sx, T sy, T sz) {
  const Epsilon_test t = orientation_3_epsilon_test<T>(px, py, pz, qx, qy, qz, rx, ry, rz, sx, sy, sz);
  if (t.decided) [[likely]]
    return t.sign;
  return exactly_degenerate_3(px, py, pz, qx, qy, qz, rx, ry, rz, sx, sy, sz) ? Certified_sign::zero
                                                                              : Certified_sign::uncertain;
}

}  // namespace relgeo::internal
