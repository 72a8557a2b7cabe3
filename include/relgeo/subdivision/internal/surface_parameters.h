// relgeo/subdivision/internal/surface_parameters.h — the parameters (u, v)
// of a face: the closed triangle, the child of local subdivision holding a
// point and its parameters there (exact rationals), and their rounding into
// the kernel's number type.
#pragma once

#include <gmpxx.h>

#include "relgeo/core/number_traits.h"
#include "relgeo/core/rounding.h"
#include "relgeo/subdivision/box_spline.h"

namespace relgeo::internal {

/// FT from an exact rational (parameters), rounded once: to nearest for
/// floating types and MPFR, exact for mpq_class, the tightest enclosure for
/// intervals (Number_traits<FT>::from_rational); number types the layer
/// cannot round to (CGAL's) get the nearest double.
template <class FT>
FT ft_from_rational(const mpq_class& q) {
  if constexpr (Number_traits<FT>::kind == Number_kind::other)
    return FT(round_rational<double>(q, Rounding::to_nearest));
  else
    return Number_traits<FT>::from_rational(q, Rounding::to_nearest);
}

/// Whether the closed triangle u, v >= 0, u + v <= 1 contains (u, v), decided
/// exactly for doubles (TwoSum).
inline bool in_parameter_triangle(double u, double v) {
  if (!(u >= 0 && v >= 0)) return false;
  const double s = u + v;
  const double bv = s - u, err = (u - (s - bv)) + (v - bv);  // u + v = s + err exactly
  return s < 1 || (s == 1 && err <= 0);
}

/// The child (box_spline.h numbering) of a face holding the point (u, v),
/// and (u, v) replaced by the point's parameters in that child:
/// c = 0 when w >= 1/2, 1 when u >= 1/2, 2 when v >= 1/2, else 3.
inline int descend_to_child(mpq_class& u, mpq_class& v) {
  const mpq_class half(1, 2), one(1);
  const mpq_class w = one - u - v;
  int c;
  mpq_class nu, nv;
  if (w >= half) c = 0, nu = 2 * u, nv = 2 * v;
  else if (u >= half) c = 1, nu = 2 * v, nv = 2 * w;
  else if (v >= half) c = 2, nu = 2 * w, nv = 2 * u;
  else c = 3, nu = one - 2 * w, nv = one - 2 * u;
  u = std::move(nu), v = std::move(nv);
  return c;
}

/// J <- d(child parameters) / d(parent parameters) J for child c
/// (loop_child_jacobian), J = d(s, t) / d(u0, v0) of the current patch.
template <class FT>
void descend_jacobian(FT (&J)[2][2], int c) {
  FT N[2][2];
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < 2; ++k)
      N[r][k] = FT(FT(FT(loop_child_jacobian[c][r][0]) * J[0][k]) + FT(FT(loop_child_jacobian[c][r][1]) * J[1][k]));
  for (int r = 0; r < 2; ++r)
    for (int k = 0; k < 2; ++k) J[r][k] = N[r][k];
}

}  // namespace relgeo::internal
