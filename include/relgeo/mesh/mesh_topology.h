// relgeo/mesh/mesh_topology.h — compact half-edge adjacency of a triangle mesh,
// built once from the face list (per subdivision level).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/core/internal/radix_sort.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// \brief Half-edge adjacency of an oriented triangle mesh, stored in flat
/// arrays (no pointers): O(V + F) to build, 4 + 4 + 4 bytes per half-edge.
///
/// Half-edge h = 3 f + i runs in face f from faces[f][i] to faces[f][(i+1)%3];
/// next/prev/face are arithmetic. opposite(h) is the half-edge of the
/// neighbouring face on the same edge, or invalid_index on the boundary.
/// Edges are numbered in order of their first half-edge; edge_halfedge(e) is
/// that half-edge (the one with a face; on the boundary the only one).
///
/// Around a vertex, outgoing half-edges are visited counter-clockwise (seen
/// from outside, faces counter-clockwise) by ccw_outgoing(h) = opposite(prev(h)).
/// vertex_halfedge(v) starts that walk: on a boundary vertex it is the
/// outgoing boundary half-edge, so the walk visits every face of the fan.
///
/// Requirements (build() throws Invalid_mesh, listing every violation):
/// indices in range, no repeated vertex in a face, every edge in at most two
/// faces traversed in opposite directions (edge-manifold and consistently
/// oriented), the faces around each vertex form a single fan
/// (vertex-manifold). Isolated vertices are allowed (vertex_halfedge is
/// invalid_index). build_checked() records the violations instead and leaves
/// the offending adjacencies unset (opposite = invalid_index).
class Mesh_topology {
 public:
  Mesh_topology() = default;

  /// \throws Invalid_mesh when the faces violate the requirements above.
  static Mesh_topology build(std::size_t number_of_vertices, std::span<const Triangle> faces) {
    std::vector<Mesh_issue> issues;
    Mesh_topology t = build_checked(number_of_vertices, faces, issues);
    if (!issues.empty()) throw Invalid_mesh("Mesh_topology", std::move(issues));
    return t;
  }
  template <class Mesh>
  static Mesh_topology build(const Mesh& m) {
    return build(m.vertices.size(), m.faces);
  }

  /// \brief The topology of the mesh obtained by splitting every face of
  /// `parent` into four (Loop or midpoint refinement), without searching:
  /// O(V + F), several times faster than build().
  ///
  /// Numbering (the one loop_subdivide uses): parent vertex v stays v; the
  /// new vertex of parent edge e is V + e; parent face f = (v0, v1, v2)
  /// becomes faces 4f..4f+3 = (v0, m0, m2), (v1, m1, m0), (v2, m2, m1),
  /// (m0, m1, m2), m_i the new vertex of edge (v_i, v_i+1). `child_faces`
  /// must be exactly those faces. The result equals build(child_faces).
  /// \pre parent was built from a valid mesh (build() did not throw).
  static Mesh_topology refined(const Mesh_topology& parent, std::span<const Triangle> child_faces);

  /// The parent half-edge a child half-edge lies on (its first or second
  /// half), or invalid_index for the child edges inside a parent face
  /// (numbering of refined()).
  static constexpr Index parent_halfedge(Index child_h) {
    const Index f = child_h / 3, piece = f % 4, pos = child_h % 3, pf = f / 4;
    if (piece == 3 || pos == 1) return invalid_index;
    return 3 * pf + (pos == 0 ? piece : (piece + 2) % 3);
  }

  /// Never throws for bad input: appends every violation to `issues`
  /// (index_out_of_range, repeated_vertex_in_face, non_manifold_edge,
  /// inconsistent_orientation, non_manifold_vertex; each edge and vertex once;
  /// vertices of non-manifold or misoriented edges are not also reported as
  /// non-manifold vertices).
  /// Faces with a bad index or a repeated vertex get no adjacency at all.
  static Mesh_topology build_checked(std::size_t number_of_vertices,
                                     std::span<const Triangle> faces,
                                     std::vector<Mesh_issue>& issues);

  std::size_t number_of_vertices() const { return out_begin_.empty() ? 0 : out_begin_.size() - 1; }
  std::size_t number_of_faces() const { return faces_.size(); }
  std::size_t number_of_halfedges() const { return 3 * faces_.size(); }
  std::size_t number_of_edges() const { return edge_halfedge_.size(); }
  std::span<const Triangle> faces() const { return faces_; }

  static constexpr Index face(Index h) { return h / 3; }
  static constexpr Index next(Index h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static constexpr Index prev(Index h) { return h % 3 == 0 ? h + 2 : h - 1; }
  Index source(Index h) const { return faces_[h / 3][h % 3]; }
  Index target(Index h) const { return faces_[h / 3][h % 3 == 2 ? 0 : h % 3 + 1]; }
  Index opposite(Index h) const { return opposite_[h]; }
  Index edge(Index h) const { return edge_of_[h]; }
  Index edge_halfedge(Index e) const { return edge_halfedge_[e]; }
  Edge edge_vertices(Index e) const {
    const Index h = edge_halfedge_[e];
    return Edge::of(source(h), target(h));
  }
  /// The opposite of every half-edge (indexed 3 f + i), moved out of the
  /// topology, which is left empty: for a caller that needs only these and
  /// frees the rest (the mesh Boolean keeps a fifth of the topology's memory).
  std::vector<Index> take_opposites() && {
    std::vector<Index> o = std::move(opposite_);
    *this = Mesh_topology();
    return o;
  }
  bool is_boundary_halfedge(Index h) const { return opposite_[h] == invalid_index; }
  bool is_boundary_edge(Index e) const { return opposite_[edge_halfedge_[e]] == invalid_index; }

  /// The next outgoing half-edge of source(h), counter-clockwise; invalid_index
  /// when h's face is the last of a boundary fan.
  Index ccw_outgoing(Index h) const { return opposite_[prev(h)]; }
  /// Start of the counter-clockwise walk around v (see class comment).
  Index vertex_halfedge(Index v) const { return vertex_halfedge_[v]; }
  bool is_isolated(Index v) const { return vertex_halfedge_[v] == invalid_index; }
  bool is_boundary_vertex(Index v) const {
    const Index h = vertex_halfedge_[v];
    return h != invalid_index && opposite_[h] == invalid_index;
  }
  /// Number of faces around v.
  Index number_of_incident_faces(Index v) const { return out_begin_[v + 1] - out_begin_[v]; }
  /// Number of neighbouring vertices (faces + 1 on the boundary).
  Index valence(Index v) const {
    return number_of_incident_faces(v) + (is_boundary_vertex(v) ? 1 : 0);
  }
  /// The outgoing half-edges of v in counter-clockwise order, starting at
  /// vertex_halfedge(v).
  template <class F>
  void for_each_outgoing(Index v, F&& f) const {
    Index h = vertex_halfedge_[v];
    for (Index k = 0, n = number_of_incident_faces(v); h != invalid_index && k < n; ++k) {
      f(h);
      h = ccw_outgoing(h);
      if (h == vertex_halfedge_[v]) break;
    }
  }
  /// The neighbours of v in counter-clockwise order. Interior vertex: n
  /// neighbours, the i-th the target of the i-th outgoing half-edge. Boundary
  /// vertex with k faces: k + 1 neighbours, the first and last on the boundary.
  std::vector<Index> vertex_ring(Index v) const {
    std::vector<Index> ring;
    Index last = invalid_index;
    for_each_outgoing(v, [&](Index h) {
      ring.push_back(target(h));
      last = h;
    });
    if (last != invalid_index && is_boundary_vertex(v)) ring.push_back(source(prev(last)));
    return ring;
  }
  /// The half-edge from u to v, or invalid_index.
  Index find_halfedge(Index u, Index v) const {
    for (Index k = out_begin_[u]; k < out_begin_[u + 1]; ++k)
      if (target(out_[k]) == v) return out_[k];
    return invalid_index;
  }
  /// The edge {u, v}, or invalid_index.
  Index find_edge(Index u, Index v) const {
    Index h = find_halfedge(u, v);
    if (h == invalid_index) h = find_halfedge(v, u);
    return h == invalid_index ? invalid_index : edge_of_[h];
  }

 private:
  // The steps of build_checked, in order; each appends what it finds to `issues`.
  static std::vector<char> check_faces(std::size_t nv, std::span<const Triangle> faces, std::vector<Mesh_issue>& issues);
  void sort_outgoing(std::size_t nv, const std::vector<char>& face_ok);
  std::vector<char> match_opposites(std::size_t nv, const std::vector<char>& face_ok, std::vector<Mesh_issue>& issues);
  void number_edges(const std::vector<char>& face_ok);
  void find_walk_starts(const std::vector<char>& on_bad_edge, std::vector<Mesh_issue>& issues);
  Index count_fans(Index v) const;

  std::vector<Triangle> faces_;
  std::vector<Index> opposite_, edge_of_, edge_halfedge_;
  std::vector<Index> out_begin_, out_;  // outgoing half-edges of each vertex (CSR)
  std::vector<Index> vertex_halfedge_;
};

inline Mesh_topology Mesh_topology::refined(const Mesh_topology& p, std::span<const Triangle> child_faces) {
  const Index nv = static_cast<Index>(p.number_of_vertices()), ne = static_cast<Index>(p.number_of_edges());
  const Index nf = static_cast<Index>(p.number_of_faces());
  if (child_faces.size() != 4 * std::size_t(nf))
    throw Precondition_violation("Mesh_topology::refined: child_faces is not the refined face list");
  Mesh_topology t;
  t.faces_.assign(child_faces.begin(), child_faces.end());
  const Index nh = 12 * nf, cv = nv + ne;
  // Opposites (see the derivation in doc/subdivision.md).
  t.opposite_.assign(nh, invalid_index);
  for (Index f = 0; f < nf; ++f) {
    for (Index i = 0; i < 3; ++i) {
      const Index corner = 4 * f + i;
      const Index o = p.opposite_[3 * f + i];                   // across parent edge i
      const Index o_prev = p.opposite_[3 * f + (i + 2) % 3];    // across parent edge i-1
      if (o != invalid_index) t.opposite_[3 * corner] = 3 * (4 * (o / 3) + (o % 3 + 1) % 3) + 2;
      t.opposite_[3 * corner + 1] = 3 * (4 * f + 3) + (i + 2) % 3;
      if (o_prev != invalid_index) t.opposite_[3 * corner + 2] = 3 * (4 * (o_prev / 3) + o_prev % 3);
      t.opposite_[3 * (4 * f + 3) + i] = 3 * (4 * f + (i + 1) % 3) + 1;
    }
  }
  // Edges, numbered as build() numbers them.
  t.edge_of_.assign(nh, invalid_index);
  t.edge_halfedge_.reserve(2 * std::size_t(ne) + 3 * std::size_t(nf));
  for (Index h = 0; h < nh; ++h) {
    const Index o = t.opposite_[h];
    if (o != invalid_index && o < h) {
      t.edge_of_[h] = t.edge_of_[o];
      continue;
    }
    t.edge_of_[h] = static_cast<Index>(t.edge_halfedge_.size());
    t.edge_halfedge_.push_back(h);
  }
  // Outgoing half-edges (CSR): degrees are known.
  t.out_begin_.assign(std::size_t(cv) + 1, 0);
  for (Index v = 0; v < nv; ++v) t.out_begin_[v + 1] = p.number_of_incident_faces(v);
  for (Index e = 0; e < ne; ++e) t.out_begin_[nv + e + 1] = p.is_boundary_edge(e) ? 3 : 6;
  for (Index v = 0; v < cv; ++v) t.out_begin_[v + 1] += t.out_begin_[v];
  t.out_.resize(nh);
  {
    std::vector<Index> fill(t.out_begin_.begin(), t.out_begin_.end() - 1);
    for (Index h = 0; h < nh; ++h) t.out_[fill[t.faces_[h / 3][h % 3]]++] = h;
  }
  t.vertex_halfedge_.resize(cv);
  for (Index v = 0; v < cv; ++v) {
    const bool boundary = v < nv ? p.is_boundary_vertex(v) : p.is_boundary_edge(v - nv);
    if (t.out_begin_[v] == t.out_begin_[v + 1]) {  // isolated
      t.vertex_halfedge_[v] = invalid_index;
      continue;
    }
    Index start = t.out_[t.out_begin_[v]];
    if (boundary)
      for (Index k = t.out_begin_[v]; k < t.out_begin_[v + 1]; ++k)
        if (t.opposite_[t.out_[k]] == invalid_index) start = t.out_[k];
    t.vertex_halfedge_[v] = start;
  }
  return t;
}

inline Mesh_topology Mesh_topology::build_checked(std::size_t nv, std::span<const Triangle> faces,
                                                  std::vector<Mesh_issue>& issues) {
  if (faces.size() >= invalid_index / 3 || nv >= invalid_index)
    throw Invalid_input("Mesh_topology: mesh too large for 32-bit indices");
  Mesh_topology t;
  t.faces_.assign(faces.begin(), faces.end());
  const std::vector<char> face_ok = check_faces(nv, faces, issues);
  t.sort_outgoing(nv, face_ok);
  const std::vector<char> on_bad_edge = t.match_opposites(nv, face_ok, issues);
  t.number_edges(face_ok);
  t.find_walk_starts(on_bad_edge, issues);
  return t;
}

/// Which faces can take part in the topology: every index in range, three
/// distinct vertices.
inline std::vector<char> Mesh_topology::check_faces(std::size_t nv, std::span<const Triangle> faces,
                                                    std::vector<Mesh_issue>& issues) {
  const Index nf = static_cast<Index>(faces.size());
  std::vector<char> face_ok(nf, 1);
  for (Index f = 0; f < nf; ++f) {
    const Triangle& tr = faces[f];
    for (Index v : tr)
      if (v >= nv) {
        issues.push_back({Mesh_defect::index_out_of_range, {f, v}});
        face_ok[f] = 0;
      }
    if (face_ok[f] && (tr[0] == tr[1] || tr[1] == tr[2] || tr[2] == tr[0])) {
      issues.push_back({Mesh_defect::repeated_vertex_in_face, {f, invalid_index}});
      face_ok[f] = 0;
    }
  }
  return face_ok;
}

/// Outgoing half-edges per vertex (counting sort by source).
inline void Mesh_topology::sort_outgoing(std::size_t nv, const std::vector<char>& face_ok) {
  const Index nf = static_cast<Index>(faces_.size());
  out_begin_.assign(nv + 1, 0);
  for (Index f = 0; f < nf; ++f)
    if (face_ok[f])
      for (Index v : faces_[f]) ++out_begin_[v + 1];
  for (std::size_t v = 0; v < nv; ++v) out_begin_[v + 1] += out_begin_[v];
  out_.resize(out_begin_[nv]);
  std::vector<Index> fill(out_begin_.begin(), out_begin_.end() - 1);
  for (Index f = 0; f < nf; ++f)
    if (face_ok[f])
      for (Index i = 0; i < 3; ++i) out_[fill[faces_[f][i]]++] = 3 * f + i;
}

/// Opposites: the unique half-edge b->a for a->b, when the edge is manifold.
/// Reports the non-manifold and misoriented edges, and returns the vertices
/// on them: those cannot be walked around, and are not reported again as
/// non-manifold vertices. The good half-edges are sorted by their edge
/// {a < b} (key a * nv + b, radix sort): an edge's half-edges end up side
/// by side. Each carries its direction (a > b) in its lowest bit, so the
/// matching reads no face: on CGAL's armadillo the matching took 1.55 ms
/// with it and radix_sort_bits's one read for the counts of all passes,
/// 2.29 ms before (and 3.2 with the half-edges bucketed by their smaller
/// vertex).
inline std::vector<char> Mesh_topology::match_opposites(std::size_t nv, const std::vector<char>& face_ok,
                                                        std::vector<Mesh_issue>& issues) {
  const Index nh = static_cast<Index>(3 * faces_.size());
  opposite_.assign(nh, invalid_index);
  // Once sorted, each edge has one half-edge (boundary), two in opposite
  // directions (opposites), two in one direction (misoriented) or more (not
  // manifold). `tagged(i)` is h << 1 | (h runs from the larger vertex).
  std::vector<Edge> bad_edges, misoriented;
  const auto match = [&](std::size_t n, auto&& key, auto&& tagged) {
    for (std::size_t i = 0, j; i < n; i = j) {
      const std::uint64_t k = key(i);
      for (j = i + 1; j < n && key(j) == k;) ++j;
      if (j - i == 1) continue;
      const std::uint64_t x = tagged(i), y = tagged(i + 1);
      if (j - i > 2)
        bad_edges.push_back(Edge::of(static_cast<Index>(k / nv), static_cast<Index>(k % nv)));
      else if ((x & 1) == (y & 1))
        misoriented.push_back(Edge::of(static_cast<Index>(k / nv), static_cast<Index>(k % nv)));
      else
        opposite_[x >> 1] = static_cast<Index>(y >> 1), opposite_[y >> 1] = static_cast<Index>(x >> 1);
    }
  };
  const auto edge_key = [nv](Index a, Index b) { return std::uint64_t{std::min(a, b)} * nv + std::max(a, b); };
  // Each good half-edge as (key, tagged), in order.
  const auto for_each_halfedge = [&](auto&& f) {
    for (Index face = 0; face < faces_.size(); ++face) {
      if (!face_ok[face]) continue;
      const Triangle& t = faces_[face];
      for (Index i = 0; i < 3; ++i) {
        const Index a = t[i], b = t[i == 2 ? 0 : i + 1];
        f(edge_key(a, b), std::uint64_t{3 * face + i} << 1 | (a > b));
      }
    }
  };
  const int key_bits = static_cast<int>(std::bit_width(nv < 2 ? std::uint64_t{0} : std::uint64_t{nv} * nv - 1));
  const int tag_bits = static_cast<int>(std::bit_width(std::uint64_t{nh})) + 1;
  if (key_bits + tag_bits <= 64) {
    // One word per half-edge: the key, then the tag in the low bits.
    std::vector<std::uint64_t> word, tmp;
    word.reserve(nh);
    for_each_halfedge([&](std::uint64_t key, std::uint64_t tag) { word.push_back(key << tag_bits | tag); });
    internal::radix_sort_bits(word, tmp, tag_bits, key_bits);
    const std::uint64_t tag_mask = (std::uint64_t{1} << tag_bits) - 1;
    match(
        word.size(), [&](std::size_t i) { return word[i] >> tag_bits; },
        [&](std::size_t i) { return word[i] & tag_mask; });
  } else {  // over 2^21 vertices and faces or so: pairs
    std::vector<std::pair<std::uint64_t, std::uint64_t>> pairs;
    pairs.reserve(nh);
    for_each_halfedge([&](std::uint64_t key, std::uint64_t tag) { pairs.emplace_back(key, tag); });
    std::sort(pairs.begin(), pairs.end());
    match(
        pairs.size(), [&](std::size_t i) { return pairs[i].first; }, [&](std::size_t i) { return pairs[i].second; });
  }
  const auto report_edges = [&](std::vector<Edge>& v, Mesh_defect d) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    for (const Edge& e : v) issues.push_back({d, {e.a, e.b}});
  };
  report_edges(bad_edges, Mesh_defect::non_manifold_edge);
  report_edges(misoriented, Mesh_defect::inconsistent_orientation);
  std::vector<char> on_bad_edge(nv, 0);
  for (const auto* v : {&bad_edges, &misoriented})
    for (const Edge& e : *v) on_bad_edge[e.a] = on_bad_edge[e.b] = 1;
  return on_bad_edge;
}

/// Edge numbering: in the order of each edge's first half-edge.
inline void Mesh_topology::number_edges(const std::vector<char>& face_ok) {
  const Index nh = static_cast<Index>(3 * faces_.size());
  edge_of_.assign(nh, invalid_index);
  edge_halfedge_.reserve(nh / 2 + 3);
  for (Index h = 0; h < nh; ++h) {
    if (!face_ok[h / 3] || edge_of_[h] != invalid_index) continue;
    const Index e = static_cast<Index>(edge_halfedge_.size());
    edge_halfedge_.push_back(h);
    edge_of_[h] = e;
    if (opposite_[h] != invalid_index) edge_of_[opposite_[h]] = e;
  }
}

/// Walk starts; a vertex whose walk misses faces has several fans.
inline void Mesh_topology::find_walk_starts(const std::vector<char>& on_bad_edge, std::vector<Mesh_issue>& issues) {
  const Index nv = static_cast<Index>(on_bad_edge.size());
  vertex_halfedge_.assign(nv, invalid_index);
  for (Index v = 0; v < nv; ++v) {
    const Index begin = out_begin_[v], end = out_begin_[v + 1];
    if (begin == end) continue;
    Index start = out_[begin], boundary_starts = 0;
    for (Index k = begin; k < end; ++k)
      if (opposite_[out_[k]] == invalid_index) start = out_[k], ++boundary_starts;
    vertex_halfedge_[v] = start;
    Index reached = 0;
    for_each_outgoing(v, [&](Index) { ++reached; });
    if (reached != end - begin && !on_bad_edge[v])
      issues.push_back({Mesh_defect::non_manifold_vertex, {v, boundary_starts + count_fans(v)}});
  }
}

/// The fans around v without a boundary half-edge (cycles): a boundary fan
/// starts at a boundary half-edge, and those are counted by the caller.
inline Index Mesh_topology::count_fans(Index v) const {
  const Index begin = out_begin_[v], end = out_begin_[v + 1];
  Index cycles = 0;
  std::vector<char> seen(end - begin, 0);
  const auto slot = [&](Index h) {
    return static_cast<Index>(std::find(out_.begin() + begin, out_.begin() + end, h) - (out_.begin() + begin));
  };
  for (Index k = begin; k < end; ++k) {
    if (opposite_[out_[k]] == invalid_index) {
      for (Index h = out_[k]; h != invalid_index && !seen[slot(h)]; h = ccw_outgoing(h)) seen[slot(h)] = 1;
    }
  }
  for (Index k = begin; k < end; ++k)
    if (!seen[k - begin]) {
      ++cycles;
      for (Index h = out_[k]; h != invalid_index && !seen[slot(h)]; h = ccw_outgoing(h)) seen[slot(h)] = 1;
    }
  return cycles;
}

}  // namespace relgeo
