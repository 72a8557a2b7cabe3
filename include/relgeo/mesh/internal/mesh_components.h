// relgeo/mesh/internal/mesh_components.h — connected components of a face
// list (faces sharing a vertex are connected) and the Euler characteristic
// V - E + F of each, for any face list with valid indices (manifold or not).
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "relgeo/core/internal/union_find.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

struct Face_components {
  std::vector<Index> component;   ///< of each face, numbered in order of first face
  std::vector<Index> first_face;  ///< of each component
  std::size_t size() const { return first_face.size(); }
};

/// Components by union-find over the vertices. \pre indices < nv.
inline Face_components face_components(const std::vector<Triangle>& faces, std::size_t nv) {
  Union_find<Index> sets(nv);
  for (const Triangle& t : faces)
    for (int i = 1; i < 3; ++i) sets.unite(t[0], t[i]);
  Face_components c;
  c.component.resize(faces.size());
  std::vector<Index> id(nv, invalid_index);
  for (Index f = 0; f < faces.size(); ++f) {
    Index& slot = id[sets.find(faces[f][0])];
    if (slot == invalid_index) {
      slot = static_cast<Index>(c.first_face.size());
      c.first_face.push_back(f);
    }
    c.component[f] = slot;
  }
  return c;
}

/// Vertices (used by a face), edges (distinct vertex pairs of faces) and
/// faces of one component.
struct Euler_counts {
  std::size_t vertices = 0, edges = 0, faces = 0;
  long long characteristic() const {
    return static_cast<long long>(vertices) - static_cast<long long>(edges) + static_cast<long long>(faces);
  }
};

/// The counts of every component: edges found per vertex among the
/// neighbours of larger index of its faces (no global sort).
/// \pre indices < nv, `c` from face_components(faces, nv).
inline std::vector<Euler_counts> euler_counts(const std::vector<Triangle>& faces, std::size_t nv,
                                              const Face_components& c) {
  std::vector<Euler_counts> counts(c.size());
  std::vector<Index> begin(nv + 1, 0);
  for (const Triangle& t : faces)
    for (Index v : t) ++begin[v + 1];
  for (std::size_t v = 0; v < nv; ++v) begin[v + 1] += begin[v];
  std::vector<Index> incident(begin[nv]);
  {
    std::vector<Index> fill(begin.begin(), begin.end() - 1);
    for (Index f = 0; f < faces.size(); ++f)
      for (Index v : faces[f]) incident[fill[v]++] = f;
  }
  std::vector<Index> larger;
  for (Index v = 0; v < nv; ++v) {
    if (begin[v] == begin[v + 1]) continue;  // isolated
    const Index comp = c.component[incident[begin[v]]];
    ++counts[comp].vertices;
    larger.clear();
    for (Index k = begin[v]; k < begin[v + 1]; ++k)
      for (Index w : faces[incident[k]])
        if (w > v) larger.push_back(w);
    std::sort(larger.begin(), larger.end());
    counts[comp].edges += static_cast<std::size_t>(std::unique(larger.begin(), larger.end()) - larger.begin());
  }
  for (Index f = 0; f < faces.size(); ++f) ++counts[c.component[f]].faces;
  return counts;
}

/// The same counts read off the half-edge topology `t` of the faces, when
/// its edges are exactly their distinct vertex pairs: every face has three
/// distinct vertices and no edge was reported non-manifold or misoriented
/// (then each edge joins at most two faces, of one component). No edge list
/// to sort: on the Boolean's outputs this was most of the counts' time.
/// Returns nothing when a face repeats a vertex (euler_counts above then).
/// \pre indices < nv, `c` from face_components(faces, nv), `t` built from
/// the faces with no non_manifold_edge or inconsistent_orientation issue.
inline std::optional<std::vector<Euler_counts>> euler_counts(const std::vector<Triangle>& faces, std::size_t nv,
                                                             const Face_components& c, const Mesh_topology& t) {
  std::vector<Euler_counts> counts(c.size());
  std::vector<unsigned char> seen(nv, 0);
  for (Index f = 0; f < faces.size(); ++f) {
    const Triangle& v = faces[f];
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return std::nullopt;
    Euler_counts& n = counts[c.component[f]];
    ++n.faces;
    for (Index w : v)
      if (!seen[w]) seen[w] = 1, ++n.vertices;
  }
  for (Index e = 0; e < t.number_of_edges(); ++e) ++counts[c.component[Mesh_topology::face(t.edge_halfedge(e))]].edges;
  return counts;
}

}  // namespace relgeo::internal
