// relgeo/kernel/internal/expansion_orientation.h — the exact sign of
// orientation_2 for doubles in floating-point expansions (expansion.h),
// without GMP: the expansion stage of Filtered_exact_kernel::orientation_2
// (orientation_3's is expansion_orientation_3.h, with the same two steps).
//
// D = a b - c d with a = qx - px, b = ry - py, c = qy - py, d = rx - px. Each
// difference is split exactly by two_diff into its rounded value and a tail,
// a = â + t_a, and
//  1. Compensated evaluation with a proven bound. D = â b̂ - ĉ d̂ + T1 + R
//     with T1 = t_a b̂ + t_b â - t_c d̂ - t_d ĉ and R = t_a t_b - t_c t_d; in
//     round to nearest |t| <= u |·| (u = 2^-53), so with P = |â b̂| + |ĉ d̂|,
//     |R| <= u^2 P, and T1 computed in floating point (T1c, 3 roundings per
//     term) errs by at most gamma_3 2u P (gamma_n = nu / (1 - nu)). The two
//     products are split exactly by two_product into H + L; the N = 5 terms
//     T1c, H1, L1, -H2, -L2 are added by Sum2 (Ogita, Rump, Oishi, SIAM J.
//     Sci. Comput. 26, 2005), whose result E errs from their exact sum by at
//     most u |E| + gamma_3 gamma_4 X, X = the terms' absolute sum
//     <= ((1 + u)^2 + 2u (1 + gamma_3)) P. So |D - E| <= u |E| + K P,
//       K = u^2 + 2u gamma_3 + gamma_3 gamma_4 ((1 + u)^2 + 2u (1 + gamma_3))
//     (about 19 u^2), and with the computed P^ >= (1 - gamma_2) P,
//     sign(E) = sign(D) whenever |E| > fl(c P^) and
//       (1 - u)^2 (1 - gamma_2) c >= K;
//     c = 32 u^2 satisfies it (checked in rational arithmetic by
//     test/kernel/expansion_orientation_test.cpp).
//  2. Otherwise D exactly: (a b - c d) with the differences as 2-component
//     expansions, at most 16 components; its sign is that of the largest.
//
// Range: every coordinate 0 or of magnitude in [2^-400, 2^500]. Every value is
// then a multiple of q = 2^-452 and every product of two a multiple of
// q^2 = 2^-904, so every two_product is exact (its factors' lowest bits sum to
// >= -904 > -1074), every nonzero floating-point result of step 1 is normal
// (>= q^2; the bound c q^2 = 2^-1005), and nothing overflows: differences are
// below 2^501, products below 2^1003 (Dekker's range, error_free.h: factors
// below 2^995, products below 2^1020).
//
// It relies on round to nearest (ties to even) without FTZ/DAZ: callers run
// it in a Default_fp_environment. Measured against the distillation of 16
// error-free terms it replaces (VecSum passes until one term dominates):
// 3x faster on near-collinear input (doc/kernels.md).
#pragma once

#include <cmath>
#include <optional>
#include <utility>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/internal/error_free.h"
#include "relgeo/kernel/internal/expansion.h"

namespace relgeo::internal {

/// Whether v is 0 or 2^-400 <= |v| <= 2^500 (false for NaN and infinities):
/// the range of the orientation_2 expansion stage (see above).
inline bool in_expansion_range(double v) {
  const double a = std::abs(v);
  return a == 0 || (a >= 0x1p-400 && a <= 0x1p500);
}

/// The constant of step 1's error bound: c = 32 u^2.
struct Expansion_orientation_2_constants {
  static constexpr double u = 0x1p-53;
  static constexpr double c = 32 * u * u;
  static constexpr int terms = 5;  ///< N, the terms added by Sum2
};

/// Step 2: the exact sign of a b - c d from the split differences.
[[gnu::noinline]] inline Certified_sign exact_orientation_2_in_expansions(Two_terms a, Two_terms b, Two_terms c,
                                                                         Two_terms d) {
  return (Expansion<2>(a) * Expansion<2>(b) - Expansion<2>(c) * Expansion<2>(d)).sign();
}

/// The exact sign of orientation_2 of double points, and whether step 1
/// (true) or step 2 decided it; nullopt when a coordinate is outside
/// in_expansion_range.
inline std::optional<std::pair<Certified_sign, bool>> expansion_orientation_2_with_step(
    double px, double py, double qx, double qy, double rx, double ry) {
  bool in_range = true;
  for (double v : {px, py, qx, qy, rx, ry}) in_range &= in_expansion_range(v);
  if (!in_range) return std::nullopt;
  // The same formula as determinants.h: (qx - px)(ry - py) - (qy - py)(rx - px).
  const Two_terms a = two_diff(qx, px), b = two_diff(ry, py), c = two_diff(qy, py), d = two_diff(rx, px);
  const Two_terms ab = two_product(a.value, b.value), cd = two_product(c.value, d.value);
  const double t1 = (a.error * b.value + b.error * a.value) - (c.error * d.value + d.error * c.value);
  // Sum2 of t1, ab, -cd.
  const Two_terms s1 = two_sum(t1, ab.value);
  const Two_terms s2 = two_sum(s1.value, ab.error);
  const Two_terms s3 = two_sum(s2.value, -cd.value);
  const Two_terms s4 = two_sum(s3.value, -cd.error);
  const double estimate = s4.value + (((s1.error + s2.error) + s3.error) + s4.error);
  const double permanent = std::abs(a.value * b.value) + std::abs(c.value * d.value);
  if (std::abs(estimate) > Expansion_orientation_2_constants::c * permanent) [[likely]]
    return std::pair{estimate > 0 ? Certified_sign::positive : Certified_sign::negative, true};
  return std::pair{exact_orientation_2_in_expansions(a, b, c, d), false};
}

/// The exact sign of orientation_2 of double points in the range of
/// in_expansion_range, nullopt outside it.
inline std::optional<Certified_sign> expansion_orientation_2(double px, double py, double qx, double qy,
                                                             double rx, double ry) {
  const auto r = expansion_orientation_2_with_step(px, py, qx, qy, rx, ry);
  if (!r) return std::nullopt;
  return r->first;
}

}  // namespace relgeo::internal
