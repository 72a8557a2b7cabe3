// relgeo/hull/internal/hull_support.h — input checks, lexicographic sorting and
// output normalisation shared by the hull algorithms.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/hull/hull_result.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/internal/kernel_base.h"

namespace relgeo::internal {

/// x and y of a relgeo point (members) or a CGAL point (methods).
template <class P>
auto coordinate_x(const P& p) {
  if constexpr (requires { p.x(); }) return p.x();
  else return p.x;
}
template <class P>
auto coordinate_y(const P& p) {
  if constexpr (requires { p.y(); }) return p.y();
  else return p.y;
}

/// Throws Non_finite_input naming the first point with a NaN or infinite coordinate.
template <class Point>
void require_finite_points(std::span<const Point> points, const char* who) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto x = coordinate_x(points[i]);
    const auto y = coordinate_y(points[i]);
    bool finite = true;
    if constexpr (std::is_floating_point_v<decltype(x)> ||
                  requires { x.inf(); x.sup(); })
      finite = is_finite_value(x) && is_finite_value(y);
    if (!finite)
      throw Non_finite_input(std::string(who) + ": point " + std::to_string(i) +
                             " has a NaN or infinite coordinate");
  }
}

/// Indices of the points sorted lexicographically (ties by index); equal
/// points reduced to their smallest index. An `uncertain` comparison counts as
/// `equal` and is reported through *undecided.
template <class K>
std::vector<std::size_t> sorted_distinct_indices(std::span<const typename K::Point_2> points,
                                                 const K& k, std::size_t* undecided) {
  const auto compare = k.compare_xy_2_object();
  std::vector<std::size_t> idx(points.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  std::size_t unsure = 0;
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
    const Certified_sign s = compare(points[a], points[b]);
    unsure += (s == Certified_sign::uncertain);
    return s == Certified_sign::negative;
  });
  std::vector<std::size_t> out;
  out.reserve(idx.size());
  for (std::size_t i : idx) {
    if (!out.empty()) {
      const Certified_sign s = compare(points[out.back()], points[i]);
      unsure += (s == Certified_sign::uncertain);
      if (s == Certified_sign::zero || s == Certified_sign::uncertain) continue;
    }
    out.push_back(i);
  }
  if (undecided) *undecided += unsure;
  return out;
}

/// Fills result.points from result.indices.
template <class Point>
void attach_points(Hull_result<Point>& r, std::span<const Point> points) {
  r.points.clear();
  r.points.reserve(r.indices.size());
  for (std::size_t i : r.indices) r.points.push_back(points[i]);
}

/// Rotates a cyclic index sequence to start at its lexicographically smallest
/// point (ties by index), as the output convention asks.
template <class K>
void rotate_to_smallest(std::vector<std::size_t>& cycle, std::span<const typename K::Point_2> points,
                        const K& k) {
  if (cycle.size() < 2) return;
  const auto compare = k.compare_xy_2_object();
  std::size_t best = 0;
  for (std::size_t i = 1; i < cycle.size(); ++i) {
    const Certified_sign s = compare(points[cycle[i]], points[cycle[best]]);
    if (s == Certified_sign::negative || (s == Certified_sign::zero && cycle[i] < cycle[best])) best = i;
  }
  std::rotate(cycle.begin(), cycle.begin() + static_cast<std::ptrdiff_t>(best), cycle.end());
}

}  // namespace relgeo::internal
