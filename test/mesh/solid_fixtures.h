// test/mesh/solid_fixtures.h — closed meshes and rigid motions for the face
// BVH, self-intersection and solid-validation suites and the mesh benchmark
// (deterministic).
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh/mesh_fixtures.h"

namespace relgeo_test {

/// The sphere of radius r around c obtained by projecting the surface of a
/// cube cut into n x n squares per side (each split into two triangles):
/// 12 n^2 faces, closed, outward oriented (n = 41: 20172 faces; n = 289:
/// 1002252 faces).
inline Mesh_d cube_sphere(int n, double r = 1.0, Point_3<double> c = {0, 0, 0}) {
  Mesh_d m;
  std::unordered_map<std::uint64_t, Index> index;
  const auto vertex = [&](int i, int j, int k) {
    const std::uint64_t key = (std::uint64_t(i) * (n + 1) + std::uint64_t(j)) * (n + 1) + std::uint64_t(k);
    auto [it, fresh] = index.emplace(key, static_cast<Index>(m.vertices.size()));
    if (fresh) {
      const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n, z = -1 + 2.0 * k / n;
      const double s = r / std::sqrt(x * x + y * y + z * z);
      m.vertices.push_back({c.x + s * x, c.y + s * y, c.z + s * z});
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int u = 0; u < n; ++u)
        for (int v = 0; v < n; ++v) {
          // lattice point with coordinate `axis` fixed, (axis+1)%3 = u, (axis+2)%3 = v:
          // e_(axis+1) x e_(axis+2) = e_axis, so (u, v) counter-clockwise faces +axis
          const auto at = [&](int du, int dv) {
            int c3[3];
            c3[axis] = side ? n : 0;
            c3[(axis + 1) % 3] = u + du;
            c3[(axis + 2) % 3] = v + dv;
            return vertex(c3[0], c3[1], c3[2]);
          };
          const Index a = at(0, 0), b = at(1, 0), cc = at(1, 1), d = at(0, 1);
          if (side) m.faces.push_back({a, b, cc}), m.faces.push_back({a, cc, d});
          else m.faces.push_back({a, cc, b}), m.faces.push_back({a, d, cc});
        }
  return m;
}

inline Mesh_d translated(Mesh_d m, double dx, double dy, double dz) {
  for (auto& p : m.vertices) p = {p.x + dx, p.y + dy, p.z + dz};
  return m;
}

/// m rotated by `angle` about the axis through `c` along (ax, ay, az)
/// (Rodrigues; coordinates rounded to double).
inline Mesh_d rotated(Mesh_d m, double angle, Point_3<double> axis, Point_3<double> c) {
  const double l = std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
  const double ux = axis.x / l, uy = axis.y / l, uz = axis.z / l;
  const double co = std::cos(angle), si = std::sin(angle), t = 1 - co;
  const double R[3][3] = {{co + ux * ux * t, ux * uy * t - uz * si, ux * uz * t + uy * si},
                          {uy * ux * t + uz * si, co + uy * uy * t, uy * uz * t - ux * si},
                          {uz * ux * t - uy * si, uz * uy * t + ux * si, co + uz * uz * t}};
  for (auto& p : m.vertices) {
    const double x = p.x - c.x, y = p.y - c.y, z = p.z - c.z;
    p = {c.x + R[0][0] * x + R[0][1] * y + R[0][2] * z, c.y + R[1][0] * x + R[1][1] * y + R[1][2] * z,
         c.z + R[2][0] * x + R[2][1] * y + R[2][2] * z};
  }
  return m;
}

/// The centre of the bounding box.
inline Point_3<double> box_centre(const Mesh_d& m) {
  Point_3<double> lo = m.vertices.front(), hi = lo;
  for (const auto& p : m.vertices) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  return {(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2};
}

/// All faces reversed (an inverted solid).
inline Mesh_d inverted(Mesh_d m) {
  for (auto& f : m.faces) std::swap(f[1], f[2]);
  return m;
}

/// The disjoint union of a and b (b's indices shifted).
inline Mesh_d disjoint_union(Mesh_d a, const Mesh_d& b) {
  const Index off = static_cast<Index>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto f : b.faces) a.faces.push_back({f[0] + off, f[1] + off, f[2] + off});
  return a;
}

/// The cube [x0, x0 + s] x [y0, y0 + s] x [z0, z0 + s], 12 faces, outward.
inline Mesh_d cube(double s = 1, Point_3<double> o = {0, 0, 0}) {
  Mesh_d m;
  for (int i = 0; i < 8; ++i) m.vertices.push_back({o.x + s * (i & 1), o.y + s * ((i >> 1) & 1), o.z + s * ((i >> 2) & 1)});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.faces.push_back({Index(q[0]), Index(q[1]), Index(q[2])});
    m.faces.push_back({Index(q[0]), Index(q[2]), Index(q[3])});
  }
  return m;
}

}  // namespace relgeo_test
