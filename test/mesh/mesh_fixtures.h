// test/mesh/mesh_fixtures.h — procedural test meshes (deterministic), shared by
// the mesh and subdivision suites and the subdivision benchmark.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo_test {

using relgeo::Index;
using relgeo::Point_3;
using Mesh_d = relgeo::Triangle_mesh<Point_3<double>>;

inline Mesh_d tetrahedron() {
  Mesh_d m;
  m.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  m.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  return m;
}

inline Mesh_d octahedron() {
  Mesh_d m;
  m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

inline Mesh_d icosahedron() {
  const double t = (1 + std::sqrt(5.0)) / 2;
  Mesh_d m;
  m.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  m.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  return m;
}

/// Icosahedron refined by `levels` midpoint splits, projected to the unit
/// sphere: 20 * 4^levels faces, valences 5 and 6.
inline Mesh_d icosphere(int levels) {
  Mesh_d m = icosahedron();
  const auto project = [](Point_3<double> p) {
    const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    return Point_3<double>{p.x / r, p.y / r, p.z / r};
  };
  for (auto& p : m.vertices) p = project(p);
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<Index, Index>, Index> mid;
    const auto midpoint = [&](Index a, Index b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const auto& p = m.vertices[a];
      const auto& q = m.vertices[b];
      m.vertices.push_back(project({(p.x + q.x) / 2, (p.y + q.y) / 2, (p.z + q.z) / 2}));
      return mid[key] = static_cast<Index>(m.vertices.size() - 1);
    };
    std::vector<relgeo::Triangle> faces;
    for (const auto& f : m.faces) {
      const Index a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      faces.push_back({f[0], a, c}), faces.push_back({f[1], b, a});
      faces.push_back({f[2], c, b}), faces.push_back({a, b, c});
    }
    m.faces = std::move(faces);
  }
  return m;
}

/// Regular torus (all valences 6): m x n grid, 2 m n faces.
inline Mesh_d torus(int m_ring, int n_tube, double R = 2.0, double r = 0.7) {
  Mesh_d m;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < m_ring; ++i)
    for (int j = 0; j < n_tube; ++j) {
      const double u = 2 * pi * i / m_ring, v = 2 * pi * j / n_tube;
      m.vertices.push_back({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                            r * std::sin(v)});
    }
  const auto id = [&](int i, int j) {
    return static_cast<Index>(((i + m_ring) % m_ring) * n_tube + (j + n_tube) % n_tube);
  };
  for (int i = 0; i < m_ring; ++i)
    for (int j = 0; j < n_tube; ++j) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

/// A torus with dyadic coordinates (exactly representable everywhere, for
/// exact comparisons): positions rounded to multiples of 2^-10.
inline Mesh_d dyadic_torus(int m_ring, int n_tube) {
  Mesh_d m = torus(m_ring, n_tube);
  for (auto& p : m.vertices)
    p = {std::ldexp(std::round(std::ldexp(p.x, 10)), -10), std::ldexp(std::round(std::ldexp(p.y, 10)), -10),
         std::ldexp(std::round(std::ldexp(p.z, 10)), -10)};
  return m;
}

/// Open n x n grid in the plane z = sin-bump (boundary everywhere around).
inline Mesh_d open_grid(int n) {
  Mesh_d m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      m.vertices.push_back({double(i), double(j), 0.25 * std::sin(i * 0.7) * std::cos(j * 0.4)});
  const auto id = [&](int i, int j) { return static_cast<Index>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

/// Axis-aligned box [0,2]^3 with each square face split into 4 triangles
/// around its centre (valences 4 at face centres, 6 at corners... ), the 12
/// box edges tagged as creases and the 8 box corners as corners.
inline Mesh_d creased_box() {
  Mesh_d m;
  for (int i = 0; i < 8; ++i) m.vertices.push_back({2.0 * (i & 1), 2.0 * ((i >> 1) & 1), 2.0 * ((i >> 2) & 1)});
  // quads counter-clockwise seen from outside
  const std::array<std::array<Index, 4>, 6> quads{{{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
  for (const auto& q : quads) {
    Point_3<double> c{0, 0, 0};
    for (Index v : q) c.x += m.vertices[v].x / 4, c.y += m.vertices[v].y / 4, c.z += m.vertices[v].z / 4;
    m.vertices.push_back(c);
    const Index ci = static_cast<Index>(m.vertices.size() - 1);
    for (int k = 0; k < 4; ++k) {
      m.faces.push_back({q[k], q[(k + 1) % 4], ci});
      m.tags.add_crease(q[k], q[(k + 1) % 4]);
    }
  }
  for (Index v = 0; v < 8; ++v) m.tags.add_corner(v);
  return m;
}

/// Bipyramid over a regular n-gon: the two apexes have valence n, the
/// equator vertices valence 4. Closed, 2n faces.
inline Mesh_d bipyramid(int n) {
  Mesh_d m;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i) m.vertices.push_back({std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), 0.1 * (i % 3)});
  m.vertices.push_back({0, 0, 1.3});
  m.vertices.push_back({0.1, -0.05, -1.1});
  const Index top = static_cast<Index>(n), bottom = top + 1;
  for (int i = 0; i < n; ++i) {
    const Index a = static_cast<Index>(i), b = static_cast<Index>((i + 1) % n);
    m.faces.push_back({a, b, top});
    m.faces.push_back({b, a, bottom});
  }
  return m;
}

/// Converts coordinates (exactly for GMP rationals, MPFR >= 53 bits, intervals).
template <class FT>
relgeo::Triangle_mesh<Point_3<FT>> convert(const Mesh_d& m) {
  relgeo::Triangle_mesh<Point_3<FT>> r;
  for (const auto& p : m.vertices) r.vertices.push_back({FT(p.x), FT(p.y), FT(p.z)});
  r.faces = m.faces;
  r.tags = m.tags;
  return r;
}

/// Deterministic pseudo-random jitter of the coordinates (xorshift), to
/// leave symmetric positions.
inline Mesh_d jitter(Mesh_d m, double amount, std::uint64_t seed = 42) {
  std::uint64_t s = seed;
  const auto next = [&] {
    s ^= s << 13, s ^= s >> 7, s ^= s << 17;
    return double(s >> 11) * 0x1p-53 - 0.5;
  };
  for (auto& p : m.vertices) p.x += amount * next(), p.y += amount * next(), p.z += amount * next();
  return m;
}

}  // namespace relgeo_test
