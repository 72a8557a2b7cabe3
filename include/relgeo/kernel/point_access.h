// relgeo/kernel/point_access.h — uniform coordinate access for the point
// types the algorithms read (beside the point types themselves, so every
// area reads points, and checks them finite, in one way).
//
// relgeo::Point_3<FT> has public members x, y, z; CGAL points (and any type
// with x(), y(), z() and a (FT, FT, FT) constructor) are read through the
// accessors. Coordinates are combined in the point's own number type FT.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <utility>

#include "relgeo/core/errors.h"
#include "relgeo/core/number_traits.h"
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

/// A coordinate as the nearest double (an interval's midpoint): the number
/// layer's nearest_double.
template <class FT>
double coordinate_to_double(const FT& v) {
  return nearest_double(v);
}

/// Whether a coordinate is finite: no NaN or infinity (an interval neither in
/// an endpoint); rationals and CGAL's exact types always are.
template <class FT>
bool coordinate_is_finite(const FT& v) {
  return is_finite_number(v);
}

template <class P>
bool point_is_finite(const P& p) {
  using A = Point_access<P>;
  return coordinate_is_finite(A::x(p)) && coordinate_is_finite(A::y(p)) &&
         coordinate_is_finite(A::z(p));
}

// Planar points (the hulls and their error measures).

/// x and y of a relgeo point (members) or a CGAL point (methods).
template <class P>
decltype(auto) coordinate_x(const P& p) {
  if constexpr (requires { p.x(); }) return p.x();
  else return (p.x);  // a reference: no copy of a rational
}
template <class P>
decltype(auto) coordinate_y(const P& p) {
  if constexpr (requires { p.y(); }) return p.y();
  else return (p.y);
}

/// Throws Non_finite_input naming the first point with a NaN or infinite
/// coordinate (in the number layer's sense: an interval with an infinite
/// endpoint, an MPFR NaN or infinity; rationals are always finite).
template <class Point>
void require_finite_points(std::span<const Point> points, const char* who) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!is_finite_number(coordinate_x(points[i])) || !is_finite_number(coordinate_y(points[i])))
      throw Non_finite_input(std::string(who) + ": point " + std::to_string(i) +
                             " has a NaN or infinite coordinate");
}

}  // namespace relgeo::internal
