// relgeo/subdivision/internal/loop_rules.h — Loop's rules, written once: the
// weights of every refinement and limit rule (smooth, dart, crease, corner,
// boundary; Hoppe's and Biermann-Levin-Zorin's edge rules), the vertices each
// weighs, and the stencils built from them.
//
// Every user of a rule asks here: Loop_subdivider's fused refinement (which
// evaluates a rule on pre-summed neighbour groups), the explicit stencils of
// loop_masks.h, the limit evaluator's local subdivision and the 1-ring
// matrices of exact limit positions. So they agree by construction; only the
// order of the floating-point operations differs between the fused and the
// explicit evaluation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/loop_features.h"
#include "relgeo/subdivision/loop_weights.h"
#include "relgeo/subdivision/stencil.h"

namespace relgeo::internal {

/// Crease vertices and corners: their rules look only at their own sector.
constexpr bool is_special(Vertex_kind k) { return k == Vertex_kind::crease || k == Vertex_kind::corner; }

// ---------------------------------------------------------------------------
// The weights.

/// Which neighbours a vertex rule weighs: the whole ring (smooth, dart), the
/// two crease neighbours (crease vertex; on the boundary the two boundary
/// neighbours), none (corner, isolated vertex: fixed).
enum class Rule_neighbours : std::uint8_t { ring, crease, none };

/// A vertex rule: `centre` at the vertex, `neighbour` at each of its
/// `neighbours` (both point into the weight table).
template <class FT>
struct Vertex_rule {
  Rule_neighbours neighbours;
  const FT* centre;
  const FT* neighbour;  ///< nullptr for Rule_neighbours::none
};

/// Loop's vertex-point rule for a vertex of kind `kind` and valence n (ring
/// size; only read for smooth vertices and darts): (1 - n beta, beta),
/// crease (3/4, 1/8), fixed otherwise. \pre w holds valence n.
template <class K>
Vertex_rule<typename K::FT> vertex_point_rule(const Loop_weights<K>& w, Vertex_kind kind, Index n) {
  switch (kind) {
    case Vertex_kind::smooth:
    case Vertex_kind::dart: return {Rule_neighbours::ring, &w.centre(n), &w.beta(n)};
    case Vertex_kind::crease: return {Rule_neighbours::crease, &w.three_quarters(), &w.eighth()};
    default: return {Rule_neighbours::none, &w.one(), nullptr};
  }
}

/// The limit-position rule (thesis Fig. 2.6): smooth and dart (1 - n chi,
/// chi), crease (2/3, 1/6), fixed otherwise. \pre w holds valence n.
template <class K>
Vertex_rule<typename K::FT> limit_point_rule(const Loop_weights<K>& w, Vertex_kind kind, Index n) {
  switch (kind) {
    case Vertex_kind::smooth:
    case Vertex_kind::dart: return {Rule_neighbours::ring, &w.limit_centre(n), &w.chi(n)};
    case Vertex_kind::crease: return {Rule_neighbours::crease, &w.two_thirds(), &w.sixth()};
    default: return {Rule_neighbours::none, &w.one(), nullptr};
  }
}

/// The three shapes of an edge rule on edge (a, b) with opposite vertices
/// c, d ("wings"): crease (1/2, 1/2; no wings), standard (3/8, 3/8, wings
/// 1/8), modified (BLZ: 3/4 - gamma at the special end, gamma at the other,
/// wings 1/8).
enum class Edge_shape : std::uint8_t { crease, standard, modified };

/// Whether BLZ's rule changes the weights of edge (a, b): a smooth edge with
/// exactly one crease-or-corner end.
inline bool edge_rule_is_modified(const Loop_options& o, bool crease, Vertex_kind a, Vertex_kind b) {
  return o.crease_rules == Loop_crease_rules::biermann_levin_zorin && !crease && is_special(a) != is_special(b);
}

/// BLZ's weight at a special vertex of a smooth edge is the standard 3/8
/// exactly when its sector has 3 faces (crease vertex) or alpha / k = pi / 3
/// (corner).
inline bool blz_weight_is_standard(const Loop_options& o, Vertex_kind kind, Index k) {
  if (kind == Vertex_kind::crease) return k == 3;
  return 3 * o.corner_angle_num == o.corner_angle_den * static_cast<long>(k);
}

/// The weights of an edge rule. Crease and standard weights point into the
/// weight table; the modified ones are computed (gamma) and held here, so an
/// Edge_rule is neither copied nor moved (edge_point_rule returns it as a
/// prvalue: guaranteed copy elision).
template <class FT>
class Edge_rule {
 public:
  Edge_rule(Edge_shape shape, const FT& ends, const FT* wing) : shape_(shape), a_(&ends), b_(&ends), wing_(wing) {}
  Edge_rule(const FT& at_a, const FT& at_b, const FT& wing)
      : shape_(Edge_shape::modified), own_(std::array<FT, 2>{at_a, at_b}), a_(&(*own_)[0]), b_(&(*own_)[1]), wing_(&wing) {}
  Edge_rule(const Edge_rule&) = delete;
  Edge_rule& operator=(const Edge_rule&) = delete;

  Edge_shape shape() const { return shape_; }
  const FT& end_a() const { return *a_; }
  const FT& end_b() const { return *b_; }
  /// The weight of each opposite vertex. \pre shape() != crease.
  const FT& wing() const { return *wing_; }

 private:
  Edge_shape shape_;
  std::optional<std::array<FT, 2>> own_;  // BLZ's modified end weights (nothing built otherwise)
  const FT* a_;
  const FT* b_;
  const FT* wing_;
};

/// Loop's edge-point rule of edge (a, b) (Hoppe et al. 1994; BLZ 2000 when
/// the options say so). `kind_at(end)` gives the kind of end 0 (a) or 1 (b)
/// and `sector_faces(end)` the number of faces of the sector holding the
/// edge there; they are asked only under BLZ's rules (the sector only for
/// the special end of a modified edge), so the fast path reads neither.
template <class K, class Kind_at, class Sector_faces>
Edge_rule<typename K::FT> edge_point_rule(const Loop_weights<K>& w, bool crease, Kind_at&& kind_at,
                                          Sector_faces&& sector_faces) {
  using FT = typename K::FT;
  if (crease) return Edge_rule<FT>(Edge_shape::crease, w.half(), nullptr);
  const Vertex_kind a = w.options().crease_rules == Loop_crease_rules::biermann_levin_zorin ? kind_at(0) : Vertex_kind::smooth;
  const Vertex_kind b = w.options().crease_rules == Loop_crease_rules::biermann_levin_zorin ? kind_at(1) : Vertex_kind::smooth;
  if (!edge_rule_is_modified(w.options(), crease, a, b)) return Edge_rule<FT>(Edge_shape::standard, w.three_eighths(), &w.eighth());
  const int special = is_special(a) ? 0 : 1;
  const FT g = w.gamma(sector_faces(special), (special == 0 ? a : b) == Vertex_kind::corner);
  const FT at_special = FT(w.three_quarters() - g);
  return special == 0 ? Edge_rule<FT>(at_special, g, w.eighth()) : Edge_rule<FT>(g, at_special, w.eighth());
}

// ---------------------------------------------------------------------------
// The data the rules read, per vertex and half-edge.

/// Sector sizes: for every outgoing half-edge h of a crease vertex or corner
/// v, the number of faces of v's sector holding face(h) (others untouched).
/// \pre `sector` has one entry per half-edge, 0 where not yet set.
inline void fill_sector_faces(const Mesh_topology& t, const Loop_features& f, std::vector<Index>& sector) {
  for (Index v = 0; v < t.number_of_vertices(); ++v) {
    if (!f.is_special(v)) continue;
    t.for_each_outgoing(v, [&](Index h) {
      if (sector[h] != 0) return;
      const Loop_sector s = loop_sector(t, f, v, h);
      Index g = s.first;  // every outgoing half-edge of the sector gets its size
      for (Index i = 0; i < s.faces() && g != invalid_index; ++i, g = t.ccw_outgoing(g)) sector[g] = s.faces();
    });
  }
}

/// The per-half-edge and per-vertex data the rules read, for a control mesh
/// or a local patch: vertex kinds; whether each half-edge's edge is a crease
/// (tagged or boundary); for the vertex at corner h % 3 of face h / 3 (the
/// source of h), when it is a crease vertex or corner, the number of faces of
/// its sector holding that face (0 otherwise).
struct Loop_rule_data {
  std::vector<Vertex_kind> kind;
  std::vector<std::uint8_t> crease;
  std::vector<Index> sector;
  bool special(Index v) const { return is_special(kind[v]); }
  // The interface of a rule source (see mesh_rule_source below).
  Vertex_kind vertex_kind(Index v) const { return kind[v]; }
  bool is_crease(Index h) const { return crease[h] != 0; }
  Index sector_faces(Index h) const { return sector[h]; }
  friend bool operator==(const Loop_rule_data&, const Loop_rule_data&) = default;
};

inline Loop_rule_data loop_rule_data(const Mesh_topology& t, const Loop_features& f) {
  Loop_rule_data d;
  d.kind = f.vertex_kind;
  const std::size_t nh = t.number_of_halfedges();
  d.crease.resize(nh);
  for (Index h = 0; h < nh; ++h) d.crease[h] = f.edge_is_crease[t.edge(h)];
  d.sector.assign(nh, 0);
  fill_sector_faces(t, f, d.sector);
  return d;
}

/// The rule data of a whole mesh read from its Loop_features (sectors found
/// by walking around the vertex, as needed).
struct Mesh_rule_source {
  const Mesh_topology& topology;
  const Loop_features& features;
  Vertex_kind vertex_kind(Index v) const { return features.vertex_kind[v]; }
  bool is_crease(Index h) const { return features.edge_is_crease[topology.edge(h)] != 0; }
  Index sector_faces(Index h) const { return loop_sector(topology, features, topology.source(h), h).faces(); }
};

/// Whether every edge at smooth vertex a follows the standard weights (not
/// BLZ, or each special neighbour's gamma is 3/8).
template <class Rules>
bool standard_weights_around(const Mesh_topology& t, const Rules& r, const Loop_options& o, Index a) {
  if (o.crease_rules != Loop_crease_rules::biermann_levin_zorin) return true;
  bool ok = true;
  t.for_each_outgoing(a, [&](Index g) {
    const Index x = t.target(g);
    const Vertex_kind kx = r.vertex_kind(x);
    if (is_special(kx) && !blz_weight_is_standard(o, kx, r.sector_faces(Mesh_topology::next(g)))) ok = false;
  });
  return ok;
}

// ---------------------------------------------------------------------------
// The rules as explicit stencils (the vertex's fan must be complete in t).

/// Appends vertex a and the neighbours a vertex rule weighs: the ring
/// counter-clockwise, or the crease neighbours (on the boundary: the
/// outgoing crease edges', then the incoming boundary edge's source).
template <class FT, class Rules>
void add_vertex_rule(const Mesh_topology& t, const Rules& r, const Vertex_rule<FT>& rule, Index a, Stencil<FT>& s) {
  s.add(a, *rule.centre);
  switch (rule.neighbours) {
    case Rule_neighbours::ring: t.for_each_outgoing(a, [&](Index h) { s.add(t.target(h), *rule.neighbour); }); break;
    case Rule_neighbours::crease: {
      Index last = invalid_index;
      t.for_each_outgoing(a, [&](Index h) {
        if (r.is_crease(h)) s.add(t.target(h), *rule.neighbour);
        last = h;
      });
      if (t.is_boundary_vertex(a)) s.add(t.source(Mesh_topology::prev(last)), *rule.neighbour);
      break;
    }
    case Rule_neighbours::none: break;
  }
}

/// The refinement stencil of vertex a, into s (cleared first: callers reuse
/// one buffer). \pre w holds a's valence.
template <class K, class Rules>
void vertex_point_stencil_into(const Mesh_topology& t, const Rules& r, const Loop_weights<K>& w, Index a,
                               Stencil<typename K::FT>& s) {
  s.clear();
  add_vertex_rule(t, r, vertex_point_rule(w, r.vertex_kind(a), t.number_of_incident_faces(a)), a, s);
}

/// The limit-position stencil of vertex a, into s (cleared first). \pre w
/// holds a's valence.
template <class K, class Rules>
void limit_stencil_into(const Mesh_topology& t, const Rules& r, const Loop_weights<K>& w, Index a,
                        Stencil<typename K::FT>& s) {
  s.clear();
  add_vertex_rule(t, r, limit_point_rule(w, r.vertex_kind(a), t.number_of_incident_faces(a)), a, s);
}

/// The refinement stencil of the edge of half-edge h, into s (cleared
/// first): a = source, b = target, then the wings (opposite vertices of h's
/// face and of the other face). \throws Error (computation_failure) when a
/// smooth edge lacks its second face (a local patch cut too small).
template <class K, class Rules>
void edge_point_stencil_into(const Mesh_topology& t, const Rules& r, const Loop_weights<K>& w, Index h,
                             Stencil<typename K::FT>& s) {
  s.clear();
  const Index a = t.source(h), b = t.target(h), o = t.opposite(h);
  const bool crease = r.is_crease(h);
  if (!crease && o == invalid_index) throw Error(Error_code::computation_failure, "Loop local patch: missing face");
  const auto rule = edge_point_rule(
      w, crease, [&](int end) { return r.vertex_kind(end == 0 ? a : b); },
      [&](int end) { return r.sector_faces(end == 0 ? h : o); });
  s.add(a, rule.end_a()), s.add(b, rule.end_b());
  if (rule.shape() == Edge_shape::crease) return;
  s.add(t.target(Mesh_topology::next(h)), rule.wing());
  s.add(t.target(Mesh_topology::next(o)), rule.wing());
}

}  // namespace relgeo::internal
