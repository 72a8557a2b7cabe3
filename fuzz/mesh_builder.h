// fuzz/mesh_builder.h — small triangle meshes from fuzz bytes, for the
// subdivision harnesses: a valid base mesh (closed meshes of valence 3, 4, 5
// and 6 vertices, an open grid) or arbitrary faces, then edits that break
// or keep validity (flip, duplicate, drop or rewire a face, glue a pillow,
// add an isolated vertex, move a vertex, tag creases and corners).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fuzz_support.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::fuzz {

using Mesh_d = Triangle_mesh<Point_3<double>>;

/// m with its coordinates made points of kernel K (same faces and tags).
template <class K>
Triangle_mesh<typename K::Point_3> to_kernel(const Mesh_d& m) {
  Triangle_mesh<typename K::Point_3> r;
  const auto make = K{}.construct_point_3_object();
  for (const auto& p : m.vertices) r.vertices.push_back(make(p.x, p.y, p.z));
  r.faces = m.faces;
  r.tags = m.tags;
  return r;
}

/// The largest |coordinate| of m's vertices (0 for no vertex; NaN ignored).
inline double largest_magnitude(const Mesh_d& m) {
  double r = 0;
  for (const auto& p : m.vertices) r = std::max({r, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return r;
}

inline Mesh_d base_mesh(int which) {
  Mesh_d m;
  switch (which) {
    case 0:  // tetrahedron: valence 3
      m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
      break;
    case 1:  // octahedron: valence 4
      m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
      break;
    case 2: {  // bipyramid over a pentagon: valences 4 and 5
      for (int i = 0; i < 5; ++i)
        m.vertices.push_back({std::cos(2 * M_PI * i / 5), std::sin(2 * M_PI * i / 5), 0});
      m.vertices.push_back({0, 0, 1});
      m.vertices.push_back({0, 0, -1});
      for (Index i = 0; i < 5; ++i) {
        m.faces.push_back({i, (i + 1) % 5, 5});
        m.faces.push_back({(i + 1) % 5, i, 6});
      }
      break;
    }
    case 3: {  // open 3 x 3 grid: boundary, interior valence 6
      for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) m.vertices.push_back({double(x), double(y), double((x * y) % 3) / 4});
      for (Index y = 0; y < 3; ++y)
        for (Index x = 0; x < 3; ++x) {
          const Index a = 4 * y + x;
          m.faces.push_back({a, a + 1, a + 5});
          m.faces.push_back({a, a + 5, a + 4});
        }
      break;
    }
    default: {  // bipyramid over a hexagon with the apexes as corners: valences 4 and 6
      for (int i = 0; i < 6; ++i)
        m.vertices.push_back({std::cos(M_PI * i / 3), std::sin(M_PI * i / 3), 0});
      m.vertices.push_back({0, 0, 2});
      m.vertices.push_back({0, 0, -2});
      for (Index i = 0; i < 6; ++i) {
        m.faces.push_back({i, (i + 1) % 6, 6});
        m.faces.push_back({(i + 1) % 6, i, 7});
      }
    }
  }
  return m;
}

/// A mesh from the bytes: byte 0 chooses the base (or arbitrary faces), then
/// up to 24 edit records.
inline Mesh_d build_mesh(Input& in) {
  const int base = in.byte() % 7;
  Mesh_d m;
  if (base < 5) {
    m = base_mesh(base);
  } else {  // arbitrary: up to 12 vertices and 20 faces
    const std::size_t nv = 3 + in.byte() % 10, nf = 1 + in.byte() % 20;
    for (std::size_t v = 0; v < nv; ++v) {
      const double x = in.coordinate(), y = in.coordinate();
      m.vertices.push_back({x, y, in.coordinate()});
    }
    for (std::size_t f = 0; f < nf; ++f)
      m.faces.push_back({Index(in.below(nv)), Index(in.below(nv)), Index(in.below(nv))});
  }
  for (int edits = in.byte() % 25; edits > 0 && !in.empty(); --edits) {
    const std::size_t nv = m.vertices.size(), nf = m.faces.size();
    if (nf == 0) break;
    Triangle& f = m.faces[in.below(nf)];
    switch (in.byte() % 10) {
      case 0: std::swap(f[1], f[2]); break;        // flip
      case 1: m.faces.push_back(f); break;          // repeat a face
      case 2: m.faces.erase(m.faces.begin() + static_cast<std::ptrdiff_t>(in.below(nf))); break;  // hole
      case 3: f[in.below(3)] = Index(in.below(nv + 1)); break;  // rewire (possibly out of range)
      case 4: m.faces.push_back({f[1], f[0], f[2]}); break;     // a pillow on f
      case 5: m.vertices.push_back({in.coordinate(), in.coordinate(), in.coordinate()}); break;  // isolated
      case 6: {  // move a vertex
        auto& p = m.vertices[in.below(nv)];
        p.x = in.coordinate(), p.y = in.coordinate(), p.z = in.coordinate();
        break;
      }
      case 7: {  // scale everything (near overflow, near underflow)
        static constexpr double s[] = {1e300, 1e-300, 0x1p-1060, 1e150, -1};
        const double k = s[in.below(5)];
        for (auto& p : m.vertices) p = {p.x * k, p.y * k, p.z * k};
        break;
      }
      case 8: {  // crease on an edge of f, or between two arbitrary vertices
        const Index a = f[in.below(3)], b = in.flag() ? f[in.below(3)] : Index(in.below(nv));
        if (a != b) m.tags.add_crease(a, b);
        break;
      }
      default: m.tags.add_corner(Index(in.below(nv + 1)));
    }
  }
  return m;
}

}  // namespace relgeo::fuzz
