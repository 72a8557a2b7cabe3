// relgeo/mesh/shapes.h — closed triangle meshes to experiment with: boxes
// with exact (dyadic) corners, icospheres and tori in general position, and
// rigid motions of a mesh. Used by the Boolean tests, benchmarks and the
// tool's experiment; outward oriented, closed, manifold.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// The box [x0, x0 + sx] x [y0, y0 + sy] x [z0, z0 + sz], 12 outward triangles.
inline Mesh_double box(double x0, double y0, double z0, double sx, double sy, double sz) {
  Mesh_double m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({x0 + sx * (i & 1), y0 + sy * ((i >> 1) & 1), z0 + sz * ((i >> 2) & 1)});
  const int f[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                        {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (const auto& t : f) m.faces.push_back({Index(t[0]), Index(t[1]), Index(t[2])});
  return m;
}
inline Mesh_double cube(double x0, double y0, double z0, double s) { return box(x0, y0, z0, s, s, s); }

/// An icosphere: the icosahedron subdivided `levels` times, projected on the
/// sphere of `radius` around `center` (coordinates rounded to doubles).
inline Mesh_double icosphere(int levels, std::array<double, 3> center = {0, 0, 0}, double radius = 1) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> v{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                       {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Triangle> f{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                          {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                          {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<Index, Index>, Index> mid;
    const auto middle = [&](Index a, Index b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back({(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2});
      return mid[key] = static_cast<Index>(v.size() - 1);
    };
    std::vector<Triangle> g;
    for (const auto& tr : f) {
      const Index a = middle(tr[0], tr[1]), b = middle(tr[1], tr[2]), c = middle(tr[2], tr[0]);
      g.push_back({tr[0], a, c}), g.push_back({tr[1], b, a}), g.push_back({tr[2], c, b}), g.push_back({a, b, c});
    }
    f = std::move(g);
  }
  Mesh_double m;
  for (const auto& p : v) {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    m.vertices.push_back({center[0] + radius * p[0] / n, center[1] + radius * p[1] / n, center[2] + radius * p[2] / n});
  }
  m.faces = std::move(f);
  return m;
}

/// A torus around the z axis: tube radius r at distance R, n x m quads split.
inline Mesh_double torus(double R, double r, int n, int m, std::array<double, 3> center = {0, 0, 0}) {
  Mesh_double t;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * pi * i / n, w = 2 * pi * j / m;
      const double ring = R + r * std::cos(w);
      t.vertices.push_back({center[0] + ring * std::cos(u), center[1] + ring * std::sin(u), center[2] + r * std::sin(w)});
    }
  const auto id = [&](int i, int j) { return static_cast<Index>(((i + n) % n) * m + (j + m) % m); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return t;
}

/// m rotated about z by `angle`, then about x by `tilt`, then translated.
inline Mesh_double rigidly_moved(const Mesh_double& m, double angle, double tilt, std::array<double, 3> shift) {
  Mesh_double r = m;
  const double c = std::cos(angle), s = std::sin(angle), ct = std::cos(tilt), st = std::sin(tilt);
  for (auto& p : r.vertices) {
    const double x = c * p.x - s * p.y, y = s * p.x + c * p.y;
    const double y2 = ct * y - st * p.z, z2 = st * y + ct * p.z;
    p = {x + shift[0], y2 + shift[1], z2 + shift[2]};
  }
  return r;
}

}  // namespace relgeo
