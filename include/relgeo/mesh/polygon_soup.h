// relgeo/mesh/polygon_soup.h — polygon soups (points + index lists, CGAL's
// soup format) in and out. No dependency beyond the standard library.
#pragma once

#include <cstddef>
#include <ranges>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// How from_polygon_soup treats polygons with more than three corners.
struct Soup_options {
  /// false (default): such a polygon is an error (Invalid_input). true: it is
  /// split into a fan around its first corner (right for convex polygons).
  bool triangulate_polygons = false;
};

/// A triangle mesh from a soup. Indices are checked (Invalid_mesh with
/// index_out_of_range); polygons with fewer than three corners are
/// Invalid_input. Nothing else is checked (see check_mesh).
template <class P, class PolygonRange>
Triangle_mesh<P> from_polygon_soup(std::vector<P> points, const PolygonRange& polygons,
                                   const Soup_options& options = {}) {
  Triangle_mesh<P> m;
  m.vertices = std::move(points);
  std::vector<Mesh_issue> issues;
  Index f = 0;
  if constexpr (std::ranges::sized_range<PolygonRange>) m.faces.reserve(std::ranges::size(polygons));
  std::vector<Index> idx;  // one buffer for every polygon
  for (const auto& poly : polygons) {
    const std::size_t n = std::size(poly);
    if (n < 3) throw Invalid_input("polygon soup: polygon " + std::to_string(f) + " has fewer than 3 corners");
    if (n > 3 && !options.triangulate_polygons)
      throw Invalid_input("polygon soup: polygon " + std::to_string(f) + " has " + std::to_string(n) +
                          " corners (set Soup_options::triangulate_polygons to split it)");
    idx.clear();
    for (const auto& i : poly) {
      if (static_cast<std::size_t>(i) >= m.vertices.size())
        issues.push_back({Mesh_defect::index_out_of_range, {f, static_cast<Index>(i)}});
      idx.push_back(static_cast<Index>(i));
    }
    for (std::size_t k = 1; k + 1 < n; ++k) m.faces.push_back({idx[0], idx[k], idx[k + 1]});
    ++f;
  }
  if (!issues.empty()) throw Invalid_mesh("from_polygon_soup", std::move(issues));
  return m;
}

/// The faces as index lists (tags are not part of a soup).
template <class P>
std::vector<std::vector<std::size_t>> to_polygon_soup(const Triangle_mesh<P>& m) {
  std::vector<std::vector<std::size_t>> polys;
  polys.reserve(m.faces.size());
  for (const Triangle& t : m.faces) polys.push_back({t[0], t[1], t[2]});
  return polys;
}

}  // namespace relgeo
