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
/// c = 0 when w >= 1/2: (2u, 2v); 1 when u >= 1/2: (2v, 2w); 2 when
/// v >= 1/2: (2w, 2u); else 3: (1 - 2w, 1 - 2u). In place, without
/// temporaries (this runs at every level of a descent).
inline int descend_to_child(mpq_class& u, mpq_class& v) {
  const mpq_class w = 1 - u - v;
  const auto half_or_more = [](const mpq_class& x) { return mpq_cmp_ui(x.get_mpq_t(), 1, 2) >= 0; };
  const auto twice = [](mpq_class& out, const mpq_class& x) { mpq_mul_2exp(out.get_mpq_t(), x.get_mpq_t(), 1); };
  if (half_or_more(w)) {
    twice(u, u), twice(v, v);
    return 0;
  }
  if (half_or_more(u)) {
    twice(u, v), twice(v, w);
    return 1;
  }
  if (half_or_more(v)) {
    twice(v, u), twice(u, w);
    return 2;
  }
  twice(v, u), v = 1 - v;
  twice(u, w), u = 1 - u;
  return 3;
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
