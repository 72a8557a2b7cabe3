// relgeo/error/hull_error.h — the error E of eq. (3.2) of a computed hull.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/error/convex_polygon.h"

namespace relgeo {

/// The input points of a hull given as indices.
inline std::vector<Point_2<double>> points_at(std::span<const Point_2<double>> input,
                                              std::span<const std::size_t> indices) {
  std::vector<Point_2<double>> out;
  out.reserve(indices.size());
  for (std::size_t i : indices) {
    if (i >= input.size()) throw Invalid_input("hull index out of range");
    out.push_back(input[i]);
  }
  return out;
}

/// E(Y) of eq. (3.2) and what it was computed from.
struct Hull_error {
  /// The polygon Y, in the order returned, is simple, strictly convex and
  /// counterclockwise (is_ccw_strictly_convex_polygon, exact).
  bool convex = true;
  double value = 0;      ///< d(Y_true, Y) / M rounded upward; +inf when !convex
  double coordinate_bound = 0;  ///< M
};

/// E(Y) = d(Y_true, Y) / M for the hull `hull_indices` computed from `input`:
/// Y is the polygon those indices list, in that order (a user reads a hull as
/// a counterclockwise polygon, so it is judged as one). E is infinite when Y
/// is not a simple, strictly convex, counterclockwise polygon (a right vertex
/// set in a wrong order included), otherwise the Hausdorff distance between
/// the exact hull of the input and Y, over M = max |coordinate|. All
/// predicates exact; the value is rounded upward. E = 0 when M = 0.
/// \throws Non_finite_input for a NaN or infinite input coordinate,
/// Invalid_input for an index out of range.
inline Hull_error hull_error(std::span<const Point_2<double>> input,
                             std::span<const std::size_t> hull_indices) {
  const Default_fp_environment environment;
  internal::require_finite(input, "hull_error");
  Hull_error e;
  e.coordinate_bound = coordinate_bound(input);
  const std::vector<Point_2<double>> y = points_at(input, hull_indices);
  e.convex = is_ccw_strictly_convex_polygon(y);
  if (!e.convex) {
    e.value = std::numeric_limits<double>::infinity();
    return e;
  }
  if (e.coordinate_bound == 0) return e;
  e.value = hausdorff_distance(exact_hull(input), y, e.coordinate_bound);
  return e;
}

}  // namespace relgeo
