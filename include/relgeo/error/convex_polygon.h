// relgeo/error/convex_polygon.h — exact geometry of convex polygons with
// double vertices: exact hull, point location, distances rounded upward.
// The ground truth every error measure of relgeo is computed with.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "relgeo/core/dyadic.h"
#include "relgeo/core/errors.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/core/rounding.h"
#include "relgeo/hull/monotone_chain.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/point.h"
#include "relgeo/kernel/point_access.h"

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

namespace internal {

/// Throws Non_finite_input naming `who` when a point has a NaN or infinite
/// coordinate (the hulls' input check).
inline void require_finite(std::span<const Point_2<double>> points, const char* who) {
  require_finite_points<Point_2<double>>(points, who);
}

/// The exact orientation of three finite points (never `uncertain`: the
/// filtered kernel decides every finite case; a non-finite one throws).
inline Certified_sign exact_orientation(const Point_2<double>& a, const Point_2<double>& b,
                                        const Point_2<double>& c) {
  const Certified_sign s = Filtered_exact_kernel{}.orientation_2_object()(a, b, c);
  if (!is_certain(s)) throw Non_finite_input("exact geometry: a coordinate is NaN or infinite");
  return s;
}

/// a < b lexicographically (finite points: exact).
inline bool lexicographically_less(const Point_2<double>& a, const Point_2<double>& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

}  // namespace internal

/// \brief Whether the cyclic sequence `poly`, read as the polygon it lists, is
/// simple, strictly convex at every vertex and winds once counterclockwise
/// (CGAL's is_ccw_strongly_convex_2), decided exactly.
///
/// A polygon all of whose turns are strict left turns (each in (0, pi)) is
/// convex and simple iff its edge direction turns by 2 pi in all, i.e. iff it
/// has exactly one lexicographic local minimum (a polygon winding k times has
/// k). So the right vertex set in a wrong order is not convex. Degenerate
/// hulls count as convex: no vertex, one vertex, or two different vertices (a
/// segment). \throws Non_finite_input for a NaN or infinite coordinate.
inline bool is_ccw_strictly_convex_polygon(std::span<const Point_2<double>> poly) {
  internal::require_finite(poly, "is_ccw_strictly_convex_polygon");
  const std::size_t h = poly.size();
  if (h <= 1) return true;
  if (h == 2) return !(poly[0] == poly[1]);
  std::size_t local_minima = 0;
  for (std::size_t i = 0; i < h; ++i) {
    const Point_2<double>& a = poly[(i + h - 1) % h];
    const Point_2<double>& b = poly[i];
    const Point_2<double>& c = poly[(i + 1) % h];
    if (!certainly(internal::exact_orientation(a, b, c), Certified_sign::positive)) return false;
    local_minima += internal::lexicographically_less(b, a) && internal::lexicographically_less(b, c);
  }
  return local_minima == 1;
}

/// Exact location of p with respect to the strictly convex counterclockwise
/// polygon `poly` (1 or 2 vertices: a point or a segment, whose points are
/// `boundary`). O(log h) exact orientation tests.
/// \pre is_ccw_strictly_convex_polygon(poly).
/// \throws Non_finite_input when p or a vertex it meets is not finite.
inline Polygon_side locate(std::span<const Point_2<double>> poly, const Point_2<double>& p) {
  using internal::exact_orientation;
  if (!all_finite(p.x, p.y)) throw Non_finite_input("locate: the point has a NaN or infinite coordinate");
  const std::size_t h = poly.size();
  if (h == 0) return Polygon_side::outside;
  if (h <= 2) internal::require_finite(poly, "locate");
  if (h == 1) return poly[0] == p ? Polygon_side::boundary : Polygon_side::outside;
  if (h == 2) {
    if (!certainly(exact_orientation(poly[0], poly[1], p), Certified_sign::zero)) return Polygon_side::outside;
    const bool between = std::min(poly[0].x, poly[1].x) <= p.x && p.x <= std::max(poly[0].x, poly[1].x) &&
                         std::min(poly[0].y, poly[1].y) <= p.y && p.y <= std::max(poly[0].y, poly[1].y);
    return between ? Polygon_side::boundary : Polygon_side::outside;
  }
  // Fan from poly[0]: find the wedge (poly[i], poly[i+1]) containing p.
  const Certified_sign first = exact_orientation(poly[0], poly[1], p);
  const Certified_sign last = exact_orientation(poly[0], poly[h - 1], p);
  if (certainly(first, Certified_sign::negative) || certainly(last, Certified_sign::positive))
    return Polygon_side::outside;
  std::size_t lo = 1, hi = h - 1;  // invariant: p left of or on poly0->poly[lo], right of or on poly0->poly[hi]
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    if (certainly(exact_orientation(poly[0], poly[mid], p), Certified_sign::negative))
      hi = mid;
    else lo = mid;
  }
  const Certified_sign edge = exact_orientation(poly[lo], poly[hi], p);
  if (certainly(edge, Certified_sign::negative)) return Polygon_side::outside;
  if (certainly(edge, Certified_sign::zero)) return Polygon_side::boundary;
  if ((lo == 1 && certainly(first, Certified_sign::zero)) || (hi == h - 1 && certainly(last, Certified_sign::zero)))
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

namespace internal {

/// The distance sqrt(squared) / scale as the error measures report it: a
/// distance relative to the coordinate bound M, computed exactly and rounded
/// upward once (256-bit square root of the exact quotient).
/// \throws Invalid_input when scale is not positive and finite.
inline double relative_distance(const mpq_class& squared, double scale, const char* who) {
  if (!(scale > 0) || !std::isfinite(scale))
    throw Invalid_input(std::string(who) + ": the scale must be positive and finite");
  const mpq_class s = exact_rational(scale);
  return sqrt_rational(squared / (s * s), Rounding::upward, 256);
}

}  // namespace internal

/// Hausdorff distance between the convex hulls of two vertex sets, exactly,
/// divided by `scale` and rounded upward. For convex sets the largest distance
/// from one to the other is attained at a vertex.
/// \throws Non_finite_input for a NaN or infinite coordinate, Invalid_input
/// when scale is not positive and finite.
inline double hausdorff_distance(std::span<const Point_2<double>> a_hull,
                                 std::span<const Point_2<double>> b_hull, double scale = 1.0) {
  internal::require_finite(a_hull, "hausdorff_distance");
  internal::require_finite(b_hull, "hausdorff_distance");
  if (a_hull.empty() != b_hull.empty()) return std::numeric_limits<double>::infinity();
  if (a_hull.empty()) return 0.0;
  mpq_class worst = 0;
  for (const auto& v : a_hull) worst = std::max(worst, squared_distance(b_hull, v));
  for (const auto& v : b_hull) worst = std::max(worst, squared_distance(a_hull, v));
  return internal::relative_distance(worst, scale, "hausdorff_distance");
}

/// M of eq. (3.2): the largest |coordinate| of the input (0 for no points).
inline double coordinate_bound(std::span<const Point_2<double>> points) {
  double m = 0;
  for (const auto& p : points) m = std::max({m, std::abs(p.x), std::abs(p.y)});
  return m;
}

}  // namespace relgeo
