// relgeo/kernel/internal/exact_dyadic.h — the exact signs of the orientation
// determinants of double points in GMP integers: the last stage of the
// generic filtered predicate (filtered_predicate.h) on the formulas of
// determinants.h, alone. The reference of the specialised expansion stages'
// tests.
#pragma once

#include <array>

#include "relgeo/core/certified_sign.h"
#include "relgeo/kernel/internal/determinants.h"
#include "relgeo/kernel/internal/filtered_predicate.h"

namespace relgeo::internal {

/// Exact sign of orientation_2 of double points. \pre all coordinates finite.
inline Certified_sign exact_orientation_2(double px, double py, double qx, double qy, double rx, double ry) {
  const std::array<double, 6> c{px, py, qx, qy, rx, ry};
  return integer_sign(c, [&c](const auto& to) {
    return certified_sign_of(orientation_2_determinant(to(c[0]), to(c[1]), to(c[2]), to(c[3]), to(c[4]), to(c[5])));
  });
}

/// Exact sign of orientation_3 of double points. \pre all coordinates finite.
inline Certified_sign exact_orientation_3(const std::array<double, 12>& c) {
  return integer_sign(c, [&c](const auto& to) {
    return certified_sign_of(orientation_3_determinant(to(c[0]), to(c[1]), to(c[2]), to(c[3]), to(c[4]), to(c[5]),
                                                       to(c[6]), to(c[7]), to(c[8]), to(c[9]), to(c[10]), to(c[11])));
  });
}

}  // namespace relgeo::internal
