// relgeo/kernel/point.h — the plain point types of relgeo's own kernels.
//
// Aggregates with public coordinates: cheap to copy for float types and usable
// with any number type (intervals, GMP rationals, MPFR). CGAL points are used
// as they are through Cgal_kernel.
#pragma once

namespace relgeo {

template <class FT>
struct Point_2 {
  FT x{}, y{};
  friend bool operator==(const Point_2&, const Point_2&) = default;
};

template <class FT>
struct Point_3 {
  FT x{}, y{}, z{};
  friend bool operator==(const Point_3&, const Point_3&) = default;
};

/// Coordinate `axis` of p (0: x, 1: y, 2: z).
template <class FT>
const FT& coordinate(const Point_3<FT>& p, int axis) {
  return axis == 0 ? p.x : (axis == 1 ? p.y : p.z);
}

}  // namespace relgeo
