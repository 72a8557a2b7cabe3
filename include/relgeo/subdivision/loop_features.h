// relgeo/subdivision/loop_features.h — what Loop's rules need to know about a
// mesh: crease edges (tagged or boundary), the kind of every vertex (smooth,
// dart, crease, corner, isolated), the sectors of crease vertices and
// corners, and the refusal of meshes whose refinement is not a manifold.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// The role of a vertex in the rules (Hoppe et al. 1994).
enum class Vertex_kind : std::uint8_t {
  smooth,   ///< no incident crease edge: smooth rules
  dart,     ///< one incident crease edge: smooth rules
  crease,   ///< two incident crease edges (boundary vertices included): crease rules
  corner,   ///< tagged corner, or three or more crease edges: fixed
  isolated  ///< in no face: fixed, kept as it is
};

/// Crease edges (tagged or boundary) and vertex kinds of a mesh, per edge and
/// vertex index of its Mesh_topology.
struct Loop_features {
  std::vector<std::uint8_t> edge_is_crease;  ///< per edge: tagged crease or boundary
  std::vector<std::uint8_t> edge_is_tagged;  ///< per edge: tagged crease
  std::vector<Vertex_kind> vertex_kind;      ///< per vertex
  std::vector<std::uint8_t> crease_degree;   ///< per vertex: number of crease edges (saturating at 255)

  bool is_special(Index v) const {
    return vertex_kind[v] == Vertex_kind::crease || vertex_kind[v] == Vertex_kind::corner;
  }
};

/// Two faces sharing two edges (a two-face "pillow" on three vertices, whose
/// vertices have valence 2) refine into a non-manifold mesh: Loop refinement
/// and evaluation refuse them. \throws Invalid_input naming the faces.
inline void require_no_faces_sharing_two_edges(const Mesh_topology& t, const char* who) {
  for (Index f = 0; f < t.number_of_faces(); ++f)
    for (Index i = 0; i < 3; ++i) {
      const Index a = t.opposite(3 * f + i), b = t.opposite(3 * f + (i + 1) % 3);
      if (a != invalid_index && b != invalid_index && a / 3 == b / 3)
        throw Invalid_input(std::string(who) + ": faces " + std::to_string(f) + " and " + std::to_string(a / 3) +
                            " share two edges (a vertex of valence 2): the refinement is not a manifold");
    }
}

/// Classifies edges and vertices. \throws Invalid_mesh (invalid_tag) when a
/// crease tag is not an edge of the mesh or a corner tag is out of range.
inline Loop_features classify_loop_features(const Mesh_topology& t, const Feature_tags& tags) {
  Loop_features f;
  const std::size_t ne = t.number_of_edges(), nv = t.number_of_vertices();
  f.edge_is_crease.assign(ne, 0);
  f.edge_is_tagged.assign(ne, 0);
  std::vector<Mesh_issue> issues;
  for (const Edge& c : tags.creases()) {
    const Index e = (c.a < nv && c.b < nv) ? t.find_edge(c.a, c.b) : invalid_index;
    if (e == invalid_index) issues.push_back({Mesh_defect::invalid_tag, {c.a, c.b}});
    else f.edge_is_tagged[e] = f.edge_is_crease[e] = 1;
  }
  for (Index v : tags.corners())
    if (v >= nv) issues.push_back({Mesh_defect::invalid_tag, {v, invalid_index}});
  if (!issues.empty()) throw Invalid_mesh("Loop subdivision feature tags", std::move(issues));
  f.crease_degree.assign(nv, 0);
  for (Index e = 0; e < ne; ++e) {
    if (t.is_boundary_edge(e)) f.edge_is_crease[e] = 1;
    if (!f.edge_is_crease[e]) continue;
    const Edge ab = t.edge_vertices(e);
    for (Index v : {ab.a, ab.b})
      if (f.crease_degree[v] < 255) ++f.crease_degree[v];
  }
  f.vertex_kind.resize(nv);
  for (Index v = 0; v < nv; ++v) {
    const unsigned d = f.crease_degree[v];
    f.vertex_kind[v] = t.is_isolated(v)        ? Vertex_kind::isolated
                       : tags.is_corner(v) || d >= 3 ? Vertex_kind::corner
                       : d == 2                ? Vertex_kind::crease
                       : d == 1                ? Vertex_kind::dart
                                               : Vertex_kind::smooth;
  }
  return f;
}

/// The features of the refined mesh (numbering of Mesh_topology::refined),
/// derived from the parent's without any search: halves of crease edges are
/// crease edges (tagged when the parent edge was tagged), old vertices keep
/// their kind, a new vertex is a crease vertex on a crease edge and smooth
/// otherwise.
inline Loop_features refined_loop_features(const Mesh_topology& parent, const Loop_features& f,
                                           const Mesh_topology& child) {
  Loop_features c;
  const std::size_t nv = parent.number_of_vertices(), ne = parent.number_of_edges();
  c.edge_is_crease.assign(child.number_of_edges(), 0);
  c.edge_is_tagged.assign(child.number_of_edges(), 0);
  for (Index e = 0; e < child.number_of_edges(); ++e) {
    const Index ph = Mesh_topology::parent_halfedge(child.edge_halfedge(e));
    if (ph == invalid_index) continue;
    const Index pe = parent.edge(ph);
    c.edge_is_crease[e] = f.edge_is_crease[pe];
    c.edge_is_tagged[e] = f.edge_is_tagged[pe];
  }
  c.vertex_kind.resize(nv + ne);
  c.crease_degree.resize(nv + ne);
  std::copy(f.vertex_kind.begin(), f.vertex_kind.end(), c.vertex_kind.begin());
  std::copy(f.crease_degree.begin(), f.crease_degree.end(), c.crease_degree.begin());
  for (std::size_t e = 0; e < ne; ++e) {
    c.vertex_kind[nv + e] = f.edge_is_crease[e] ? Vertex_kind::crease : Vertex_kind::smooth;
    c.crease_degree[nv + e] = f.edge_is_crease[e] ? 2 : 0;
  }
  return c;
}

/// A sector of a crease or corner vertex v: the faces between two consecutive
/// crease edges (or the boundary), counter-clockwise. ring = p_0 ... p_k (k
/// faces), p_0 and p_k on the bounding crease edges; first = the outgoing
/// half-edge v -> p_0.
struct Loop_sector {
  Index first = invalid_index;
  std::vector<Index> ring;
  Index faces() const { return static_cast<Index>(ring.size()) - 1; }
};

/// The sector of vertex v (kind crease or corner) containing face(h), h an
/// outgoing half-edge of v.
inline Loop_sector loop_sector(const Mesh_topology& t, const Loop_features& f, Index v, Index h) {
  const auto crease_he = [&](Index g) { return f.edge_is_crease[t.edge(g)] != 0; };
  // Walk clockwise from h to the crease half-edge that starts the sector.
  Index s = h;
  for (Index guard = 0; !crease_he(s) && guard <= t.number_of_incident_faces(v); ++guard) {
    const Index o = t.opposite(s);  // clockwise: next(opposite(s))
    if (o == invalid_index) break;
    s = Mesh_topology::next(o);
  }
  Loop_sector sec;
  sec.first = s;
  Index g = s;
  for (Index guard = 0; guard <= t.number_of_incident_faces(v); ++guard) {
    sec.ring.push_back(t.target(g));
    const Index n = t.ccw_outgoing(g);
    if (n == invalid_index) {  // boundary: last neighbour is the source of prev(g)
      sec.ring.push_back(t.source(Mesh_topology::prev(g)));
      break;
    }
    if (crease_he(n)) {
      sec.ring.push_back(t.target(n));
      break;
    }
    g = n;
  }
  return sec;
}

}  // namespace relgeo
