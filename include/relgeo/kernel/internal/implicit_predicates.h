// relgeo/kernel/internal/implicit_predicates.h — the signs of the predicates
// on homogeneous points, for any number type that can report a certified
// sign (Filtered_value, Interval, expansions, GMP integers, rationals).
//
// Each predicate finds an explicit point to pivot on (the cheaper formula of
// implicit_coordinates.h), reorders the arguments with the sign of the
// permutation, evaluates the determinant and multiplies by the signs of the
// W's. `uncertain` as soon as one of those signs is.
#pragma once

#include <gmpxx.h>

#include <array>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/interval.h"
#include "relgeo/kernel/internal/filtered_predicate.h"
#include "relgeo/kernel/internal/filtered_value.h"
#include "relgeo/kernel/internal/implicit_coordinates.h"

namespace relgeo::internal {

template <class T>
Certified_sign certified_sign_of(const Filtered_value<T>& v) {
  return v.sign();
}

template <class NT>
Certified_sign sign_of_w(const Homogeneous_3<NT>& h) {
  return h.unit ? Certified_sign::positive : certified_sign_of(h.w);
}

template <class NT>
Point_3<NT> cartesian(const Homogeneous_3<NT>& h) {
  return {h.x, h.y, h.z};
}

/// Sign of the orientation of four points (positive when the fourth lies on
/// the positive side of the plane of the first three, as orientation_3).
template <class NT>
Certified_sign orientation_3_sign(const std::array<const Homogeneous_3<NT>*, 4>& h) {
  int pivot = 0;
  while (pivot < 4 && !h[pivot]->unit) ++pivot;
  if (pivot == 4) {
    Certified_sign s = certified_sign_of(orientation_3_homogeneous(h));
    for (const auto* p : h) s = s * sign_of_w(*p);
    return s;
  }
  // Moving the pivot to the front is `pivot` transpositions.
  std::array<const Homogeneous_3<NT>*, 3> rest{};
  for (int i = 0, k = 0; i < 4; ++i)
    if (i != pivot) rest[k++] = h[i];
  Certified_sign s = certified_sign_of(orientation_3_with_pivot(cartesian(*h[pivot]), *rest[0], *rest[1], *rest[2]));
  if (pivot % 2 == 1) s = -s;
  for (const auto* p : rest) s = s * sign_of_w(*p);
  return s;
}

/// Sign of the orientation of the projections of three points dropping
/// `axis` (kept axes (axis + 1) % 3, (axis + 2) % 3).
template <class NT>
Certified_sign orientation_2_sign(const std::array<const Homogeneous_3<NT>*, 3>& h, int axis) {
  int pivot = 0;
  while (pivot < 3 && !h[pivot]->unit) ++pivot;
  if (pivot == 3) {
    Certified_sign s = certified_sign_of(orientation_2_homogeneous(h, axis));
    for (const auto* p : h) s = s * sign_of_w(*p);
    return s;
  }
  // A cyclic rotation keeps the orientation of three points.
  const auto& b = *h[(pivot + 1) % 3];
  const auto& c = *h[(pivot + 2) % 3];
  return certified_sign_of(orientation_2_with_pivot(cartesian(*h[pivot]), b, c, axis)) * sign_of_w(b) *
         sign_of_w(c);
}

/// Sign of a's minus b's coordinate along `axis`.
template <class NT>
Certified_sign compare_coordinate_sign(const Homogeneous_3<NT>& a, const Homogeneous_3<NT>& b, int axis) {
  return certified_sign_of(coordinate_difference(a, b, axis)) * sign_of_w(a) * sign_of_w(b);
}

/// Lexicographic comparison of (x, y, z).
template <class NT>
Certified_sign compare_xyz_sign(const Homogeneous_3<NT>& a, const Homogeneous_3<NT>& b) {
  for (int axis = 0; axis < 3; ++axis) {
    const Certified_sign s = compare_coordinate_sign(a, b, axis);
    if (!certainly(s, Certified_sign::zero)) return s;
  }
  return Certified_sign::zero;
}

}  // namespace relgeo::internal
