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

#include "relgeo/core/fp_environment.h"
#include "relgeo/core/errors.h"
#include "relgeo/kernel/kernel_for_number.h"
#include "relgeo/mesh/internal/point_access.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/loop_masks.h"
#include "relgeo/subdivision/loop_weights.h"

namespace relgeo {

/// The kernel used when none is given, from the point type:
/// Kernel_for_number of the coordinate type (refinement uses only
/// constructions, which are the same in every kernel over one number type:
/// Naive_kernel<double>, Failsafe_kernel<double> and Filtered_exact_kernel
/// refine identically). CGAL points: pass Cgal_kernel<K> explicitly.
template <class P>
struct Default_loop_kernel;
template <class FT>
struct Default_loop_kernel<Point_3<FT>> : Kernel_for_number<FT> {};

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
template <class K>
class Loop_subdivider {
 public:
  using FT = typename K::FT;
  using Point = typename K::Point_3;
  using Mesh = Triangle_mesh<Point>;

  explicit Loop_subdivider(const Loop_options& options = {}, const K& kernel = K{})
      : kernel_(kernel), weights_(options) {}

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
  std::vector<Point> limit_positions(const Mesh& m) {
    const Default_fp_environment_if<K::is_certified> environment;
    check_coordinates(m);
    const Mesh_topology t = Mesh_topology::build(m);
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
  static void add(Acc& a, const Acc& p) {
    a.x = FT(a.x + p.x), a.y = FT(a.y + p.y), a.z = FT(a.z + p.z);
  }
  // w1 p + w2 q
  static Acc comb(const FT& w1, const Acc& p, const FT& w2, const Acc& q) {
    return Acc{FT(FT(w1 * p.x) + FT(w2 * q.x)), FT(FT(w1 * p.y) + FT(w2 * q.y)),
               FT(FT(w1 * p.z) + FT(w2 * q.z))};
  }
  static Acc scale(const FT& w, const Acc& p) { return Acc{FT(w * p.x), FT(w * p.y), FT(w * p.z)}; }
  static Acc sum(const Acc& p, const Acc& q) {
    return Acc{FT(p.x + q.x), FT(p.y + q.y), FT(p.z + q.z)};
  }

  K kernel_;
  Loop_weights<K> weights_;
  std::vector<Acc> ring_, crease_ring_, wing_, ring2_;
  std::vector<std::uint8_t> explicit_ring_;
  std::vector<Index> valence_, sector_faces_;
};

template <class K>
auto Loop_subdivider<K>::step(const Mesh& m, const Level& lv, bool to_limit, Level* next) -> Mesh {
  const Index nv = static_cast<Index>(m.vertices.size());
  const Mesh_topology& t = lv.topology;
  const Loop_features& f = lv.features;
  const Index ne = static_cast<Index>(t.number_of_edges()), nf = static_cast<Index>(m.faces.size());
  const Loop_weights<K>& w = weights_;
  const bool blz = options().crease_rules == Loop_crease_rules::biermann_levin_zorin;

  // Coordinates in FT (relgeo points already are; CGAL points are read once).
  constexpr bool native = std::is_same_v<Point, Acc>;
  std::vector<Acc> p_copy;
  const Acc* p = nullptr;
  if constexpr (native) {
    p = m.vertices.data();
  } else {
    p_copy.resize(nv);
    for (Index v = 0; v < nv; ++v)
      p_copy[v] = Acc{A::x(m.vertices[v]), A::y(m.vertices[v]), A::z(m.vertices[v])};
    p = p_copy.data();
  }

  // Ring sums and valences, edge by edge (no ordered rings needed).
  // Scratch buffers are members: repeated calls reuse their memory.
  std::vector<Acc>& ring = ring_;
  std::vector<Acc>& crease_ring = crease_ring_;
  std::vector<Index>& valence = valence_;
  ring.assign(nv, Acc{FT(0), FT(0), FT(0)});
  valence.assign(nv, 0);
  bool any_crease = false;
  for (Index e = 0; e < ne; ++e) any_crease |= f.edge_is_crease[e] != 0;
  // Special (crease or corner) vertices: a tagged corner needs no crease edge,
  // and BLZ's edge rule next to it needs its sector size all the same.
  bool any_special = any_crease;
  for (Index v = 0; v < nv && !any_special; ++v) any_special = f.is_special(v);
  if (any_crease) crease_ring.assign(nv, Acc{FT(0), FT(0), FT(0)});
  for (Index e = 0; e < ne; ++e) {
    const Index h = t.edge_halfedge(e), a = t.source(h), b = t.target(h);
    add(ring[a], p[b]), add(ring[b], p[a]);
    ++valence[a], ++valence[b];
    if (f.edge_is_crease[e]) add(crease_ring[a], p[b]), add(crease_ring[b], p[a]);
  }
  Index max_valence = 6;
  for (Index v = 0; v < nv; ++v) max_valence = std::max(max_valence, valence[v]);
  weights_.reserve(max_valence);

  // BLZ: sector size of every outgoing non-crease half-edge of a special vertex.
  std::vector<Index>& sector_faces = sector_faces_;
  if (blz && any_special) {
    sector_faces.assign(3 * std::size_t(nf), 0);
    for (Index v = 0; v < nv; ++v) {
      if (!f.is_special(v)) continue;
      t.for_each_outgoing(v, [&](Index h) {
        if (sector_faces[h] != 0) return;
        const Loop_sector s = loop_sector(t, f, v, h);
        Index g = s.first;  // every outgoing half-edge of the sector gets its size
        for (Index i = 0; i < s.faces() && g != invalid_index; ++i, g = t.ccw_outgoing(g))
          sector_faces[g] = s.faces();
      });
    }
  }

  Mesh out;
  std::vector<Acc> q_buf;
  std::vector<Acc>& q = [&]() -> std::vector<Acc>& {
    if constexpr (native) return out.vertices;
    else return q_buf;
  }();
  q.resize(std::size_t(nv) + ne);
  // Vertex points.
  for (Index v = 0; v < nv; ++v) {
    switch (f.vertex_kind[v]) {
      case Vertex_kind::smooth:
      case Vertex_kind::dart: q[v] = comb(w.centre(valence[v]), p[v], w.beta(valence[v]), ring[v]); break;
      case Vertex_kind::crease: q[v] = comb(w.three_quarters(), p[v], w.eighth(), crease_ring[v]); break;
      default: q[v] = p[v];
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
  std::vector<Acc>& wing = wing_;
  std::vector<Acc>& ring2 = ring2_;
  std::vector<std::uint8_t>& explicit_ring = explicit_ring_;
  if (to_limit) {
    wing.resize(nf);  // per face: the sum of its three new vertices
    // A smooth vertex all of whose edges follow the standard rule has the
    // refined ring sum 3n/8 p + 5/8 R (R its ring sum): no accumulation. The
    // others (darts; with BLZ, neighbours of crease/corner vertices) sum
    // their edge points explicitly.
    explicit_ring.assign(any_special ? nv : 0, 0);  // without creases there are no darts
    if (any_special)
      for (Index v = 0; v < nv; ++v) explicit_ring[v] = f.vertex_kind[v] == Vertex_kind::dart;
    if (blz && any_special)
      for (Index e = 0; e < ne; ++e) {
        const Index h = t.edge_halfedge(e), a = t.source(h), b = t.target(h);
        if (!f.edge_is_crease[e] && f.is_special(a) != f.is_special(b)) explicit_ring[a] = explicit_ring[b] = 1;
      }
    if (any_special) {
      ring2.resize(nv);
      for (Index v = 0; v < nv; ++v)
        if (explicit_ring[v]) ring2[v] = Acc{FT(0), FT(0), FT(0)};
    }
  }
  // Edge points.
  for (Index e = 0; e < ne; ++e) {
    const Index h = t.edge_halfedge(e), a = t.source(h), b = t.target(h);
    Acc& r = q[nv + e];
    if (f.edge_is_crease[e]) {
      r = comb(w.half(), p[a], w.half(), p[b]);
    } else {
      const Index c = t.target(Mesh_topology::next(h));
      const Index d = t.target(Mesh_topology::next(t.opposite(h)));
      if (blz && f.is_special(a) != f.is_special(b)) {
        const Index v = f.is_special(a) ? a : b, o = v == a ? b : a;
        const Index hv = v == a ? h : t.opposite(h);
        const FT g = w.gamma(sector_faces[hv], f.vertex_kind[v] == Vertex_kind::corner);
        const Acc s = comb(FT(w.three_quarters() - g), p[v], g, p[o]);
        r = sum(s, comb(w.eighth(), p[c], w.eighth(), p[d]));
      } else {
        r = comb(w.three_eighths(), sum(p[a], p[b]), w.eighth(), sum(p[c], p[d]));
      }
    }
    if (to_limit && any_special) {
      if (explicit_ring[a]) add(ring2[a], r);
      if (explicit_ring[b]) add(ring2[b], r);
    }
  }
  // Faces.
  out.faces.resize(4 * std::size_t(nf));
  for (Index fi = 0; fi < nf; ++fi) {
    const Triangle& tr = m.faces[fi];
    const Index e0 = t.edge(3 * fi), e1 = t.edge(3 * fi + 1), e2 = t.edge(3 * fi + 2);
    const Index m0 = nv + e0, m1 = nv + e1, m2 = nv + e2;
    Triangle* o = &out.faces[4 * std::size_t(fi)];
    o[0] = {tr[0], m0, m2};
    o[1] = {tr[1], m1, m0};
    o[2] = {tr[2], m2, m1};
    o[3] = {m0, m1, m2};
    if (to_limit) wing[fi] = sum(q[m0], sum(q[m1], q[m2]));
  }
  // Tags.
  if (!m.tags.empty()) {
    std::vector<Edge> creases;
    for (Index e = 0; e < ne; ++e)
      if (f.edge_is_tagged[e]) {
        const Edge ab = t.edge_vertices(e);
        creases.push_back(Edge{ab.a, nv + e});
        creases.push_back(Edge{ab.b, nv + e});
      }
    out.tags.set_creases(std::move(creases));
    out.tags.set_corners(std::vector<Index>(m.tags.corners().begin(), m.tags.corners().end()));
  }

  if (next) {
    next->topology = Mesh_topology::refined(t, out.faces);
    next->features = refined_loop_features(t, f, next->topology);
  }

  if (to_limit) {
    // In place: new vertices first (they read the old vertices' refined
    // positions), then the old ones (they read only ring sums).
    weights_.reserve(6);
    const FT& c6 = w.limit_centre(6);
    const FT& x6 = w.chi(6);
    // New vertex m of a smooth edge (valence 6) between faces f and g:
    // (1 - 6 chi) m + chi (a' + b' + wings), and the wings are the face sums
    // of f and g minus m twice.
    const FT c6m = FT(c6 - FT(x6 + x6));
    for (Index e = 0; e < ne; ++e) {
      Acc& r = q[nv + e];
      const Index h = t.edge_halfedge(e);
      const Acc ends = sum(q[t.source(h)], q[t.target(h)]);
      if (f.edge_is_crease[e]) {
        r = comb(w.two_thirds(), r, w.sixth(), ends);
      } else {
        const Acc around = sum(ends, sum(wing[Mesh_topology::face(h)], wing[Mesh_topology::face(t.opposite(h))]));
        r = comb(c6m, r, x6, around);
      }
    }
    const FT three_eighths_n_unit = w.three_eighths(), five_eighths = FT(w.half() + w.eighth());
    const FT twelfth = FT(w.sixth() * w.half());
    for (Index v = 0; v < nv; ++v) {
      switch (f.vertex_kind[v]) {
        case Vertex_kind::smooth:
        case Vertex_kind::dart: {
          const Index n = valence[v];
          if (any_special && explicit_ring[v]) {
            q[v] = comb(w.limit_centre(n), q[v], w.chi(n), ring2[v]);
          } else {  // sum of the refined ring = 3n/8 p + 5/8 R
            const Acc r2 = comb(FT(three_eighths_n_unit * FT(static_cast<int>(n))), p[v], five_eighths, ring[v]);
            q[v] = comb(w.limit_centre(n), q[v], w.chi(n), r2);
          }
          break;
        }
        case Vertex_kind::crease:  // crease neighbours: (p + p_c) / 2 each
          q[v] = sum(comb(w.two_thirds(), q[v], w.sixth(), p[v]), scale(twelfth, crease_ring[v]));
          break;
        default: break;
      }
    }
  }
  if constexpr (!native) {
    out.vertices.reserve(q.size());
    for (Acc& r : q) out.vertices.push_back(A::make(std::move(r.x), std::move(r.y), std::move(r.z)));
  }
  return out;
}

/// Refines `m` `levels` times with Loop's rules under kernel K (default:
/// Default_loop_kernel of the point type). See Loop_subdivider for the
/// requirements, errors and output numbering.
template <class K = void, class P>
Triangle_mesh<P> loop_subdivide(const Triangle_mesh<P>& m, unsigned levels,
                                const Loop_options& options = {}) {
  using Kernel = std::conditional_t<std::is_void_v<K>, typename Default_loop_kernel<P>::type, K>;
  return Loop_subdivider<Kernel>(options).refine(m, levels);
}

/// The limit mesh of `m` at level `levels` (refine, then push every vertex to
/// its limit position; thesis Sec. 5.2).
template <class K = void, class P>
Triangle_mesh<P> loop_limit_mesh(const Triangle_mesh<P>& m, unsigned levels,
                                 const Loop_options& options = {}) {
  using Kernel = std::conditional_t<std::is_void_v<K>, typename Default_loop_kernel<P>::type, K>;
  return Loop_subdivider<Kernel>(options).limit_mesh(m, levels);
}

}  // namespace relgeo
