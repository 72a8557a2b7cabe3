// relgeo/subdivision/internal/exact_limit.h — the exact limit position of a
// vertex: its limit mask where that is an exact eigenvector, otherwise the
// fixed point of its 1-ring subdivision matrices (built from loop_rules.h).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/internal/loop_rules.h"
#include "relgeo/subdivision/internal/small_solver.h"
#include "relgeo/subdivision/loop_weights.h"
#include "relgeo/subdivision/stencil.h"

namespace relgeo::internal {

/// Whether the limit mask of loop_masks.h is an exact eigenvector at vertex
/// a: crease vertices and corners always; smooth vertices whose edges all
/// follow the standard rule (no darts; under BLZ no special neighbour with a
/// non-standard gamma).
inline bool limit_mask_is_exact(const Mesh_topology& t, const Loop_rule_data& d, const Loop_options& o, Index a) {
  switch (d.kind[a]) {
    case Vertex_kind::crease:
    case Vertex_kind::corner:
    case Vertex_kind::isolated: return true;
    case Vertex_kind::dart: return false;
    case Vertex_kind::smooth: return standard_weights_around(t, d, o, a);
  }
  return false;
}

/// The 1-ring subdivision matrix (m = n + 1 rows, row-major) of a smooth
/// vertex or dart a with counter-clockwise ring `ring` (half-edges a ->
/// ring[i] in `he`), on slots 0 = a, i + 1 = ring[i]: row 0 is a's vertex
/// rule, row i + 1 the edge rule of edge (a, ring[i]). With `first_step`
/// the rules see the neighbours' own kinds (BLZ weights apply); otherwise the
/// kinds they have from level 1 on (new vertices: crease vertices on crease
/// edges, smooth elsewhere), so the matrix is the stationary S_inf.
template <class K>
std::vector<typename K::FT> ring_matrix(const Mesh_topology& t, const Loop_rule_data& d, const Loop_weights<K>& w,
                                        Index a, const std::vector<Index>& ring, const std::vector<Index>& he,
                                        bool first_step) {
  using FT = typename K::FT;
  const std::size_t n = ring.size(), m = n + 1;
  std::vector<FT> S(m * m, FT(0));
  const Vertex_rule<FT> vertex = vertex_point_rule(w, d.kind[a], Index(n));
  S[0] = *vertex.centre;
  for (std::size_t i = 0; i < n; ++i) S[i + 1] = FT(S[i + 1] + *vertex.neighbour);
  for (std::size_t i = 0; i < n; ++i) {
    FT* row = S.data() + (i + 1) * m;
    const bool crease = d.crease[he[i]] != 0;
    const Vertex_kind kx = first_step ? d.kind[ring[i]] : crease ? Vertex_kind::crease : Vertex_kind::smooth;
    const auto edge = edge_point_rule(
        w, crease, [&](int end) { return end == 0 ? d.kind[a] : kx; },
        [&](int end) { return d.sector[end == 0 ? he[i] : t.opposite(he[i])]; });
    row[0] = FT(row[0] + edge.end_a()), row[i + 1] = FT(row[i + 1] + edge.end_b());
    if (edge.shape() == Edge_shape::crease) continue;
    const std::size_t ip = (i + n - 1) % n, in = (i + 1) % n;
    row[ip + 1] = FT(row[ip + 1] + edge.wing()), row[in + 1] = FT(row[in + 1] + edge.wing());
  }
  return S;
}

/// l <- l S for a row vector l of size m.
template <class FT>
void multiply_from_left(std::vector<FT>& l, const std::vector<FT>& S) {
  const std::size_t m = l.size();
  std::vector<FT> ls(m, FT(0));
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < m; ++j) ls[j] = FT(ls[j] + FT(l[i] * S[i * m + j]));
  l = std::move(ls);
}

/// The left eigenvector l of S for eigenvalue 1 with sum l = 1: (S^T - I) l
/// = 0 with the first equation replaced by sum l = 1, solved in FT.
template <class FT>
std::vector<FT> left_fixed_point(const std::vector<FT>& S, std::size_t m, const FT& one) {
  std::vector<FT> A(m * m), rhs(m, FT(0));
  for (std::size_t j = 0; j < m; ++j)
    for (std::size_t i = 0; i < m; ++i) A[j * m + i] = i == j ? FT(S[i * m + j] - one) : S[i * m + j];
  for (std::size_t i = 0; i < m; ++i) A[i] = one;
  rhs[0] = one;
  return solve_small_system(std::move(A), std::move(rhs));
}

/// The exact limit position (dim values) of vertex a of a local patch or mesh
/// whose fan is complete in t.
///
/// Crease vertices, corners: the limit masks (exact). Smooth vertices and
/// darts: from level 1 on, the 1-ring subdivision matrix S_inf of a is
/// stationary (its neighbours are new vertices, special only across crease
/// edges, so no BLZ weight applies any more); the limit is l S_0 P with S_0
/// the actual first step (BLZ weights included) and l the left eigenvector of
/// S_inf for eigenvalue 1 (l S_inf = l, sum l = 1): the standard limit mask
/// for smooth vertices (chi, 1 - n chi), solved in FT for darts (whose crease
/// edge keeps the rule 1/2, 1/2). Where S_0 = S_inf and a is not a dart this
/// is exactly the limit mask (limit_mask_is_exact).
template <class K>
std::vector<typename K::FT> exact_limit_values(const Mesh_topology& t, const Loop_rule_data& d,
                                               const Loop_weights<K>& w, Index a, std::size_t dim,
                                               const typename K::FT* values) {
  using FT = typename K::FT;
  std::vector<FT> out(dim, FT(0));
  const auto add = [&](Index v, const FT& wt) {
    for (std::size_t c = 0; c < dim; ++c) out[c] = FT(out[c] + FT(wt * values[std::size_t(v) * dim + c]));
  };
  const Vertex_kind kind = d.kind[a];
  if (kind != Vertex_kind::smooth && kind != Vertex_kind::dart) {  // the limit stencil is exact
    Stencil<FT> s;
    limit_stencil_into(t, d, w, a, s);
    for (std::size_t i = 0; i < s.vertices.size(); ++i) add(s.vertices[i], s.weights[i]);
    return out;
  }
  // Ring in counter-clockwise order, with the half-edges a -> ring[i] (a is interior).
  std::vector<Index> ring, he;
  t.for_each_outgoing(a, [&](Index h) { ring.push_back(t.target(h)), he.push_back(h); });
  const std::size_t n = ring.size(), m = n + 1;
  std::vector<FT> l(m);
  if (kind == Vertex_kind::smooth) {
    const Vertex_rule<FT> limit = limit_point_rule(w, kind, Index(n));
    l[0] = *limit.centre;
    for (std::size_t i = 0; i < n; ++i) l[i + 1] = *limit.neighbour;
  } else {
    l = left_fixed_point(ring_matrix(t, d, w, a, ring, he, false), m, w.one());
  }
  bool first_step_differs = kind == Vertex_kind::smooth && !limit_mask_is_exact(t, d, w.options(), a);
  if (kind == Vertex_kind::dart)
    for (std::size_t i = 0; i < n; ++i)
      first_step_differs |= edge_rule_is_modified(w.options(), d.crease[he[i]] != 0, kind, d.kind[ring[i]]);
  if (first_step_differs) multiply_from_left(l, ring_matrix(t, d, w, a, ring, he, true));
  add(a, l[0]);
  for (std::size_t i = 0; i < n; ++i) add(ring[i], l[i + 1]);
  return out;
}

}  // namespace relgeo::internal
