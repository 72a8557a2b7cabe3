// relgeo/mesh/internal/point_access.h — uniform coordinate access for the point
// types the mesh and subdivision code work on.
//
// relgeo::Point_3<FT> has public members x, y, z; CGAL points (and any type
// with x(), y(), z() and a (FT, FT, FT) constructor) are read through the
// accessors. Coordinates are combined in the point's own number type FT.
#pragma once

#include <cmath>
#include <type_traits>

#include "relgeo/kernel/point.h"

namespace relgeo::internal {

template <class P>
struct Point_access;

/// relgeo's aggregate point.
template <class FT_>
struct Point_access<Point_3<FT_>> {
  using FT = FT_;
  static const FT& x(const Point_3<FT>& p) { return p.x; }
  static const FT& y(const Point_3<FT>& p) { return p.y; }
  static const FT& z(const Point_3<FT>& p) { return p.z; }
  static Point_3<FT> make(FT x, FT y, FT z) { return Point_3<FT>{std::move(x), std::move(y), std::move(z)}; }
};

/// Any point with x(), y(), z() accessors and a 3-argument constructor (CGAL).
template <class P>
  requires requires(const P& p) { p.x(); p.y(); p.z(); }
struct Point_access<P> {
  using FT = std::remove_cvref_t<decltype(std::declval<const P&>().x())>;
  static FT x(const P& p) { return p.x(); }
  static FT y(const P& p) { return p.y(); }
  static FT z(const P& p) { return p.z(); }
  static P make(const FT& x, const FT& y, const FT& z) { return P(x, y, z); }
};

/// Conversion of a coordinate to double: exact types round to nearest,
/// intervals give their midpoint.
template <class FT>
double coordinate_to_double(const FT& v) {
  if constexpr (std::is_arithmetic_v<FT>) return static_cast<double>(v);
  else if constexpr (requires { v.inf(); v.sup(); }) return 0.5 * v.inf() + 0.5 * v.sup();
  else if constexpr (requires { v.get_d(); }) return v.get_d();
  else if constexpr (requires { v.to_double(); }) return v.to_double();
  else return to_double(v);  // found by ADL (CGAL::to_double for CGAL number types)
}

/// Whether a coordinate is finite (NaN and infinities are not; exact and
/// MPFR values are finite unless their own NaN test says otherwise).
template <class FT>
bool coordinate_is_finite(const FT& v) {
  if constexpr (std::is_floating_point_v<FT>) return std::isfinite(v);
  else if constexpr (requires { v.inf(); v.sup(); }) return std::isfinite(v.inf()) && std::isfinite(v.sup());
  else if constexpr (requires { v.is_nan(); }) return !v.is_nan();
  else return true;
}

template <class P>
bool point_is_finite(const P& p) {
  using A = Point_access<P>;
  return coordinate_is_finite(A::x(p)) && coordinate_is_finite(A::y(p)) &&
         coordinate_is_finite(A::z(p));
}

}  // namespace relgeo::internal
