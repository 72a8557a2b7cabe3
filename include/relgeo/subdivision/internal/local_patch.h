// relgeo/subdivision/internal/local_patch.h — local subdivision: the piece of
// a Loop mesh around one face (with the rule data of the whole mesh), its
// topology, and one refinement step of it with the rules of loop_rules.h.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/internal/loop_rules.h"
#include "relgeo/subdivision/loop_weights.h"
#include "relgeo/subdivision/stencil.h"

namespace relgeo::internal {

/// A piece of a Loop mesh around one face: the face (faces[0], in its
/// parameter order) and every face incident to its vertices, with the rule
/// data carried from the whole mesh (never recomputed from the piece, whose
/// outer edges are not boundaries) and `dim` values per vertex. The fans of
/// the three vertices of faces[0] are complete, which is all the rules for
/// its children need.
template <class FT>
struct Loop_local_patch {
  std::vector<Triangle> faces;
  Loop_rule_data rules;
  std::size_t dim = 3;
  std::vector<FT> values;
  Index number_of_vertices() const { return static_cast<Index>(rules.kind.size()); }
  const FT* value(Index v) const { return values.data() + std::size_t(v) * dim; }
};

/// The local patch of face f of a mesh (topology t, rule data d); values(v,
/// out) writes the dim values of mesh vertex v. global_ids receives the mesh
/// index of each local vertex.
template <class FT, class Values>
Loop_local_patch<FT> extract_local_patch(const Mesh_topology& t, const Loop_rule_data& d, Index f, std::size_t dim,
                                         Values&& values, std::vector<Index>* global_ids = nullptr) {
  Loop_local_patch<FT> P;
  P.dim = dim;
  std::vector<Index> gfaces{f};
  for (int k = 0; k < 3; ++k)
    t.for_each_outgoing(t.faces()[f][k], [&](Index h) {
      const Index g = Mesh_topology::face(h);
      if (std::find(gfaces.begin(), gfaces.end(), g) == gfaces.end()) gfaces.push_back(g);
    });
  std::vector<Index> ids;
  const auto local = [&](Index v) {
    const auto it = std::find(ids.begin(), ids.end(), v);
    if (it != ids.end()) return static_cast<Index>(it - ids.begin());
    ids.push_back(v);
    return static_cast<Index>(ids.size() - 1);
  };
  for (Index g : gfaces) {
    const Triangle& tr = t.faces()[g];
    P.faces.push_back({local(tr[0]), local(tr[1]), local(tr[2])});
    for (int i = 0; i < 3; ++i) {
      P.rules.crease.push_back(d.crease[3 * g + i]);
      P.rules.sector.push_back(d.sector[3 * g + i]);
    }
  }
  P.values.resize(ids.size() * dim);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    P.rules.kind.push_back(d.kind[ids[i]]);
    values(ids[i], P.values.data() + i * dim);
  }
  if (global_ids) *global_ids = std::move(ids);
  return P;
}

/// Topology of a local patch (outer vertices may be non-manifold: ignored,
/// the rules only walk around the vertices of faces[0]).
template <class FT>
Mesh_topology local_topology(const Loop_local_patch<FT>& P) {
  std::vector<Mesh_issue> ignored;
  return Mesh_topology::build_checked(P.number_of_vertices(), P.faces, ignored);
}

/// Stencils stored back to back (one allocation per array for all of them,
/// not per stencil): stencil i weighs vertices[begin[i] .. begin[i + 1]).
template <class FT>
struct Stencil_list {
  std::vector<std::size_t> begin{0};
  std::vector<Index> vertices;
  std::vector<FT> weights;
  std::size_t size() const { return begin.size() - 1; }
  /// Room for n stencils of about `entries` entries each.
  void reserve(std::size_t n, std::size_t entries) {
    begin.reserve(n + 1), vertices.reserve(n * entries), weights.reserve(n * entries);
  }
  void clear() {
    begin.assign(1, 0);
    vertices.clear();
    weights.clear();
  }
  /// Appends the stencil of entries [from, to) of the given arrays.
  void append(const std::vector<Index>& v, const std::vector<FT>& w, std::size_t from, std::size_t to) {
    vertices.insert(vertices.end(), v.begin() + from, v.begin() + to);
    weights.insert(weights.end(), w.begin() + from, w.begin() + to);
    begin.push_back(vertices.size());
  }
  /// Appends stencil i of another list.
  void append(const Stencil_list& o, std::size_t i) { append(o.vertices, o.weights, o.begin[i], o.begin[i + 1]); }
};

/// One refinement step of a local patch: the children `which` (a bitmask of
/// 1 << c, c as in box_spline.h) of faces[0] as local patches. Only the
/// vertex points of faces[0]'s vertices and the edge points of their edges
/// are computed; they are exactly the vertices of the children's patches.
template <class K>
std::array<Loop_local_patch<typename K::FT>, 4> refine_local_patch(
    const Loop_local_patch<typename K::FT>& P, const Mesh_topology& t, const Loop_weights<K>& w, unsigned which,
    Stencil_list<typename K::FT>* stencils = nullptr) {
  using FT = typename K::FT;
  const Index nv = P.number_of_vertices(), ne = static_cast<Index>(t.number_of_edges());
  const Index nf = static_cast<Index>(P.faces.size());
  const std::size_t dim = P.dim;
  std::vector<FT> cv((std::size_t(nv) + ne) * dim);
  std::vector<std::uint8_t> done(std::size_t(nv) + ne, 0);
  Stencil_list<FT> used;  // every stencil applied, when `stencils` is wanted
  std::vector<std::size_t> used_index;  // per child vertex: its stencil in `used`
  if (stencils) {
    used_index.assign(std::size_t(nv) + ne, 0);
    used.reserve(std::size_t(nv) + ne, 8);
  }
  Stencil<FT> st;  // one buffer for every stencil of the step
  st.vertices.reserve(16), st.weights.reserve(16);
  const auto apply = [&](Index target) {
    FT* out = cv.data() + std::size_t(target) * dim;
    for (std::size_t c = 0; c < dim; ++c) out[c] = FT(0);
    for (std::size_t i = 0; i < st.vertices.size(); ++i) {
      const FT* in = P.value(st.vertices[i]);
      for (std::size_t c = 0; c < dim; ++c) out[c] = FT(out[c] + FT(st.weights[i] * in[c]));
    }
    done[target] = 1;
    if (stencils) used_index[target] = used.size(), used.append(st.vertices, st.weights, 0, st.vertices.size());
  };
  const auto do_edge = [&](Index h) {
    const Index e = t.edge(h);
    if (done[nv + e]) return;
    edge_point_stencil_into(t, P.rules, w, h, st);
    apply(nv + e);
  };
  for (int k = 0; k < 3; ++k) {
    const Index a = P.faces[0][k];
    if (!done[a]) {
      vertex_point_stencil_into(t, P.rules, w, a, st);
      apply(a);
    }
    Index last = invalid_index;
    t.for_each_outgoing(a, [&](Index h) {
      do_edge(h);
      last = h;
    });
    if (t.is_boundary_vertex(a)) do_edge(Mesh_topology::prev(last));
  }
  // Children of every face, with their rule data.
  const Index cnv = nv + ne;
  std::vector<Triangle> cf(4 * std::size_t(nf));
  std::vector<std::uint8_t> ccrease(12 * std::size_t(nf), 0);
  std::vector<Index> csector(12 * std::size_t(nf), 0);
  std::vector<Vertex_kind> ckind(cnv);
  for (Index v = 0; v < nv; ++v) ckind[v] = P.rules.kind[v];
  for (Index e = 0; e < ne; ++e)
    ckind[nv + e] = P.rules.crease[t.edge_halfedge(e)] ? Vertex_kind::crease : Vertex_kind::smooth;
  for (Index lf = 0; lf < nf; ++lf) {
    const Triangle& tr = P.faces[lf];
    Index m[3];
    bool cr[3];
    for (int i = 0; i < 3; ++i) m[i] = nv + t.edge(3 * lf + i), cr[i] = P.rules.crease[3 * lf + i] != 0;
    for (int k = 0; k < 3; ++k) {
      const int km = (k + 2) % 3;
      const Index c = 4 * lf + k;
      cf[c] = {tr[k], m[k], m[km]};
      ccrease[3 * c] = cr[k], ccrease[3 * c + 2] = cr[km];
      csector[3 * c] = P.rules.sector[3 * lf + k];
      csector[3 * c + 1] = cr[k] ? 3 : 0;
      csector[3 * c + 2] = cr[km] ? 3 : 0;
    }
    const Index c = 4 * lf + 3;
    cf[c] = {m[0], m[1], m[2]};
    for (int i = 0; i < 3; ++i) csector[3 * c + i] = cr[i] ? 3 : 0;
  }
  std::array<Loop_local_patch<FT>, 4> out;
  std::vector<Index> map(cnv);
  for (int ci = 0; ci < 4; ++ci) {
    if (!(which & (1u << ci))) continue;
    Loop_local_patch<FT>& Q = out[ci];
    Q.dim = dim;
    const Triangle C = cf[ci];  // child ci of faces[0] (local face 0)
    std::fill(map.begin(), map.end(), invalid_index);
    std::vector<Index> ids;
    const auto local = [&](Index v) {
      if (map[v] == invalid_index) {
        if (!done[v])
          throw Error(Error_code::computation_failure, "Loop local patch: a child vertex was not computed");
        map[v] = static_cast<Index>(ids.size());
        ids.push_back(v);
      }
      return map[v];
    };
    const auto take = [&](Index g) {
      const Triangle& tr = cf[g];
      Q.faces.push_back({local(tr[0]), local(tr[1]), local(tr[2])});
      for (int i = 0; i < 3; ++i) Q.rules.crease.push_back(ccrease[3 * g + i]), Q.rules.sector.push_back(csector[3 * g + i]);
    };
    take(Index(ci));
    for (Index g = 0; g < cf.size(); ++g) {
      if (g == Index(ci)) continue;
      const Triangle& tr = cf[g];
      bool touches = false;
      for (Index v : tr) touches |= v == C[0] || v == C[1] || v == C[2];
      if (touches) take(g);
    }
    Q.values.resize(ids.size() * dim);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      Q.rules.kind.push_back(ckind[ids[i]]);
      std::copy_n(cv.data() + std::size_t(ids[i]) * dim, dim, Q.values.data() + i * dim);
    }
    if (stencils) {  // the stencils of the (single) requested child's vertices
      stencils->clear();
      stencils->reserve(ids.size(), 8);
      for (Index v : ids) stencils->append(used, used_index[v]);
    }
  }
  return out;
}

}  // namespace relgeo::internal
