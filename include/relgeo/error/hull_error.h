// relgeo/error/hull_error.h — the error E of eq. (3.2) of a computed hull.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "relgeo/core/errors.h"
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

/// True when every point of Y lies on the boundary of conv(Y), decided exactly
/// (Y "in convex position"; repeated points are allowed).
inline bool is_convex_position(std::span<const Point_2<double>> y) {
  const std::vector<Point_2<double>> hull = exact_hull(y);
  for (const auto& p : y)
    if (locate(hull, p) == Polygon_side::inside) return false;
  return true;
}

/// E(Y) of eq. (3.2) and what it was computed from.
struct Hull_error {
  bool convex = true;    ///< Y in convex position (exact)
  double value = 0;      ///< d(Y_true, Y) / M rounded upward; +inf when !convex
  double coordinate_bound = 0;  ///< M
};

/// E(Y) = d(Y_true, Y) / M for the hull `hull_indices` computed from `input`:
/// infinite when Y is not in convex position, otherwise the Hausdorff distance
/// between the exact hull of the input and conv(Y), over M = max |coordinate|.
/// All predicates exact; the value is rounded upward. E = 0 when M = 0.
inline Hull_error hull_error(std::span<const Point_2<double>> input,
                             std::span<const std::size_t> hull_indices) {
  Hull_error e;
  e.coordinate_bound = coordinate_bound(input);
  const std::vector<Point_2<double>> y = points_at(input, hull_indices);
  e.convex = is_convex_position(y);
  if (!e.convex) {
    e.value = std::numeric_limits<double>::infinity();
    return e;
  }
  if (e.coordinate_bound == 0) return e;
  e.value = hausdorff_distance(exact_hull(input), exact_hull(y), e.coordinate_bound);
  return e;
}

}  // namespace relgeo
