// relgeo/kernel/internal/expansion_orientation_3.h — the exact sign of
// orientation_3 for doubles in floating-point expansions (expansion.h),
// without GMP: the expansion stage of Filtered_exact_kernel::orientation_3.
//
// The determinant is D(a) = c2 . (c0 x c1) of the columns c0 = q - p,
// c1 = r - p, c2 = s - p (the cofactor order of determinants.h:
// D = a22 m01 - a12 m02 + a02 m12 with the 2x2 minors m of the first two
// columns). Each entry is split exactly by two_diff into its rounded value
// and a tail, a = â + t, and the stage proceeds in two steps:
//  1. Compensated evaluation with a proven bound. D is multilinear, so
//     D(â + t) = D(â) + T1 + R with the first-order term
//     T1 = tc2 . (ĉ0 x ĉ1) + tc0 . (ĉ1 x ĉ2) + tc1 . (ĉ2 x ĉ0) and a rest R
//     of second and third order. In round to nearest |t| <= u |â|
//     (u = 2^-53), so with P = sum over the 6 monomials of |â â â|:
//       |R| <= (3u^2 + u^3) P,
//     and T1 computed in floating point (T1c; each of its 18 terms through at
//     most 7 roundings) errs by at most gamma_7 3u P (each monomial appears in
//     three terms, once per tail; gamma_n = nu / (1 - nu)). Each monomial
//     +-c x y of D(â) is written as H + L + c l with (h, l) = two_product(x, y)
//     and (H, L) = two_product(c, h), exactly; c l is computed in floating
//     point, off by at most u |c l| <= u^2 (1 + u) |c x y|. The N = 19 terms
//     (18 of the monomials, T1c) are added by Sum2 (Ogita, Rump, Oishi,
//     "Accurate sum and dot product", SIAM J. Sci. Comput. 26, 2005: a chain
//     of two_sum, the errors added in floating point, then both): its result
//     E errs from the terms' exact sum by at most
//     u |E| + gamma_{N-2} gamma_{N-1} X, where X, the terms' absolute sum, is
//     at most ((1 + 2u)(1 + u)^2 + 3u (1 + gamma_7)) P. Altogether
//       |D - E| <= u |E| + K P,
//       K = 3u^2 + u^3 + 3u gamma_7 + u^2 (1 + u)
//           + gamma_17 gamma_18 ((1 + 2u)(1 + u)^2 + 3u (1 + gamma_7))
//     (about 331 u^2). The computed P^ (a sum of positive products, at most
//     7 roundings each) is at least (1 - gamma_7) P and fl(c P^) at least
//     (1 - u) c P^, so sign(E) = sign(D) whenever |E| > fl(c P^) with
//       (1 - u)^2 (1 - gamma_7) c >= K;
//     c = 512 u^2 satisfies it (test/kernel/expansion_orientation_3_test.cpp
//     checks it in rational arithmetic). Near-coplanar input, |D| a few
//     units of u P, is decided here.
//  2. Otherwise D exactly in expansions (expansion.h): D(â) (at most 24
//     components: minors by two_product, scaled by an entry, summed) when
//     every tail is 0 (integer or otherwise exactly representable
//     differences), else D(â + t) with the entries as 2-component
//     expansions (minors of 16 components, D of at most 192).
//
// Range: every coordinate 0 or of magnitude in [2^-250, 2^300]. Then
//  * every coordinate, difference and tail is a multiple of q = 2^-302 (the
//    lowest bit of a double of magnitude >= 2^-250), every product of two a
//    multiple of q^2 and of three a multiple of q^3 = 2^-906 (sums and
//    roundings keep these multiples): every two_product has factors whose lowest bits sum to >= -906 > -1074, so it is exact
//    (expansion.h); and every nonzero floating-point result of step 2 is at
//    least q^3, a normal number, so the relative error model above holds
//    (no underflow), the bound included: c q^3 = 2^-1003;
//  * differences are below 2^301, products of three below 2^903, and every
//    sum of the at most 192 terms below 2^912: nothing overflows, and every
//    two_product stays within Dekker's range (error_free.h: factors below
//    2^995, products below 2^1020).
// test/kernel/expansion_orientation_3_test.cpp checks the stage against GMP
// (exact_dyadic.h) over the whole range and at its edges: every case in
// range is decided, and exactly.
//
// Like every later stage it relies on round to nearest (ties to even) without
// FTZ/DAZ: callers run it in a Default_fp_environment.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/internal/error_free.h"
#include "relgeo/core/interval.h"
#include "relgeo/kernel/internal/expansion.h"

namespace relgeo::internal {

/// The range of the orientation_3 expansion stage (see above).
struct Expansion_orientation_3_range {
  static constexpr double low = 0x1p-250;
  static constexpr double high = 0x1p300;
  static bool contains(double v) {
    const double a = std::abs(v);
    return a == 0 || (a >= low && a <= high);
  }
};

/// The constant of step 1's error bound: c = 512 u^2.
struct Expansion_orientation_3_constants {
  static constexpr double u = 0x1p-53;
  static constexpr double c = 512 * u * u;
  static constexpr int terms = 19;  ///< N, the terms added by Sum2
};

/// The step of the stage that decided (for tests and statistics).
enum class Expansion_step { compensated, exact_rounded_differences, exact };

/// Step 2: the exact sign of D from the split entries d[row][column]
/// (value + error), in expansions; `rounded_only` when every error is 0.
[[gnu::noinline]] inline Certified_sign exact_orientation_3_in_expansions(
    const std::array<std::array<Two_terms, 3>, 3>& d, bool rounded_only) {
  if (rounded_only) {
    const auto a = [&](int row, int col) { return d[row][col].value; };
    const Expansion<4> m01 = exact_product(a(0, 0), a(1, 1)) - exact_product(a(1, 0), a(0, 1));
    const Expansion<4> m02 = exact_product(a(0, 0), a(2, 1)) - exact_product(a(2, 0), a(0, 1));
    const Expansion<4> m12 = exact_product(a(1, 0), a(2, 1)) - exact_product(a(2, 0), a(1, 1));
    return ((m01 * a(2, 2) - m02 * a(1, 2)) + m12 * a(0, 2)).sign();
  }
  const auto e = [&](int row, int col) { return Expansion<2>(d[row][col]); };
  const Expansion<16> n01 = e(0, 0) * e(1, 1) - e(1, 0) * e(0, 1);
  const Expansion<16> n02 = e(0, 0) * e(2, 1) - e(2, 0) * e(0, 1);
  const Expansion<16> n12 = e(1, 0) * e(2, 1) - e(2, 0) * e(1, 1);
  return ((n01 * e(2, 2) - n02 * e(1, 2)) + n12 * e(0, 2)).sign();
}

/// Step 1 and what step 2 needs: the split entries d[row][column], whether
/// every error is 0, the compensated estimate E of D and the bound
/// fl(c P^), so that |D - E| <= u |E| + bound (see above).
struct Compensated_orientation_3 {
  std::array<std::array<Two_terms, 3>, 3> entries;
  bool exact_differences = true;
  double estimate = 0, bound = 0;
  /// The sign of E is D's.
  bool decides() const { return std::abs(estimate) > bound; }
};

/// Step 1 on (p, q, r, s) given as px py pz qx qy qz rx ry rz sx sy sz;
/// nullopt when a coordinate is outside Expansion_orientation_3_range (or
/// NaN or infinite).
inline std::optional<Compensated_orientation_3> compensated_orientation_3(const std::array<double, 12>& c) {
  bool in_range = true;
  for (double v : c) in_range &= Expansion_orientation_3_range::contains(v);
  if (!in_range) return std::nullopt;

  // Entries a[row][column], row = coordinate, column = q, r, s minus p.
  Compensated_orientation_3 result;
  auto& d = result.entries;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) {
      d[row][col] = two_diff(c[3 * (col + 1) + row], c[row]);
      result.exact_differences &= d[row][col].error == 0;
    }
  const auto a = [&](int row, int col) { return d[row][col].value; };
  const auto t = [&](int row, int col) { return d[row][col].error; };

  // Each monomial sign * c x y as H + L + fl(c l) (see above).
  std::array<double, Expansion_orientation_3_constants::terms> terms;
  std::size_t n = 1;  // terms[0] is T1c
  const auto add_monomial = [&](double sign, double c3, double x, double y) {
    const Two_terms h = two_product(x, y);
    const Two_terms hc = two_product(c3, h.value);
    terms[n++] = sign * hc.value;
    terms[n++] = sign * hc.error;
    terms[n++] = sign * (c3 * h.error);
    return h.value;  // fl(x y), reused for T1c
  };
  // D(â) = a22 m01 - a12 m02 + a02 m12; the rounded minor products give the
  // rows of ĉ0 x ĉ1 = (m12, -m02, m01) for T1c.
  const double m01 = add_monomial(1, a(2, 2), a(0, 0), a(1, 1)) - add_monomial(-1, a(2, 2), a(1, 0), a(0, 1));
  const double m02 = add_monomial(-1, a(1, 2), a(0, 0), a(2, 1)) - add_monomial(1, a(1, 2), a(2, 0), a(0, 1));
  const double m12 = add_monomial(1, a(0, 2), a(1, 0), a(2, 1)) - add_monomial(-1, a(0, 2), a(2, 0), a(1, 1));
  const auto cross = [&](int i, int j, int row) {  // row `row` of column i x column j
    const int r1 = (row + 1) % 3, r2 = (row + 2) % 3;
    return a(r1, i) * a(r2, j) - a(r2, i) * a(r1, j);
  };
  const auto tail_dot_cross = [&](int k, int i, int j) {  // t(column k) . (column i x column j)
    return (t(0, k) * cross(i, j, 0) + t(1, k) * cross(i, j, 1)) + t(2, k) * cross(i, j, 2);
  };
  terms[0] = ((t(0, 2) * m12 - t(1, 2) * m02) + t(2, 2) * m01) + (tail_dot_cross(0, 1, 2) + tail_dot_cross(1, 2, 0));
  // Sum2: a chain of two_sum, the errors added apart.
  double sum = terms[0], errors = 0;
  for (std::size_t i = 1; i < terms.size(); ++i) {
    const Two_terms s = two_sum(sum, terms[i]);
    sum = s.value;
    errors += s.error;
  }
  result.estimate = sum + errors;
  const auto abs_minor = [&](int r1, int r2) {  // |a(r1,0) a(r2,1)| + |a(r2,0) a(r1,1)|
    return std::abs(a(r1, 0)) * std::abs(a(r2, 1)) + std::abs(a(r2, 0)) * std::abs(a(r1, 1));
  };
  const double permanent = (std::abs(a(2, 2)) * abs_minor(0, 1) + std::abs(a(1, 2)) * abs_minor(0, 2)) +
                           std::abs(a(0, 2)) * abs_minor(1, 2);
  result.bound = Expansion_orientation_3_constants::c * permanent;
  return result;
}

/// The exact sign of orientation_3 of (p, q, r, s) (coordinates as above),
/// and the step that decided it; nullopt outside the range.
inline std::optional<std::pair<Certified_sign, Expansion_step>> expansion_orientation_3_with_step(
    const std::array<double, 12>& c) {
  const std::optional<Compensated_orientation_3> s = compensated_orientation_3(c);
  if (!s) return std::nullopt;
  if (s->decides()) [[likely]]
    return std::pair{s->estimate > 0 ? Certified_sign::positive : Certified_sign::negative,
                     Expansion_step::compensated};
  return std::pair{exact_orientation_3_in_expansions(s->entries, s->exact_differences),
                   s->exact_differences ? Expansion_step::exact_rounded_differences : Expansion_step::exact};
}

/// An interval holding the orientation_3 determinant D itself (not only its
/// sign), from step 1: |D - E| <= u |E| + fl(c P^), a few units in the last
/// place of D wide unless D is tiny against P (near-coplanar points; u |E|
/// is exact: E is 0 or at least 2^-906); nullopt outside the range.
inline std::optional<Interval> orientation_3_enclosure(const std::array<double, 12>& c) {
  const std::optional<Compensated_orientation_3> s = compensated_orientation_3(c);
  if (!s) return std::nullopt;
  const double radius =
      (Interval(Expansion_orientation_3_constants::u * std::abs(s->estimate)) + Interval(s->bound)).sup();
  return Interval(s->estimate) + Interval(-radius, radius);
}

/// The exact sign of orientation_3 (coordinates as above) in the range of
/// Expansion_orientation_3_range, nullopt outside it.
inline std::optional<Certified_sign> expansion_orientation_3(const std::array<double, 12>& c) {
  const auto r = expansion_orientation_3_with_step(c);
  if (!r) return std::nullopt;
  return r->first;
}

}  // namespace relgeo::internal
