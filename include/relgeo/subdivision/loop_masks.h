// relgeo/subdivision/loop_masks.h — vertex classification and the masks of
// Loop subdivision as explicit stencils: refinement (vertex and edge points),
// limit positions and limit tangents (thesis Sec. 2.2.2, Figs. 2.5-2.7).
//
// The stencils are the reference form of every rule (limit-surface
// evaluation and error bounds build their matrices from them); loop_subdivide
// applies the same rules through a fused fast path and the tests check both
// agree.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/mesh/internal/point_access.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/loop_weights.h"

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

/// An affine (weights sum to 1) or vector (weights sum to 0) mask.
template <class FT>
struct Stencil {
  std::vector<Index> vertices;
  std::vector<FT> weights;
  void add(Index v, FT w) {
    vertices.push_back(v);
    weights.push_back(std::move(w));
  }
};

/// sum w_i p_i, coordinate-wise in FT, as relgeo::Point_3<FT> (for a vector
/// stencil: the vector's coordinates).
template <class FT, class P>
Point_3<FT> apply_stencil(const Stencil<FT>& s, const std::vector<P>& points) {
  using A = internal::Point_access<P>;
  Point_3<FT> r{FT(0), FT(0), FT(0)};
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    const P& p = points[s.vertices[i]];
    r.x = FT(r.x + FT(s.weights[i] * A::x(p)));
    r.y = FT(r.y + FT(s.weights[i] * A::y(p)));
    r.z = FT(r.z + FT(s.weights[i] * A::z(p)));
  }
  return r;
}

/// The refinement stencil of (old) vertex v.
template <class K>
Stencil<typename K::FT> vertex_point_stencil(const Mesh_topology& t, const Loop_features& f,
                                             Loop_weights<K>& w, Index v) {
  using FT = typename K::FT;
  Stencil<FT> s;
  switch (f.vertex_kind[v]) {
    case Vertex_kind::smooth:
    case Vertex_kind::dart: {
      const std::vector<Index> ring = t.vertex_ring(v);
      const Index n = static_cast<Index>(ring.size());
      w.reserve(n);
      s.add(v, w.centre(n));
      for (Index p : ring) s.add(p, w.beta(n));
      break;
    }
    case Vertex_kind::crease: {
      s.add(v, w.three_quarters());
      t.for_each_outgoing(v, [&](Index h) {
        if (f.edge_is_crease[t.edge(h)]) s.add(t.target(h), w.eighth());
      });
      if (t.is_boundary_vertex(v)) {  // the last boundary edge comes in, not out
        Index last = invalid_index;
        t.for_each_outgoing(v, [&](Index h) { last = h; });
        s.add(t.source(Mesh_topology::prev(last)), w.eighth());
      }
      break;
    }
    default: s.add(v, w.one());
  }
  return s;
}

/// The refinement stencil of the new vertex on edge e.
template <class K>
Stencil<typename K::FT> edge_point_stencil(const Mesh_topology& t, const Loop_features& f,
                                           Loop_weights<K>& w, Index e) {
  using FT = typename K::FT;
  Stencil<FT> s;
  const Index h = t.edge_halfedge(e), a = t.source(h), b = t.target(h);
  if (f.edge_is_crease[e]) {
    s.add(a, w.half()), s.add(b, w.half());
    return s;
  }
  FT wa = w.three_eighths(), wb = w.three_eighths();
  if (w.options().crease_rules == Loop_crease_rules::biermann_levin_zorin &&
      f.is_special(a) != f.is_special(b)) {
    const Index v = f.is_special(a) ? a : b;
    const Index hv = v == a ? h : t.opposite(h);
    const FT g = w.gamma(loop_sector(t, f, v, hv).faces(), f.vertex_kind[v] == Vertex_kind::corner);
    const FT gv = FT(w.three_quarters() - g);
    (v == a ? wa : wb) = gv;
    (v == a ? wb : wa) = g;
  }
  s.add(a, wa), s.add(b, wb);
  s.add(t.target(Mesh_topology::next(h)), w.eighth());
  s.add(t.target(Mesh_topology::next(t.opposite(h))), w.eighth());
  return s;
}

/// The limit-position stencil of vertex v (thesis Fig. 2.6): smooth/dart
/// (1 - n chi) v + chi sum p_i; crease (1/6, 2/3, 1/6) on its crease
/// neighbours; corner and isolated vertices are fixed.
template <class K>
Stencil<typename K::FT> limit_stencil(const Mesh_topology& t, const Loop_features& f,
                                      Loop_weights<K>& w, Index v) {
  using FT = typename K::FT;
  Stencil<FT> s;
  switch (f.vertex_kind[v]) {
    case Vertex_kind::smooth:
    case Vertex_kind::dart: {
      const std::vector<Index> ring = t.vertex_ring(v);
      const Index n = static_cast<Index>(ring.size());
      w.reserve(n);
      s.add(v, w.limit_centre(n));
      for (Index p : ring) s.add(p, w.chi(n));
      break;
    }
    case Vertex_kind::crease: {
      const Stencil<FT> r = vertex_point_stencil(t, f, w, v);
      s.add(v, w.two_thirds());
      for (std::size_t i = 1; i < r.vertices.size(); ++i) s.add(r.vertices[i], w.sixth());
      break;
    }
    default: s.add(v, w.one());
  }
  return s;
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
template <class K>
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
