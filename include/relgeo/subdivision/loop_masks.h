// relgeo/subdivision/loop_masks.h — the masks of Loop subdivision as explicit
// stencils: refinement (vertex and edge points), limit positions and limit
// tangents (thesis Sec. 2.2.2, Figs. 2.5-2.7), for the vertices and edges of
// a mesh.
//
// The refinement and limit weights come from internal/loop_rules.h, the one
// place Loop's rules are written; Loop_subdivider's fused refinement and the
// limit evaluator read the same rules, and the tests check the fused path
// against these stencils exactly.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "relgeo/kernel/concepts.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/internal/loop_rules.h"
#include "relgeo/subdivision/loop_features.h"
#include "relgeo/subdivision/loop_weights.h"
#include "relgeo/subdivision/stencil.h"

namespace relgeo {

namespace internal {
/// The stencil of a vertex rule (vertex_point_rule or limit_point_rule) at
/// vertex v of a whole mesh, reserving v's valence first.
template <ConstructionKernel_3 K, class Rule_of>
Stencil<typename K::FT> mesh_vertex_stencil(const Mesh_topology& t, const Loop_features& f, Loop_weights<K>& w,
                                            Index v, Rule_of&& rule_of) {
  w.reserve(t.valence(v));
  Stencil<typename K::FT> s;
  add_vertex_rule(t, Mesh_rule_source{t, f}, rule_of(w, f.vertex_kind[v], t.number_of_incident_faces(v)), v, s);
  return s;
}
}  // namespace internal

/// The refinement stencil of (old) vertex v: smooth and dart (1 - n beta) v
/// + beta sum p_i over the ring; crease (3/4, 1/8, 1/8) with its crease
/// neighbours; corner and isolated vertices fixed.
template <ConstructionKernel_3 K>
Stencil<typename K::FT> vertex_point_stencil(const Mesh_topology& t, const Loop_features& f,
                                             Loop_weights<K>& w, Index v) {
  return internal::mesh_vertex_stencil(t, f, w, v, internal::vertex_point_rule<K>);
}

/// The refinement stencil of the new vertex on edge e: its ends, then (not
/// on creases) the two opposite vertices.
template <ConstructionKernel_3 K>
Stencil<typename K::FT> edge_point_stencil(const Mesh_topology& t, const Loop_features& f,
                                           Loop_weights<K>& w, Index e) {
  Stencil<typename K::FT> s;
  internal::edge_point_stencil_into(t, internal::Mesh_rule_source{t, f}, w, t.edge_halfedge(e), s);
  return s;
}

/// The limit-position stencil of vertex v (thesis Fig. 2.6): smooth/dart
/// (1 - n chi) v + chi sum p_i; crease (1/6, 2/3, 1/6) on its crease
/// neighbours; corner and isolated vertices are fixed.
template <ConstructionKernel_3 K>
Stencil<typename K::FT> limit_stencil(const Mesh_topology& t, const Loop_features& f,
                                      Loop_weights<K>& w, Index v) {
  return internal::mesh_vertex_stencil(t, f, w, v, internal::limit_point_rule<K>);
}

/// Two limit tangent masks at vertex v (weights sum to 0), for the surface
/// piece containing face(h) (h an outgoing half-edge of v; only crease and
/// corner vertices, whose limit surface has one tangent plane per sector,
/// look at it). Each mask is defined up to a positive factor; the cross
/// product first x second points to the outside (the side from which faces
/// are counter-clockwise), so it is the exact limit normal direction.
///
///  * smooth/dart, valence n, c = cos(2 pi / n), neighbours p_0..p_{n-1} ccw:
///    first  = sum T_i(c) p_i = sum cos(2 pi i / n) p_i,
///    second = sum U_{i-1}(c) p_i = sum sin(2 pi i / n) p_i / sin(2 pi / n)
///    (Chebyshev polynomials: rational at n = 3, 4, 6 and wherever c is),
///    plus the weight -(sum of the others) at v, which is 0 when c is exact
///    and keeps the mask translation invariant when c is approximated.
///  * crease vertex, sector p_0..p_k (k faces), c = cos(pi / k),
///    S = sum_{i=1}^{k-1} U_{i-1}(c): first = p_0 - p_k (along the crease,
///    the cubic B-spline's tangent); second (across, into the sector) = the
///    left eigenvector of the local refinement matrix:
///      k = 1: p_0 + p_1 - 2 v (eigenvalue 1/4);
///      Hoppe rules: (2c+1) U_{i-1}(c) at p_i, 1 - S at p_0 and p_k,
///        -2(1 - S) - (2c+1) S at v (eigenvalue 3/8 + c/4; k = 2: p_1 - v,
///        k = 3: -p_0 + 2p_1 + 2p_2 - p_3 - 2v);
///      BLZ rules: 2 U_{i-1}(c) at p_i, 1 - S at p_0 and p_k, -2 at v
///        (eigenvalue 1/2 for every k).
///  * corner: first = p_0 - v, second = p_k - v (the end tangents of the
///    two crease curves, exact: eigenvalue 1/2 of the end rule).
///  * isolated: empty stencils.
template <ConstructionKernel_3 K>
std::pair<Stencil<typename K::FT>, Stencil<typename K::FT>> tangent_stencils(
    const Mesh_topology& t, const Loop_features& f, Loop_weights<K>& w, Index v,
    Index h = invalid_index) {
  using FT = typename K::FT;
  using Tr = typename Loop_weights<K>::Traits;
  Stencil<FT> s1, s2;
  const Vertex_kind kind = f.vertex_kind[v];
  if (kind == Vertex_kind::isolated) return {s1, s2};
  if (kind == Vertex_kind::smooth || kind == Vertex_kind::dart) {
    const std::vector<Index> ring = t.vertex_ring(v);
    const Index n = static_cast<Index>(ring.size());
    w.reserve(n);
    const FT c = w.cos_2pi_n(n), two_c = FT(c + c);
    FT t_prev = w.one(), t_cur = c;        // T_0, T_1
    FT u_prev = FT(0), u_cur = w.one();    // U_{-1}, U_0
    FT sum1 = FT(0), sum2 = FT(0);
    for (Index i = 0; i < n; ++i) {
      s1.add(ring[i], t_prev);  // T_i
      s2.add(ring[i], u_prev);  // U_{i-1}
      sum1 = FT(sum1 + t_prev), sum2 = FT(sum2 + u_prev);
      FT t_next = FT(FT(two_c * t_cur) - t_prev), u_next = FT(FT(two_c * u_cur) - u_prev);
      t_prev = std::move(t_cur), t_cur = std::move(t_next);
      u_prev = std::move(u_cur), u_cur = std::move(u_next);
    }
    // The weights sum to 0 exactly when c is cos(2 pi / n) exactly; with an
    // approximated c the remainder goes to v, so the mask stays a vector
    // mask (translation invariant) in every number type.
    s1.add(v, FT(-sum1)), s2.add(v, FT(-sum2));
    return {s1, s2};
  }
  if (h == invalid_index) h = t.vertex_halfedge(v);
  const Loop_sector sec = loop_sector(t, f, v, h);
  const Index k = sec.faces();
  const std::vector<Index>& p = sec.ring;
  if (kind == Vertex_kind::corner) {
    s1.add(p.front(), w.one()), s1.add(v, FT(-w.one()));
    s2.add(p.back(), w.one()), s2.add(v, FT(-w.one()));
    return {s1, s2};
  }
  s1.add(p.front(), w.one()), s1.add(p.back(), FT(-w.one()));
  if (k == 1) {
    s2.add(p[0], w.one()), s2.add(p[1], w.one()), s2.add(v, Tr::rational(-2, 1));
    return {s1, s2};
  }
  const FT c = Tr::cos_2pi(1, 2 * long(k)), two_c = FT(c + c);
  const bool blz = w.options().crease_rules == Loop_crease_rules::biermann_levin_zorin;
  const FT scale = blz ? Tr::rational(2, 1) : FT(two_c + w.one());
  FT sum = FT(0), u_prev = FT(0), u_cur = w.one();  // U_{-1}, U_0
  std::vector<FT> inner;
  for (Index i = 1; i < k; ++i) {  // U_{i-1}
    sum = FT(sum + u_cur);
    inner.push_back(u_cur);
    FT u_next = FT(FT(two_c * u_cur) - u_prev);
    u_prev = std::move(u_cur), u_cur = std::move(u_next);
  }
  const FT end = FT(w.one() - sum);
  s2.add(p.front(), end);
  for (Index i = 1; i < k; ++i) s2.add(p[i], FT(scale * inner[i - 1]));
  s2.add(p.back(), end);
  s2.add(v, blz ? Tr::rational(-2, 1) : FT(FT(Tr::rational(-2, 1) * end) - FT(scale * sum)));
  return {s1, s2};
}

}  // namespace relgeo
