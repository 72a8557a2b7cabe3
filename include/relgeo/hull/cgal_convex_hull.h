// relgeo/hull/cgal_convex_hull.h — CGAL's planar hull algorithms as peers,
// returning relgeo's Hull_result (needs relgeo::cgal).
#pragma once

#include <CGAL/ch_graham_andrew.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <iterator>
#include <numeric>
#include <span>
#include <vector>

#include "relgeo/hull/hull_result.h"
#include "relgeo/hull/internal/hull_frame.h"
#include "relgeo/hull/internal/hull_input.h"
#include "relgeo/kernel/cgal_kernel.h"

namespace relgeo {

/// Which CGAL function computes the hull.
enum class Cgal_hull_algorithm {
  convex_hull_2,   ///< CGAL::convex_hull_2 (Akl-Toussaint + Bykat by default)
  graham_andrew    ///< CGAL::ch_graham_andrew (Andrew's variant of Graham's scan)
};

/// \brief CGAL's planar convex hull of `points` with CGAL kernel CK, mapped
/// back to input indices (the smallest index among equal points) and rotated
/// to relgeo's output convention. A peer for tests and benchmarks.
/// \throws Non_finite_input if a coordinate is NaN or infinite.
template <class CK>
Hull_result<typename CK::Point_2> cgal_convex_hull(std::span<const typename CK::Point_2> points,
                                                   Cgal_hull_algorithm algorithm = Cgal_hull_algorithm::convex_hull_2,
                                                   const Cgal_kernel<CK>& k = {}) {
  using Point = typename CK::Point_2;
  internal::require_finite_points<Point>(points, "cgal_convex_hull");
  Hull_result<Point> r;
  std::vector<Point> out;
  if (algorithm == Cgal_hull_algorithm::graham_andrew)
    CGAL::ch_graham_andrew(points.begin(), points.end(), std::back_inserter(out), CK());
  else
    CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(out), CK());
  // Map points back to indices: lexicographically sorted indices, ties by index.
  std::vector<std::size_t> sorted(points.size());
  std::iota(sorted.begin(), sorted.end(), std::size_t{0});
  const auto less = typename CK::Less_xy_2();
  std::stable_sort(sorted.begin(), sorted.end(),
                   [&](std::size_t a, std::size_t b) { return less(points[a], points[b]); });
  for (const Point& p : out) {
    const auto it = std::lower_bound(sorted.begin(), sorted.end(), p,
                                     [&](std::size_t i, const Point& q) { return less(points[i], q); });
    r.indices.push_back(*it);
  }
  internal::rotate_to_smallest(r.indices, points, k);
  internal::attach_points(r, points);
  return r;
}

}  // namespace relgeo
