// relgeo/error/convex_polygon.h — exact geometry of convex polygons with
// double vertices: exact hull, point location, distances rounded upward.
// The ground truth every error measure of relgeo is computed with.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "relgeo/hull/monotone_chain.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/point.h"

namespace relgeo {

/// Where a point lies with respect to a convex polygon.
enum class Polygon_side { inside, boundary, outside };

/// The exact convex hull of double points: strictly convex, counterclockwise,
/// starting at the lexicographically smallest vertex (1 or 2 vertices for
/// degenerate input).
inline std::vector<Point_2<double>> exact_hull(std::span<const Point_2<double>> points) {
  return monotone_chain<Filtered_exact_kernel>(points).points;
}

namespace internal {

inline mpq_class squared_distance_to_segment(const Point_2<double>& p, const Point_2<double>& a,
                                             const Point_2<double>& b) {
  const mpq_class px(p.x), py(p.y), ax(a.x), ay(a.y);
  const mpq_class dx = mpq_class(b.x) - ax, dy = mpq_class(b.y) - ay;
  const mpq_class wx = px - ax, wy = py - ay;
  const mpq_class len2 = dx * dx + dy * dy;
  const mpq_class dot = wx * dx + wy * dy;
  if (len2 == 0 || dot <= 0) return wx * wx + wy * wy;
  if (dot >= len2) {
    const mpq_class ex = px - mpq_class(b.x), ey = py - mpq_class(b.y);
    return ex * ex + ey * ey;
  }
  const mpq_class cross = wx * dy - wy * dx;  // distance^2 = cross^2 / len2
  return cross * cross / len2;
}

}  // namespace internal

/// Exact location of p with respect to the strictly convex counterclockwise
/// polygon `poly` (1 or 2 vertices: a point or a segment, whose points are
/// `boundary`). O(log h) exact orientation tests.
inline Polygon_side locate(std::span<const Point_2<double>> poly, const Point_2<double>& p) {
  const Filtered_exact_kernel k;
  const auto o = k.orientation_2_object();
  const std::size_t h = poly.size();
  if (h == 0) return Polygon_side::outside;
  if (h == 1) return poly[0] == p ? Polygon_side::boundary : Polygon_side::outside;
  if (h == 2) {
    if (o(poly[0], poly[1], p) != Certified_sign::zero) return Polygon_side::outside;
    const bool between = std::min(poly[0].x, poly[1].x) <= p.x && p.x <= std::max(poly[0].x, poly[1].x) &&
                         std::min(poly[0].y, poly[1].y) <= p.y && p.y <= std::max(poly[0].y, poly[1].y);
    return between ? Polygon_side::boundary : Polygon_side::outside;
  }
  // Fan from poly[0]: find the wedge (poly[i], poly[i+1]) containing p.
  const Certified_sign first = o(poly[0], poly[1], p), last = o(poly[0], poly[h - 1], p);
  if (first == Certified_sign::negative || last == Certified_sign::positive) return Polygon_side::outside;
  std::size_t lo = 1, hi = h - 1;  // invariant: p left of or on poly0->poly[lo], right of or on poly0->poly[hi]
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    if (o(poly[0], poly[mid], p) == Certified_sign::negative) hi = mid;
    else lo = mid;
  }
  const Certified_sign edge = o(poly[lo], poly[hi], p);
  if (edge == Certified_sign::negative) return Polygon_side::outside;
  if (edge == Certified_sign::zero) return Polygon_side::boundary;
  if ((lo == 1 && first == Certified_sign::zero) || (hi == h - 1 && last == Certified_sign::zero))
    return Polygon_side::boundary;  // on the first or the last edge through poly[0]
  return Polygon_side::inside;
}

/// Exact squared distance from p to the convex polygon (0 inside or on it).
inline mpq_class squared_distance(std::span<const Point_2<double>> poly, const Point_2<double>& p) {
  if (poly.empty()) throw Invalid_input("squared_distance: empty polygon");
  if (locate(poly, p) != Polygon_side::outside) return 0;
  if (poly.size() == 1) return internal::squared_distance_to_segment(p, poly[0], poly[0]);
  mpq_class best = internal::squared_distance_to_segment(p, poly[0], poly[1]);
  for (std::size_t i = 1; i < poly.size(); ++i) {
    mpq_class d = internal::squared_distance_to_segment(p, poly[i], poly[(i + 1) % poly.size()]);
    if (d < best) best = std::move(d);
  }
  return best;
}

/// sqrt(q / scale^2) rounded upward to a double (scale > 0): a distance divided
/// by the coordinate bound M, as the error measures report it.
inline double sqrt_ratio_up(const mpq_class& q, double scale = 1.0) {
  mpfr_t v;
  mpfr_init2(v, 256);
  mpfr_set_q(v, q.get_mpq_t(), MPFR_RNDU);
  mpfr_sqrt(v, v, MPFR_RNDU);
  mpfr_div_d(v, v, scale, MPFR_RNDU);
  const double d = mpfr_get_d(v, MPFR_RNDU);
  mpfr_clear(v);
  return d;
}

/// Hausdorff distance between the convex hulls of two vertex sets, exactly,
/// divided by `scale` and rounded upward. For convex sets the largest distance
/// from one to the other is attained at a vertex.
inline double hausdorff_distance(std::span<const Point_2<double>> a_hull,
                                 std::span<const Point_2<double>> b_hull, double scale = 1.0) {
  if (a_hull.empty() != b_hull.empty()) return std::numeric_limits<double>::infinity();
  if (a_hull.empty()) return 0.0;
  mpq_class worst = 0;
  for (const auto& v : a_hull) worst = std::max(worst, squared_distance(b_hull, v));
  for (const auto& v : b_hull) worst = std::max(worst, squared_distance(a_hull, v));
  return sqrt_ratio_up(worst, scale);
}

/// M of eq. (3.2): the largest |coordinate| of the input (0 for no points).
inline double coordinate_bound(std::span<const Point_2<double>> points) {
  double m = 0;
  for (const auto& p : points) m = std::max({m, std::abs(p.x), std::abs(p.y)});
  return m;
}

}  // namespace relgeo
