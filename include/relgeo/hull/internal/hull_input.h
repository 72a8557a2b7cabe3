// relgeo/hull/internal/hull_input.h — which point types the hull algorithms
// handle as plain floating-point pairs. (The coordinates of relgeo and CGAL
// points and the finiteness check of the input: relgeo/kernel/point_access.h.)
#pragma once

#include <type_traits>

#include "relgeo/kernel/point.h"
#include "relgeo/kernel/point_access.h"

namespace relgeo::internal {

/// relgeo::Point_2<T> with T float, double or long double: points the hulls
/// compare and filter directly on their coordinates (finite values compare
/// exactly), without the kernel's functors.
template <class Point>
concept Floating_point_2 = requires(const Point& p) {
  requires std::is_floating_point_v<std::remove_cvref_t<decltype(p.x)>>;
  requires std::is_same_v<Point, relgeo::Point_2<std::remove_cvref_t<decltype(p.x)>>>;
};

}  // namespace relgeo::internal
