// relgeo/subdivision/internal/point_algebra.h — the few vector operations the
// subdivision area performs on Point_3<FT>, coordinate-wise in FT, each
// intermediate converted back to FT (expression-template number types such as
// mpq_class evaluate exactly these operations, in this order).
#pragma once

#include "relgeo/kernel/point.h"

namespace relgeo::internal {

template <class FT>
Point_3<FT> point_sum(const Point_3<FT>& p, const Point_3<FT>& q) {
  return {FT(p.x + q.x), FT(p.y + q.y), FT(p.z + q.z)};
}
template <class FT>
Point_3<FT> point_difference(const Point_3<FT>& p, const Point_3<FT>& q) {
  return {FT(p.x - q.x), FT(p.y - q.y), FT(p.z - q.z)};
}
/// a += p.
template <class FT>
void accumulate_point(Point_3<FT>& a, const Point_3<FT>& p) {
  a.x = FT(a.x + p.x), a.y = FT(a.y + p.y), a.z = FT(a.z + p.z);
}
/// w p.
template <class FT>
Point_3<FT> point_scale(const FT& w, const Point_3<FT>& p) {
  return {FT(w * p.x), FT(w * p.y), FT(w * p.z)};
}
/// w1 p + w2 q.
template <class FT>
Point_3<FT> point_combination(const FT& w1, const Point_3<FT>& p, const FT& w2, const Point_3<FT>& q) {
  return {FT(FT(w1 * p.x) + FT(w2 * q.x)), FT(FT(w1 * p.y) + FT(w2 * q.y)), FT(FT(w1 * p.z) + FT(w2 * q.z))};
}
template <class FT>
FT point_dot(const Point_3<FT>& a, const Point_3<FT>& b) {
  return FT(FT(FT(a.x * b.x) + FT(a.y * b.y)) + FT(a.z * b.z));
}
template <class FT>
Point_3<FT> point_cross(const Point_3<FT>& a, const Point_3<FT>& b) {
  return {FT(FT(a.y * b.z) - FT(a.z * b.y)), FT(FT(a.z * b.x) - FT(a.x * b.z)), FT(FT(a.x * b.y) - FT(a.y * b.x))};
}

}  // namespace relgeo::internal
