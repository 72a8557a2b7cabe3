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

}  // namespace relgeo
