// python/src/mesh_arrays.cpp — (V, F) arrays to and from Mesh_double.
#include "mesh_arrays.h"

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/mesh/polygon_soup.h"

namespace relgeo::python {

namespace {

std::vector<Point_3<double>> vertices_of(const Double_array& v, const std::string& who) {
  const std::size_t n = require_rows(v, 3, who + ": V");
  const Coordinate_rows rows = coordinate_rows(v);
  std::vector<Point_3<double>> points(n);
  for (std::size_t i = 0; i < n; ++i) points[i] = {rows(i, 0), rows(i, 1), rows(i, 2)};
  return points;
}

std::vector<std::array<std::int64_t, 3>> faces_of(const Index_array& f, const std::string& who) {
  const std::size_t m = require_rows(f, 3, who + ": F");
  const auto u = f.unchecked<2>();
  std::vector<std::array<std::int64_t, 3>> faces(m);
  for (std::size_t i = 0; i < m; ++i) {
    const auto row = static_cast<py::ssize_t>(i);
    faces[i] = {u(row, 0), u(row, 1), u(row, 2)};
  }
  return faces;
}

}  // namespace

Mesh_double checked_mesh(const Double_array& v, const Index_array& f, const std::string& who) {
  std::vector<Point_3<double>> points = vertices_of(v, who);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
      throw Non_finite_input(who + ": vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
  // Negative indices wrap to huge ones: out of range too.
  return from_polygon_soup(std::move(points), faces_of(f, who));
}

Mesh_double unchecked_mesh(const Double_array& v, const Index_array& f, const std::string& who) {
  Mesh_double m;
  m.vertices = vertices_of(v, who);
  for (const auto& face : faces_of(f, who)) {
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      if (face[k] < 0 || face[k] >= static_cast<std::int64_t>(invalid_index))
        throw py::value_error(who + ": face " + std::to_string(m.faces.size()) + " has the index " +
                              std::to_string(face[k]) + ", not a vertex index");
      t[k] = static_cast<Index>(face[k]);
    }
    m.faces.push_back(t);
  }
  return m;
}

py::tuple mesh_arrays(const Mesh_double& m) {
  std::vector<double> coordinates;
  coordinates.reserve(3 * m.vertices.size());
  for (const auto& p : m.vertices) coordinates.insert(coordinates.end(), {p.x, p.y, p.z});
  std::vector<Index> indices;
  indices.reserve(3 * m.faces.size());
  for (const Triangle& t : m.faces) indices.insert(indices.end(), t.begin(), t.end());
  return py::make_tuple(matrix_array<double>(coordinates, m.vertices.size(), 3),
                        matrix_array<std::int64_t>(indices, m.faces.size(), 3));
}

}  // namespace relgeo::python
