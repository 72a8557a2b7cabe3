// relgeo/mesh/triangle_mesh.h — the index-based triangle mesh relgeo's mesh and
// subdivision algorithms work on, with crease-edge and corner-vertex tags.
//
// Design (doc/subdivision.md, "Mesh representation"): a vertex vector, a
// vector of index triples (counter-clockwise seen from outside) and the
// feature tags. Adjacency is not stored; Mesh_topology (mesh_topology.h) is
// built from the faces when an algorithm needs it, in O(V + F). This flat
// layout is what makes Loop refinement faster than half-edge based
// implementations, and it holds any point type: relgeo::Point_3<FT> of every
// relgeo kernel (double, intervals, GMP rationals, MPFR) or CGAL points.
// Conversions: polygon_soup.h (no dependency), cgal_conversion.h
// (CGAL::Surface_mesh and any FaceGraph), eigen_io.h (Eigen V/F), mesh_io.h
// (OFF, OBJ, PLY, STL files through CGAL's IO, tags in a side file).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/kernel/point.h"

namespace relgeo {

/// Index of a vertex, face or edge (32 bits: meshes up to 4e9 elements).
using Index = std::uint32_t;
/// "No element" (e.g. the opposite of a boundary half-edge).
inline constexpr Index invalid_index = std::numeric_limits<Index>::max();

/// A face: three vertex indices, counter-clockwise seen from outside.
using Triangle = std::array<Index, 3>;

/// An undirected edge as the pair of its vertex indices, stored with a < b.
struct Edge {
  Index a = 0, b = 0;
  /// The edge {u, v} in normal form (smaller index first).
  static constexpr Edge of(Index u, Index v) { return u < v ? Edge{u, v} : Edge{v, u}; }
  friend constexpr bool operator==(const Edge&, const Edge&) = default;
  friend constexpr auto operator<=>(const Edge&, const Edge&) = default;
};

/// Feature tags of a mesh: crease edges and corner vertices (Hoppe et al.,
/// "Piecewise smooth surface reconstruction", SIGGRAPH 1994).
///
/// Boundary edges are creases implicitly (they need no tag). A vertex on three
/// or more crease edges is treated as a corner whether tagged or not. Both sets
/// are kept sorted and free of duplicates, so membership is a binary search.
class Feature_tags {
 public:
  /// Tags edge {u, v} as a crease. \pre u != v.
  void add_crease(Index u, Index v) {
    if (u == v) throw Precondition_violation("Feature_tags::add_crease: u == v");
    const Edge e = Edge::of(u, v);
    auto it = std::lower_bound(creases_.begin(), creases_.end(), e);
    if (it == creases_.end() || *it != e) creases_.insert(it, e);
  }
  /// Tags vertex v as a corner (its position is never moved).
  void add_corner(Index v) {
    auto it = std::lower_bound(corners_.begin(), corners_.end(), v);
    if (it == corners_.end() || *it != v) corners_.insert(it, v);
  }
  /// Replaces all crease tags (sorts and removes duplicates: O(n log n)).
  void set_creases(std::vector<Edge> creases) {
    for (Edge& e : creases) {
      if (e.a == e.b) throw Precondition_violation("Feature_tags::set_creases: edge (v, v)");
      e = Edge::of(e.a, e.b);
    }
    std::sort(creases.begin(), creases.end());
    creases.erase(std::unique(creases.begin(), creases.end()), creases.end());
    creases_ = std::move(creases);
  }
  /// Replaces all corner tags.
  void set_corners(std::vector<Index> corners) {
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    corners_ = std::move(corners);
  }
  bool is_crease(Index u, Index v) const {
    return std::binary_search(creases_.begin(), creases_.end(), Edge::of(u, v));
  }
  bool is_corner(Index v) const { return std::binary_search(corners_.begin(), corners_.end(), v); }
  std::span<const Edge> creases() const { return creases_; }
  std::span<const Index> corners() const { return corners_; }
  bool empty() const { return creases_.empty() && corners_.empty(); }
  void clear() { creases_.clear(), corners_.clear(); }
  friend bool operator==(const Feature_tags&, const Feature_tags&) = default;

 private:
  std::vector<Edge> creases_;
  std::vector<Index> corners_;
};

/// \brief A triangle mesh: vertices, faces (index triples) and feature tags.
///
/// An aggregate with public members, like relgeo::Point_3: build it with
/// designated initializers or push_back. Nothing is checked on construction;
/// check_mesh (validity.h) reports every defect, and each algorithm documents
/// what it requires (Loop refinement: edge- and vertex-manifold, consistently
/// oriented, no repeated index in a face, finite coordinates).
///
/// \tparam Point relgeo::Point_3<FT> or a CGAL-style point with x(), y(), z().
template <class Point_>
struct Triangle_mesh {
  using Point = Point_;
  std::vector<Point> vertices;
  std::vector<Triangle> faces;
  Feature_tags tags;

  std::size_t number_of_vertices() const { return vertices.size(); }
  std::size_t number_of_faces() const { return faces.size(); }
  friend bool operator==(const Triangle_mesh&, const Triangle_mesh&) = default;
};

/// The mesh of files and of most examples: double coordinates.
using Mesh_double = Triangle_mesh<Point_3<double>>;

}  // namespace relgeo
