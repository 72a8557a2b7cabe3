// relgeo/mesh/internal/kernel_points.h — a mesh's vertices as points of the
// kernel that decides predicates on them, and whether that was exact.
#pragma once

#include <span>
#include <type_traits>
#include <vector>

#include "relgeo/core/number_traits.h"
#include "relgeo/kernel/point_access.h"

namespace relgeo::internal {

/// The vertices as K::Point_3: a view when the mesh already stores them,
/// otherwise converted through the nearest double of each coordinate.
/// `exact` says whether every converted point has the mesh's coordinates
/// exactly (always for double input and kernels over doubles, rationals,
/// intervals or MPFR; not for rational input rounded to a double kernel).
/// \pre finite coordinates (the conversion of NaN is kernel-defined).
template <class K, class P>
class Kernel_points {
 public:
  using Point = typename K::Point_3;

  Kernel_points(const std::vector<P>& vertices, const K& k) {
    if constexpr (std::is_same_v<P, Point>) {
      view_ = vertices;
    } else {
      using A = Point_access<P>;
      const auto make = k.construct_point_3_object();
      storage_.reserve(vertices.size());
      for (const P& p : vertices) {
        const double x = nearest_double(A::x(p)), y = nearest_double(A::y(p)), z = nearest_double(A::z(p));
        using B = Point_access<Point>;
        storage_.push_back(make(x, y, z));
        const Point& q = storage_.back();
        exact_ = exact_ && holds(A::x(p), x) && holds(A::y(p), y) && holds(A::z(p), z) && holds(B::x(q), x) &&
                 holds(B::y(q), y) && holds(B::z(q), z);
      }
      view_ = storage_;
    }
  }
  Kernel_points(const Kernel_points&) = delete;
  Kernel_points& operator=(const Kernel_points&) = delete;

  const Point& operator[](std::size_t i) const { return view_[i]; }
  std::size_t size() const { return view_.size(); }
  bool exact() const { return exact_; }

 private:
  // v is exactly the double d.
  template <class T>
  static bool holds(const T& v, double d) {
    return lower_double(v) == d && upper_double(v) == d;
  }
  std::vector<Point> storage_;
  std::span<const Point> view_;
  bool exact_ = true;
};

}  // namespace relgeo::internal
