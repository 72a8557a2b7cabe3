// relgeo/kernel/internal/exact_dyadic.h — the orientation determinants of
// double points (determinants.h) as formulas of the generic filtered
// predicate (filtered_predicate.h), used by Filtered_exact_kernel after its
// specialised stages, and their exact signs in GMP integers (that
// predicate's last stage alone): the reference of the specialised expansion
// stages' tests.
#pragma once

#include <array>

#include "relgeo/core/certified_sign.h"
#include "relgeo/kernel/internal/determinants.h"
#include "relgeo/kernel/internal/filtered_predicate.h"

namespace relgeo::internal {

/// The sign of orientation_2 of (c[0], c[1]), (c[2], c[3]), (c[4], c[5]),
/// evaluated through `to`, the conversion of a coordinate to a stage's
/// number type. `c` must outlive the formula.
inline auto orientation_2_formula(const std::array<double, 6>& c) {
  return [&c](const auto& to) {
    return certified_sign_of(orientation_2_determinant(to(c[0]), to(c[1]), to(c[2]), to(c[3]), to(c[4]), to(c[5])));
  };
}

/// The sign of orientation_3 of the points (c[0], c[1], c[2]) ... (c[9],
/// c[10], c[11]), as orientation_2_formula.
inline auto orientation_3_formula(const std::array<double, 12>& c) {
  return [&c](const auto& to) {
    return certified_sign_of(orientation_3_determinant(to(c[0]), to(c[1]), to(c[2]), to(c[3]), to(c[4]), to(c[5]),
                                                       to(c[6]), to(c[7]), to(c[8]), to(c[9]), to(c[10]), to(c[11])));
  };
}

/// Exact sign of orientation_2 of double points. \pre all coordinates finite.
inline Certified_sign exact_orientation_2(double px, double py, double qx, double qy, double rx, double ry) {
  const std::array<double, 6> c{px, py, qx, qy, rx, ry};
  return integer_sign(c, orientation_2_formula(c));
}

/// Exact sign of orientation_3 of double points. \pre all coordinates finite.
inline Certified_sign exact_orientation_3(const std::array<double, 12>& c) {
  return integer_sign(c, orientation_3_formula(c));
}

}  // namespace relgeo::internal
