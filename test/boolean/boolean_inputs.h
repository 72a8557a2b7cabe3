// test/boolean/boolean_inputs.h — the closed meshes of the Boolean tests
// (relgeo/mesh/shapes.h) and the figures the tests compare on.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <utility>

#include "relgeo/kernel/point.h"
#include "relgeo/mesh/shapes.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::test {

using Mesh = Triangle_mesh<Point_3<double>>;

using relgeo::box;
using relgeo::cube;
using relgeo::icosphere;
using relgeo::rigidly_moved;
using relgeo::torus;

/// Volume of a closed mesh (doubles; for tolerance checks only).
inline double volume(const Mesh& m) {
  double v = 0;
  for (const auto& f : m.faces) {
    const auto &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
    v += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
  }
  return v / 6;
}

/// Area of a mesh's faces (doubles; for tolerance checks only).
inline double area(const Mesh& m) {
  double s = 0;
  for (const auto& f : m.faces) {
    const auto &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    s += 0.5 * std::hypot(uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx);
  }
  return s;
}

/// The tetrahedron with corners v, outward oriented (the sign of its
/// volume in doubles: corners whose orientation rounding cannot flip).
inline Mesh tetrahedron(const std::array<Point_3<double>, 4>& v) {
  Mesh m;
  m.vertices.assign(v.begin(), v.end());
  m.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  if (volume(m) < 0)
    for (auto& f : m.faces) std::swap(f[1], f[2]);
  return m;
}

/// V - E + F of a mesh (edges counted once).
inline long euler_characteristic(const Mesh& m) {
  std::vector<std::pair<Index, Index>> e;
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) e.push_back(std::minmax(f[k], f[(k + 1) % 3]));
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  std::vector<char> used(m.vertices.size(), 0);
  for (const auto& f : m.faces)
    for (Index v : f) used[v] = 1;
  const long v = std::count(used.begin(), used.end(), 1);
  return v - static_cast<long>(e.size()) + static_cast<long>(m.faces.size());
}

}  // namespace relgeo::test
