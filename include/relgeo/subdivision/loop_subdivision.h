// relgeo/subdivision/loop_subdivision.h — Loop refinement with crease, boundary
// and corner rules, limit positions and limit meshes, under any kernel.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/kernel/compiled_kernels.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/kernel_for_number.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/internal/loop_rules.h"
#include "relgeo/subdivision/internal/point_algebra.h"
#include "relgeo/subdivision/loop_features.h"
#include "relgeo/subdivision/loop_masks.h"
#include "relgeo/subdivision/loop_weights.h"

namespace relgeo {

/// \brief Loop subdivision under kernel K: refinement, limit positions, limit
/// meshes. Holds the options and the weight table (reuse one object for many
/// calls to compute the weights once).
///
/// Every step requires a mesh that is edge- and vertex-manifold, consistently
/// oriented, with no repeated vertex in a face, valid tags and finite
/// coordinates, and no two faces sharing two edges (a two-face pillow, whose
/// refinement is not a manifold); it throws Invalid_mesh (listing the issues),
/// Invalid_input (the pillow) or Non_finite_input otherwise, and
/// Error (computation_failure) when finite coordinates overflow in the
/// kernel's arithmetic. Open meshes are fine (boundary = crease rules);
/// isolated vertices are kept fixed; geometrically degenerate (collinear)
/// faces are refined like any other.
///
/// Output numbering: vertex i of the input is vertex i of the output (moved);
/// the new vertex of edge e (Mesh_topology edge numbering of the input) is
/// vertex V + e; face f becomes faces 4f..4f+3: (v0, m0, m2), (v1, m1, m0),
/// (v2, m2, m1), (m0, m1, m2), m_i the new vertex of edge (v_i, v_i+1). Each
/// tagged crease (a, b) becomes the tagged creases (a, m), (m, b); corner
/// tags are kept.
///
/// Complexity: O(V + F) per level: the adjacency is built (and the input
/// validated) once, then derived level by level (Mesh_topology::refined).
/// The object keeps scratch buffers between calls (repeated calls do not
/// reallocate them): use one object per thread.
template <ConstructionKernel_3 K>
class Loop_subdivider {
 public:
  using FT = typename K::FT;
  using Point = typename K::Point_3;
  using Mesh = Triangle_mesh<Point>;

  /// K is a type argument only: refinement uses its number type
  /// (constructions in FT), never a kernel object.
  explicit Loop_subdivider(const Loop_options& options = {}) : weights_(options) {}

  const Loop_options& options() const { return weights_.options(); }
  Loop_weights<K>& weights() { return weights_; }

  /// The mesh after `levels` refinement steps (levels = 0: a copy).
  Mesh refine(const Mesh& m, unsigned levels) {
    const Default_fp_environment_if<K::is_certified> environment;
    check_coordinates(m);
    if (levels == 0) return m;
    Level lv = analyse(m), next;
    Mesh cur = step(m, lv, false, levels > 1 ? &next : nullptr);
    for (unsigned i = 1; i < levels; ++i) {
      lv = std::move(next);
      cur = step(cur, lv, false, i + 1 < levels ? &next : nullptr);
    }
    check_result(cur.vertices, "refinement");
    return cur;
  }

  /// The limit mesh at level k (thesis Sec. 5.2): refine k times, then move
  /// every vertex to its limit position (same connectivity as refine(m, k)).
  /// The last refinement and the limit masks are fused in one pass, so no
  /// adjacency of the finest mesh is built.
  Mesh limit_mesh(const Mesh& m, unsigned levels) {
    const Default_fp_environment_if<K::is_certified> environment;
    check_coordinates(m);
    if (levels == 0) {
      Mesh r = m;
      r.vertices = limit_positions(m);
      return r;
    }
    Level lv = analyse(m), next;
    Mesh cur = m;
    for (unsigned i = 0; i + 1 < levels; ++i) {
      cur = step(cur, lv, false, &next);
      lv = std::move(next);
    }
    Mesh r = step(cur, lv, true, nullptr);
    check_result(r.vertices, "limit mesh");
    return r;
  }

  /// The limit positions of the mesh's own vertices (stencils of loop_masks.h).
  /// The same input contract as refine (analyse).
  std::vector<Point> limit_positions(const Mesh& m) {
    const Default_fp_environment_if<K::is_certified> environment;
    check_coordinates(m);
    const Mesh_topology t = Mesh_topology::build(m);
    require_no_faces_sharing_two_edges(t, "Loop subdivision");
    const Loop_features f = classify_loop_features(t, m.tags);
    std::vector<Point> out;
    out.reserve(m.vertices.size());
    for (Index v = 0; v < m.vertices.size(); ++v) {
      const Point_3<FT> p = apply_stencil(limit_stencil(t, f, weights_, v), m.vertices);
      out.push_back(A::make(p.x, p.y, p.z));
    }
    check_result(out, "limit positions");
    return out;
  }

  /// The adjacency and features of one level.
  struct Level {
    Mesh_topology topology;
    Loop_features features;
  };
  /// Builds (and so validates) the adjacency and features of a mesh.
  /// \throws Invalid_mesh as Mesh_topology::build and classify_loop_features;
  /// Invalid_input for two faces sharing two edges.
  static Level analyse(const Mesh& m) {
    Level lv{Mesh_topology::build(m), {}};
    require_no_faces_sharing_two_edges(lv.topology, "Loop subdivision");
    lv.features = classify_loop_features(lv.topology, m.tags);
    return lv;
  }

  /// One refinement step of m, whose adjacency is lv (fused with the limit
  /// masks when `to_limit`). When `next` is given, it receives the adjacency
  /// of the result, derived without search (Mesh_topology::refined).
  Mesh step(const Mesh& m, const Level& lv, bool to_limit, Level* next);
  /// One refinement step (analyse + step).
  Mesh step(const Mesh& m, bool to_limit) {
    check_coordinates(m);
    return step(m, analyse(m), to_limit, nullptr);
  }

 private:
  using A = internal::Point_access<Point>;
  using Acc = Point_3<FT>;
  static constexpr bool native = std::is_same_v<Point, Acc>;

  static void check_coordinates(const Mesh& m) {
    for (std::size_t v = 0; v < m.vertices.size(); ++v)
      if (!internal::point_is_finite(m.vertices[v]))
        throw Non_finite_input("Loop subdivision: vertex " + std::to_string(v) +
                               " has a NaN or infinite coordinate");
  }
  // Finite input can overflow in floating point (a vertex's neighbours are
  // summed before they are weighted): refuse rather than return infinities
  // (test/data/bad/coordinates_max.off; doc/reliability.md).
  static void check_result(const std::vector<Point>& out, const char* what) {
    for (std::size_t v = 0; v < out.size(); ++v)
      if (!internal::point_is_finite(out[v]))
        throw Error(Error_code::computation_failure,
                    std::string("Loop subdivision: the ") + what + " overflows at vertex " + std::to_string(v) +
                        " (coordinates too close to the largest finite value of the number type)");
  }

  bool blz() const { return options().crease_rules == Loop_crease_rules::biermann_levin_zorin; }

  // The named steps of step(), in order. Each reads the parent's adjacency lv
  // and coordinates p and writes the scratch members below or the result.
  const Acc* coordinates(const Mesh& m);
  void sum_rings(const Level& lv, const Acc* p);
  void find_sector_sizes(const Level& lv);
  void vertex_points(const Level& lv, const Acc* p, std::vector<Acc>& q) const;
  void mark_explicit_rings(const Level& lv);
  void edge_points(const Level& lv, const Acc* p, std::vector<Acc>& q, bool to_limit);
  void child_faces(const Mesh& m, const Level& lv, const std::vector<Acc>& q, bool to_limit, Mesh& out);
  static void child_tags(const Mesh& m, const Level& lv, Mesh& out);
  void limit_of_new_vertices(const Level& lv, std::vector<Acc>& q);
  void limit_of_old_vertices(const Level& lv, const Acc* p, std::vector<Acc>& q);

  Loop_weights<K> weights_;
  // Scratch buffers of step(), members so that repeated calls reuse their
  // memory: coordinates in FT (CGAL points), per vertex the ring sum, the
  // crease-neighbour sum, the valence, the refined ring sum (explicit_ring),
  // per face the sum of its new vertices (wing), per half-edge the sector size.
  std::vector<Acc> coords_, ring_, crease_ring_, wing_, ring2_;
  std::vector<std::uint8_t> explicit_ring_;
  std::vector<Index> valence_, sector_faces_;
  bool any_crease_ = false;
  bool any_special_ = false;  // a crease edge or a tagged corner (BLZ needs sectors even without creases)
};

template <ConstructionKernel_3 K>
auto Loop_subdivider<K>::step(const Mesh& m, const Level& lv, bool to_limit, Level* next) -> Mesh {
  const Acc* p = coordinates(m);
  sum_rings(lv, p);
  find_sector_sizes(lv);
  Mesh out;
  std::vector<Acc> q_buf;
  std::vector<Acc>& q = [&]() -> std::vector<Acc>& {
    if constexpr (native) return out.vertices;
    else return q_buf;
  }();
  q.resize(m.vertices.size() + lv.topology.number_of_edges());
  vertex_points(lv, p, q);
  if (to_limit) mark_explicit_rings(lv);
  edge_points(lv, p, q, to_limit);
  child_faces(m, lv, q, to_limit, out);
  child_tags(m, lv, out);
  if (next) {
    next->topology = Mesh_topology::refined(lv.topology, out.faces);
    next->features = refined_loop_features(lv.topology, lv.features, next->topology);
  }
  if (to_limit) {
    // In place: new vertices first (they read the old vertices' refined
    // positions), then the old ones (they read only ring sums).
    limit_of_new_vertices(lv, q);
    limit_of_old_vertices(lv, p, q);
  }
  if constexpr (!native) {
    out.vertices.reserve(q.size());
    for (Acc& r : q) out.vertices.push_back(A::make(std::move(r.x), std::move(r.y), std::move(r.z)));
  }
  return out;
}

// Coordinates in FT (relgeo points already are; CGAL points are read once).
template <ConstructionKernel_3 K>
auto Loop_subdivider<K>::coordinates(const Mesh& m) -> const Acc* {
  if constexpr (native) {
    return m.vertices.data();
  } else {
    coords_.resize(m.vertices.size());
    for (std::size_t v = 0; v < m.vertices.size(); ++v)
      coords_[v] = Acc{A::x(m.vertices[v]), A::y(m.vertices[v]), A::z(m.vertices[v])};
    return coords_.data();
  }
}

// Ring sums, crease-neighbour sums and valences, edge by edge (no ordered
// rings needed); reserves the weights of the largest valence.
template <ConstructionKernel_3 K>
void Loop_subdivider<K>::sum_rings(const Level& lv, const Acc* p) {
  const Mesh_topology& t = lv.topology;
  const Loop_features& f = lv.features;
  const Index nv = static_cast<Index>(t.number_of_vertices()), ne = static_cast<Index>(t.number_of_edges());
  ring_.assign(nv, Acc{FT(0), FT(0), FT(0)});
  valence_.assign(nv, 0);
  any_crease_ = false;
  for (Index e = 0; e < ne; ++e) any_crease_ |= f.edge_is_crease[e] != 0;
  if (any_crease_) crease_ring_.assign(nv, Acc{FT(0), FT(0), FT(0)});
  // A tagged corner needs no crease edge, and BLZ's edge rule next to it
  // needs its sector size all the same (fuzz/loop_subdivision found the
  // sizes read from a buffer never filled).
  any_special_ = any_crease_;
  for (Index v = 0; v < nv && !any_special_; ++v) any_special_ = f.is_special(v);
  for (Index e = 0; e < ne; ++e) {
    const Index h = t.edge_halfedge(e), a = t.source(h), b = t.target(h);
    internal::accumulate_point(ring_[a], p[b]), internal::accumulate_point(ring_[b], p[a]);
    ++valence_[a], ++valence_[b];
    if (f.edge_is_crease[e])
      internal::accumulate_point(crease_ring_[a], p[b]), internal::accumulate_point(crease_ring_[b], p[a]);
  }
  Index max_valence = 6;
  for (Index v = 0; v < nv; ++v) max_valence = std::max(max_valence, valence_[v]);
  weights_.reserve(max_valence);
}

// BLZ: the sector size of every outgoing half-edge of a special vertex.
template <ConstructionKernel_3 K>
void Loop_subdivider<K>::find_sector_sizes(const Level& lv) {
  if (!blz() || !any_special_) return;
  sector_faces_.assign(lv.topology.number_of_halfedges(), 0);
  internal::fill_sector_faces(lv.topology, lv.features, sector_faces_);
}

// Vertex points: the vertex rule on the pre-summed ring or crease neighbours.
template <ConstructionKernel_3 K>
void Loop_subdivider<K>::vertex_points(const Level& lv, const Acc* p, std::vector<Acc>& q) const {
  const Index nv = static_cast<Index>(lv.topology.number_of_vertices());
  for (Index v = 0; v < nv; ++v) {
    const internal::Vertex_rule<FT> r = internal::vertex_point_rule(weights_, lv.features.vertex_kind[v], valence_[v]);
    switch (r.neighbours) {
      case internal::Rule_neighbours::ring: q[v] = internal::point_combination(*r.centre, p[v], *r.neighbour, ring_[v]); break;
      case internal::Rule_neighbours::crease:
        q[v] = internal::point_combination(*r.centre, p[v], *r.neighbour, crease_ring_[v]);
        break;
      case internal::Rule_neighbours::none: q[v] = p[v]; break;  // fixed: weight 1, copied
    }
  }
}

// With to_limit, the limit masks of the refined mesh are accumulated on the
// way, from the parent's adjacency (no adjacency of the refined mesh):
//  old vertex v: its neighbours are the new vertices of its edges (ring,
//  reused: the parent's ring sums are no longer needed);
//  new vertex of a smooth edge (interior, valence 6): the two moved
//  endpoints and the new vertices of the other edges of both faces (from
//  per-face sums of the new vertices, `wing`);
//  new vertex of a crease edge: its crease neighbours, the moved endpoints.
// A smooth vertex all of whose edges follow the standard rule has the refined
// ring sum n e p + (e + 2 w) R (R its ring sum, e and w the standard end and
// wing weights): no accumulation. The others (darts; with BLZ, ends of
// modified edges) sum their edge points explicitly.
template <ConstructionKernel_3 K>
void Loop_subdivider<K>::mark_explicit_rings(const Level& lv) {
  const Mesh_topology& t = lv.topology;
  const Loop_features& f = lv.features;
  const Index nv = static_cast<Index>(t.number_of_vertices()), ne = static_cast<Index>(t.number_of_edges());
  wing_.resize(t.number_of_faces());
  explicit_ring_.assign(any_special_ ? nv : 0, 0);  // without creases and corners no ring is explicit
  if (!any_special_) return;
  for (Index v = 0; v < nv; ++v) explicit_ring_[v] = f.vertex_kind[v] == Vertex_kind::dart;
  for (Index e = 0; e < ne; ++e) {
    const Index h = t.edge_halfedge(e), a = t.source(h), b = t.target(h);
    if (internal::edge_rule_is_modified(options(), f.edge_is_crease[e] != 0, f.vertex_kind[a], f.vertex_kind[b]))
      explicit_ring_[a] = explicit_ring_[b] = 1;
  }
  ring2_.resize(nv);
  for (Index v = 0; v < nv; ++v)
    if (explicit_ring_[v]) ring2_[v] = Acc{FT(0), FT(0), FT(0)};
}

// Edge points: the edge rule with equal weights factored out (ends and wings
// of a standard edge are summed first).
template <ConstructionKernel_3 K>
void Loop_subdivider<K>::edge_points(const Level& lv, const Acc* p, std::vector<Acc>& q, bool to_limit) {
  const Mesh_topology& t = lv.topology;
  const Loop_features& f = lv.features;
  const Index nv = static_cast<Index>(t.number_of_vertices()), ne = static_cast<Index>(t.number_of_edges());
  for (Index e = 0; e < ne; ++e) {
    const Index h = t.edge_halfedge(e), a = t.source(h), b = t.target(h);
    const auto rule = internal::edge_point_rule(
        weights_, f.edge_is_crease[e] != 0, [&](int end) { return f.vertex_kind[end == 0 ? a : b]; },
        [&](int end) { return sector_faces_[end == 0 ? h : t.opposite(h)]; });
    Acc& r = q[nv + e];
    if (rule.shape() == internal::Edge_shape::crease) {
      r = internal::point_combination(rule.end_a(), p[a], rule.end_b(), p[b]);
    } else {
      const Index c = t.target(Mesh_topology::next(h));
      const Index d = t.target(Mesh_topology::next(t.opposite(h)));
      if (rule.shape() == internal::Edge_shape::standard)
        r = internal::point_combination(rule.end_a(), internal::point_sum(p[a], p[b]), rule.wing(),
                                        internal::point_sum(p[c], p[d]));
      else
        r = internal::point_sum(internal::point_combination(rule.end_a(), p[a], rule.end_b(), p[b]),
                                internal::point_combination(rule.wing(), p[c], rule.wing(), p[d]));
    }
    if (to_limit && any_special_) {
      if (explicit_ring_[a]) internal::accumulate_point(ring2_[a], r);
      if (explicit_ring_[b]) internal::accumulate_point(ring2_[b], r);
    }
  }
}

// The four children of every face (with to_limit, the per-face sums of the
// new vertices).
template <ConstructionKernel_3 K>
void Loop_subdivider<K>::child_faces(const Mesh& m, const Level& lv, const std::vector<Acc>& q, bool to_limit,
                                     Mesh& out) {
  const Mesh_topology& t = lv.topology;
  const Index nv = static_cast<Index>(m.vertices.size()), nf = static_cast<Index>(m.faces.size());
  out.faces.resize(4 * std::size_t(nf));
  for (Index fi = 0; fi < nf; ++fi) {
    const Triangle& tr = m.faces[fi];
    const Index m0 = nv + t.edge(3 * fi), m1 = nv + t.edge(3 * fi + 1), m2 = nv + t.edge(3 * fi + 2);
    Triangle* o = &out.faces[4 * std::size_t(fi)];
    o[0] = {tr[0], m0, m2};
    o[1] = {tr[1], m1, m0};
    o[2] = {tr[2], m2, m1};
    o[3] = {m0, m1, m2};
    if (to_limit) wing_[fi] = internal::point_sum(q[m0], internal::point_sum(q[m1], q[m2]));
  }
}

// Each tagged crease (a, b) becomes (a, m), (m, b); corner tags are kept.
template <ConstructionKernel_3 K>
void Loop_subdivider<K>::child_tags(const Mesh& m, const Level& lv, Mesh& out) {
  if (m.tags.empty()) return;
  const Index nv = static_cast<Index>(m.vertices.size()), ne = static_cast<Index>(lv.topology.number_of_edges());
  std::vector<Edge> creases;
  for (Index e = 0; e < ne; ++e)
    if (lv.features.edge_is_tagged[e]) {
      const Edge ab = lv.topology.edge_vertices(e);
      creases.push_back(Edge{ab.a, nv + e});
      creases.push_back(Edge{ab.b, nv + e});
    }
  out.tags.set_creases(std::move(creases));
  out.tags.set_corners(std::vector<Index>(m.tags.corners().begin(), m.tags.corners().end()));
}

// Limit positions of the new vertices, in place. A new vertex m of a smooth
// edge (smooth, valence 6) between faces f and g: (1 - 6 chi) m + chi (a' +
// b' + wings), and the wings are the face sums of f and g minus m twice. A
// new vertex of a crease edge: the crease limit rule on the moved ends.
template <ConstructionKernel_3 K>
void Loop_subdivider<K>::limit_of_new_vertices(const Level& lv, std::vector<Acc>& q) {
  const Mesh_topology& t = lv.topology;
  const Index nv = static_cast<Index>(t.number_of_vertices()), ne = static_cast<Index>(t.number_of_edges());
  weights_.reserve(6);
  const internal::Vertex_rule<FT> smooth = internal::limit_point_rule(weights_, Vertex_kind::smooth, 6);
  const internal::Vertex_rule<FT> crease = internal::limit_point_rule(weights_, Vertex_kind::crease, 0);
  const FT smooth_centre_less_wings = FT(*smooth.centre - FT(*smooth.neighbour + *smooth.neighbour));
  for (Index e = 0; e < ne; ++e) {
    Acc& r = q[nv + e];
    const Index h = t.edge_halfedge(e);
    const Acc ends = internal::point_sum(q[t.source(h)], q[t.target(h)]);
    if (lv.features.edge_is_crease[e]) {
      r = internal::point_combination(*crease.centre, r, *crease.neighbour, ends);
    } else {
      const Acc around = internal::point_sum(
          ends, internal::point_sum(wing_[Mesh_topology::face(h)], wing_[Mesh_topology::face(t.opposite(h))]));
      r = internal::point_combination(smooth_centre_less_wings, r, *smooth.neighbour, around);
    }
  }
}

// Limit positions of the old vertices, in place, from ring sums: a smooth
// vertex's refined ring sum explicitly (ring2) or from the standard edge rule
// (see mark_explicit_rings); a crease vertex's refined crease neighbours are
// the crease edge rule's (p + p_c) / 2, so the crease limit rule gives
// neighbour * p (the two halves) + neighbour / 2 * the crease-neighbour sum.
template <ConstructionKernel_3 K>
void Loop_subdivider<K>::limit_of_old_vertices(const Level& lv, const Acc* p, std::vector<Acc>& q) {
  const Index nv = static_cast<Index>(lv.topology.number_of_vertices());
  const auto no_sector = [](int) -> Index { return 0; };
  const auto smooth_ends = [](int) { return Vertex_kind::smooth; };
  const auto crease_ends = [](int) { return Vertex_kind::crease; };
  const auto standard = internal::edge_point_rule(weights_, false, smooth_ends, no_sector);
  const auto crease_edge = internal::edge_point_rule(weights_, true, crease_ends, no_sector);
  const FT& end = standard.end_a();
  const FT refined_ring_weight = FT(standard.end_b() + FT(standard.wing() + standard.wing()));
  const internal::Vertex_rule<FT> crease = internal::limit_point_rule(weights_, Vertex_kind::crease, 0);
  const FT half_neighbour = FT(*crease.neighbour * crease_edge.end_b());
  for (Index v = 0; v < nv; ++v) {
    const Vertex_kind kind = lv.features.vertex_kind[v];
    const Index n = valence_[v];
    const internal::Vertex_rule<FT> r = internal::limit_point_rule(weights_, kind, n);
    switch (r.neighbours) {
      case internal::Rule_neighbours::ring:
        if (any_special_ && explicit_ring_[v]) {
          q[v] = internal::point_combination(*r.centre, q[v], *r.neighbour, ring2_[v]);
        } else {
          const Acc r2 = internal::point_combination(FT(end * FT(static_cast<int>(n))), p[v], refined_ring_weight, ring_[v]);
          q[v] = internal::point_combination(*r.centre, q[v], *r.neighbour, r2);
        }
        break;
      case internal::Rule_neighbours::crease:
        q[v] = internal::point_sum(internal::point_combination(*r.centre, q[v], *r.neighbour, p[v]),
                                   internal::point_scale(half_neighbour, crease_ring_[v]));
        break;
      case internal::Rule_neighbours::none: break;
    }
  }
}

/// Refines `m` `levels` times with Loop's rules under kernel K (default:
/// Kernel_for_number of the coordinate type: refinement uses only
/// constructions, which are the same in every kernel over one number type,
/// so Naive_kernel<double>, Failsafe_kernel<double> and Filtered_exact_kernel
/// refine identically; CGAL points: pass Cgal_kernel<K>). See Loop_subdivider
/// for the requirements, errors and output numbering.
template <KernelOrDefault K = void, class P>
Triangle_mesh<P> loop_subdivide(const Triangle_mesh<P>& m, unsigned levels,
                                const Loop_options& options = {}) {
  using Kernel = Kernel_or_default<K, Kernel_for_number, P>;
  return Loop_subdivider<Kernel>(options).refine(m, levels);
}

/// The limit mesh of `m` at level `levels` (refine, then push every vertex to
/// its limit position; thesis Sec. 5.2).
template <KernelOrDefault K = void, class P>
Triangle_mesh<P> loop_limit_mesh(const Triangle_mesh<P>& m, unsigned levels,
                                 const Loop_options& options = {}) {
  using Kernel = Kernel_or_default<K, Kernel_for_number, P>;
  return Loop_subdivider<Kernel>(options).limit_mesh(m, levels);
}

// relgeo::compiled makes the subdivider of double meshes (Kernel_for_number
// of double: loop_subdivide's and loop_limit_mesh's default) once
// (src/compiled/subdivision.cpp).
#if RELGEO_LINKS_COMPILED
extern template class Loop_subdivider<Naive_kernel<double>>;
#endif

}  // namespace relgeo
