// relgeo/hull/internal/hull_input.h — what the hull algorithms read from their
// input: the coordinates of relgeo and CGAL points, the finiteness check, and
// which point types they handle as plain floating-point pairs.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <type_traits>

#include "relgeo/core/errors.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/kernel/point.h"

namespace relgeo::internal {

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

/// relgeo::Point_2<T> with T float, double or long double: points the hulls
/// compare and filter directly on their coordinates (finite values compare
/// exactly), without the kernel's functors.
template <class Point>
concept Floating_point_2 = requires(const Point& p) {
  requires std::is_floating_point_v<std::remove_cvref_t<decltype(p.x)>>;
  requires std::is_same_v<Point, relgeo::Point_2<std::remove_cvref_t<decltype(p.x)>>>;
};

}  // namespace relgeo::internal
