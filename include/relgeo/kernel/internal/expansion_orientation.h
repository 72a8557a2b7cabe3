// relgeo/kernel/internal/expansion_orientation.h — the exact sign of
// orientation_2 for doubles by error-free transformations, without GMP.
//
// With the coordinate differences split exactly into two doubles each
// (TwoSum), (qx-px)(ry-py) - (qy-py)(rx-px) is exactly the sum of 16 doubles
// (TwoProduct of each pair of parts). Its sign is found by distillation: each
// pass of VecSum (Ogita, Rump, Oishi, "Accurate sum and dot product", SIAM J.
// Sci. Comput. 26, 2005) keeps the exact sum and moves it into the last
// element s; once |s| exceeds an upper bound of the others' absolute sum, the
// sign is sign(s). About 10x faster than the GMP stage (exact_dyadic.h), which
// remains the fallback outside the guarded range.
#pragma once

#include <array>
#include <cmath>
#include <optional>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/internal/error_free.h"

namespace relgeo::internal {

/// Whether v is 0 or 2^-400 <= |v| <= 2^500 (false for NaN and infinities).
/// In that range no TwoProduct below underflows (the smallest nonzero part of
/// a difference is 2^-452, so products are >= 2^-904) or overflows (<= 2^1002),
/// and no sum of 16 products overflows.
inline bool in_expansion_range(double v) {
  const double a = std::abs(v);
  return a == 0 || (a >= 0x1p-400 && a <= 0x1p500);
}

/// The exact sign of a sum of N doubles (finite, sum far from overflow), or
/// nullopt if `max_passes` distillation passes do not settle it.
template <std::size_t N>
std::optional<Certified_sign> sign_of_exact_sum(std::array<double, N> x, int max_passes = 2 * N) {
  // Rounded sum of N - 1 nonnegative terms: below the exact sum by at most
  // (N - 2) u of it, plus underflow (each rounding error at most 2^-1075).
  constexpr double widen = 1 + 2 * static_cast<double>(N) * 0x1p-53;
  for (int pass = 0; pass < max_passes; ++pass) {
    for (std::size_t i = 1; i < N; ++i) {
      const Two_terms t = two_sum(x[i], x[i - 1]);
      x[i] = t.value, x[i - 1] = t.error;
    }
    double rest = 0;
    for (std::size_t i = 0; i + 1 < N; ++i) rest += std::abs(x[i]);
    const double s = x[N - 1];
    if (rest == 0) return sign_of(s > 0 ? 1 : (s < 0 ? -1 : 0));  // the sum is s exactly
    if (std::abs(s) > rest * widen + static_cast<double>(N) * 0x1p-1074)
      return s > 0 ? Certified_sign::positive : Certified_sign::negative;
  }
  return std::nullopt;
}

/// Exact sign of orientation_2 of double points in the range of
/// in_expansion_range, nullopt outside it (or, in theory, if distillation
/// does not settle: the caller then uses the GMP stage).
inline std::optional<Certified_sign> expansion_orientation_2(double px, double py, double qx, double qy,
                                                             double rx, double ry) {
  for (double v : {px, py, qx, qy, rx, ry})
    if (!in_expansion_range(v)) return std::nullopt;
  // The same formula as determinants.h: (qx - px)(ry - py) - (qy - py)(rx - px).
  const Two_terms a = two_diff(qx, px), b = two_diff(ry, py), c = two_diff(qy, py), d = two_diff(rx, px);
  std::array<double, 16> terms;
  std::size_t k = 0;
  auto add_product = [&](double x, double y, double sign) {
    const Two_terms t = two_product(x, y);
    terms[k++] = sign * t.value, terms[k++] = sign * t.error;
  };
  for (double u : {a.value, a.error})
    for (double v : {b.value, b.error}) add_product(u, v, 1.0);
  for (double u : {c.value, c.error})
    for (double v : {d.value, d.error}) add_product(u, v, -1.0);
  return sign_of_exact_sum(terms);
}

}  // namespace relgeo::internal
