// relgeo/subdivision/limit_evaluation.h — exact evaluation of the Loop limit
// surface at any (face, u, v) of a control mesh, with derivatives and normals,
// under any kernel (SPEC Sec. 4; thesis Sec. 2.2.2, 5.2).
//
// Method (doc/subdivision.md, Sec. 7.1):
//  * regular patches (three smooth valence-6 vertices with standard rules
//    around them) are quartic box splines over 12 control points, evaluated
//    through their Bezier form (box_spline.h);
//  * regular crease patches (vertices on a crease with 3 faces on the patch's
//    side; Hoppe's rules, or BLZ's, which coincide there) are the same box
//    spline over the net extended across the crease by ghost points
//    g = a + b - c (a, b a crease edge, c its opposite vertex on the patch's
//    side): the crease and ghost rules commute with refinement (checked
//    exactly by test/subdivision/derivation/check_crease_ghosts.py);
//  * every other patch (extraordinary vertices, darts, corners, irregular
//    crease vertices, BLZ-modified edges, several irregular vertices at
//    level 0) by *provably converging local subdivision*: the face and the
//    faces around its vertices are refined with the mesh's own rules (the
//    same stencils as Loop_subdivider, so the same numbers), the child
//    containing (u, v) is kept, until it is a regular (crease) patch; at an
//    irregular vertex itself the exact limit position is returned (the limit
//    mask where it is an exact eigenvector, otherwise the left eigenvector of
//    the vertex's local subdivision matrix, solved in FT).
// Why not Stam's eigenbasis: its eigenvectors are irrational already for
// rational weights (valence 5: sqrt(5)), so it cannot be exact under GMP
// rationals, and it covers smooth extraordinary vertices only (creases,
// corners, darts and BLZ would each need their own eigen-analysis). Local
// subdivision is exact wherever the weights are, treats every tagged
// configuration with the rules the mesh is refined with, and costs
// O(log2(1/d)) local steps, d the parameter distance to the nearest
// irregular vertex (each step refines ~15-30 faces).
//
// Parameters are doubles (every double is a dyadic rational: converted
// exactly by the exact, interval and MPFR >= 53 kernels). The child choice is
// made on the exact parameters (GMP rationals), so interval results enclose
// the exact value and rational results are exact.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "relgeo/core/fp_environment.h"
#include "relgeo/core/errors.h"
#include "relgeo/core/interval.h"
#include "relgeo/core/mpfr_number.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/core/rounding.h"
#include "relgeo/mesh/internal/point_access.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/box_spline.h"
#include "relgeo/subdivision/internal/loop_rules.h"
#include "relgeo/subdivision/loop_masks.h"
#include "relgeo/subdivision/loop_subdivision.h"
#include "relgeo/subdivision/loop_weights.h"

namespace relgeo {

/// How the limit surface over a face is evaluated.
enum class Loop_patch_kind : std::uint8_t {
  regular,         ///< box spline of 12 control points (all smooth valence 6, standard rules)
  regular_crease,  ///< box spline of the net extended across regular creases by ghost points
  irregular        ///< local subdivision until the sub-patch holding (u, v) is regular
};

inline const char* to_string(Loop_patch_kind k) {
  switch (k) {
    case Loop_patch_kind::regular: return "regular";
    case Loop_patch_kind::regular_crease: return "regular_crease";
    case Loop_patch_kind::irregular: return "irregular";
  }
  return "unknown";
}

/// A surface parameter that names no point of the surface: a face index out
/// of range, or (u, v) outside the closed triangle u, v >= 0, u + v <= 1.
/// (NaN and infinite parameters throw Non_finite_input.)
class Invalid_surface_parameter : public Invalid_input {
 public:
  explicit Invalid_surface_parameter(const std::string& what) : Invalid_input(what) {}
};

/// A point of the limit surface with its first derivatives.
template <class FT>
struct Loop_limit_jet {
  Point_3<FT> position;
  /// Partial derivatives with respect to the face's u and v (zero when
  /// has_derivatives is false).
  Point_3<FT> du, dv;
  /// du x dv (not normalised; exact direction), or, at an irregular vertex,
  /// the cross product of the tangent masks (exact at smooth vertices with
  /// standard rules, crease vertices and corners; the smooth masks'
  /// approximation at darts and BLZ-modified vertices).
  Point_3<FT> normal;
  /// False exactly at an irregular vertex, where the parametric derivatives
  /// vanish or are unbounded (the tangent plane exists: see normal).
  bool has_derivatives = true;
  /// Local subdivision levels used (0: evaluated on the face's own patch).
  unsigned levels = 0;
};

namespace internal {

/// A control point of a regular patch: vertex a, or the ghost a + b - c.
struct Patch_slot {
  Index a = invalid_index, b = invalid_index, c = invalid_index;
  bool is_ghost() const { return b != invalid_index; }
  friend bool operator==(const Patch_slot&, const Patch_slot&) = default;
};

/// Whether the corner `corner` of face f is a regular vertex of the patch:
/// smooth of valence 6 whose edges all follow the standard rule, or a crease
/// vertex with 3 faces in the sector holding f.
inline bool patch_corner_is_regular(const Mesh_topology& t, const Loop_rule_data& d, const Loop_options& o,
                                    Index f, int corner) {
  const Index h = 3 * f + Index(corner), a = t.source(h);
  switch (d.kind[a]) {
    case Vertex_kind::smooth:
      return !t.is_boundary_vertex(a) && t.number_of_incident_faces(a) == 6 && standard_weights_around(t, d, o, a);
    case Vertex_kind::crease: return d.sector[h] == 3;
    default: return false;
  }
}

/// Classifies face f and, for regular ones, fills its 12 control slots
/// (box_spline.h order). A crease vertex's sector p_0..p_3 (3 faces) is
/// completed by the ghosts a + p_3 - p_2 and a + p_0 - p_1; a conflict
/// between the slots found from different corners (only in degenerate tiny
/// meshes) makes the patch irregular.
inline Loop_patch_kind classify_loop_patch(const Mesh_topology& t, const Loop_rule_data& d, const Loop_options& o,
                                           Index f, std::array<Patch_slot, 12>* slots) {
  for (int k = 0; k < 3; ++k)
    if (!patch_corner_is_regular(t, d, o, f, k)) return Loop_patch_kind::irregular;
  static constexpr int dirs[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
  static constexpr int start[3] = {0, 2, 4};
  std::array<Patch_slot, 12> s{};
  std::array<bool, 12> set{};
  bool any_crease = false;
  for (int k = 0; k < 3; ++k) {
    const Index h = 3 * f + Index(k), a = t.source(h);
    std::array<Patch_slot, 6> cycle;
    if (d.kind[a] == Vertex_kind::smooth) {
      Index g = h;
      for (int m = 0; m < 6; ++m, g = t.ccw_outgoing(g)) cycle[m] = Patch_slot{t.target(g)};
    } else {  // crease vertex, 3 faces in this sector
      any_crease = true;
      Index first = h;  // clockwise to the crease half-edge starting the sector
      for (int guard = 0; guard < 3 && !d.crease[first]; ++guard) first = Mesh_topology::next(t.opposite(first));
      if (!d.crease[first]) return Loop_patch_kind::irregular;
      std::array<Index, 4> p{};
      int pos = -1;
      Index g = first;
      for (int i = 0; i < 3; ++i) {
        if (g == invalid_index) return Loop_patch_kind::irregular;
        if (g == h) pos = i;
        p[i] = t.target(g);
        if (i == 2) p[3] = t.source(Mesh_topology::prev(g));
        g = t.ccw_outgoing(g);
      }
      if (pos < 0) return Loop_patch_kind::irregular;
      // ghosts with (a, b) sorted: the same ghost is found from both crease ends
      const auto ghost = [](Index x, Index y, Index z) { return Patch_slot{std::min(x, y), std::max(x, y), z}; };
      const std::array<Patch_slot, 6> sector{{{p[0]}, {p[1]}, {p[2]}, {p[3]}, ghost(a, p[3], p[2]), ghost(a, p[0], p[1])}};
      for (int m = 0; m < 6; ++m) cycle[m] = sector[(pos + m) % 6];
    }
    const int cx = k == 1 ? 1 : 0, cy = k == 2 ? 1 : 0;
    const auto put = [&](int x, int y, const Patch_slot& ps) {
      for (int i = 0; i < 12; ++i)
        if (loop_patch_lattice[i][0] == x && loop_patch_lattice[i][1] == y) {
          if (set[i] && !(s[i] == ps)) return false;
          s[i] = ps, set[i] = true;
          return true;
        }
      return false;  // unreachable: every neighbour of a corner is a slot
    };
    if (!put(cx, cy, Patch_slot{a})) return Loop_patch_kind::irregular;
    for (int m = 0; m < 6; ++m) {
      const int* dxy = dirs[(start[k] + m) % 6];
      if (!put(cx + dxy[0], cy + dxy[1], cycle[m])) return Loop_patch_kind::irregular;
    }
  }
  if (slots) *slots = s;
  return any_crease ? Loop_patch_kind::regular_crease : Loop_patch_kind::regular;
}

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

/// One refinement step of a local patch: the children `which` (a bitmask of
/// 1 << c, c as in box_spline.h) of faces[0] as local patches. Only the
/// vertex points of faces[0]'s vertices and the edge points of their edges
/// are computed; they are exactly the vertices of the children's patches.
template <class K>
std::array<Loop_local_patch<typename K::FT>, 4> refine_local_patch(
    const Loop_local_patch<typename K::FT>& P, const Mesh_topology& t, const Loop_weights<K>& w, unsigned which,
    std::vector<Stencil<typename K::FT>>* stencils = nullptr) {
  using FT = typename K::FT;
  const Index nv = P.number_of_vertices(), ne = static_cast<Index>(t.number_of_edges());
  const Index nf = static_cast<Index>(P.faces.size());
  const std::size_t dim = P.dim;
  std::vector<FT> cv((std::size_t(nv) + ne) * dim);
  std::vector<std::uint8_t> done(std::size_t(nv) + ne, 0);
  std::vector<Stencil<FT>> used;  // per child vertex, when `stencils` is wanted
  if (stencils) used.resize(std::size_t(nv) + ne);
  const auto apply = [&](Index target, Stencil<FT>&& st) {
    FT* out = cv.data() + std::size_t(target) * dim;
    for (std::size_t c = 0; c < dim; ++c) out[c] = FT(0);
    for (std::size_t i = 0; i < st.vertices.size(); ++i) {
      const FT* in = P.value(st.vertices[i]);
      for (std::size_t c = 0; c < dim; ++c) out[c] = FT(out[c] + FT(st.weights[i] * in[c]));
    }
    done[target] = 1;
    if (stencils) used[target] = std::move(st);
  };
  const auto do_edge = [&](Index h) {
    const Index e = t.edge(h);
    if (!done[nv + e]) apply(nv + e, edge_point_stencil_of(t, P.rules, w, h));
  };
  for (int k = 0; k < 3; ++k) {
    const Index a = P.faces[0][k];
    if (!done[a]) apply(a, vertex_point_stencil_of(t, P.rules, w, a));
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
      for (Index v : ids) stencils->push_back(used[v]);
    }
  }
  return out;
}

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

/// |x| as a double, for pivot choice (an interval's largest magnitude).
template <class FT>
double magnitude(const FT& x) {
  if constexpr (is_interval_v<FT>) return std::max(std::abs(lower_double(x)), std::abs(upper_double(x)));
  else return std::abs(nearest_double(x));
}

/// Solves the m x m system A x = b (row-major) by Gaussian elimination with
/// partial pivoting, divisions through Loop_number_traits<FT>::quotient.
/// \throws Error (computation_failure) when a pivot is not certainly nonzero.
template <class FT>
std::vector<FT> solve_small_system(std::vector<FT> A, std::vector<FT> b) {
  using Tr = Loop_number_traits<FT>;
  const std::size_t m = b.size();
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < m; ++r)
      if (magnitude(A[r * m + c]) > magnitude(A[piv * m + c])) piv = r;
    const Certified_sign pivot_sign = certified_sign(A[piv * m + c]);
    if (pivot_sign == Certified_sign::zero || pivot_sign == Certified_sign::uncertain)
      throw Error(Error_code::computation_failure, "limit position: singular eigen-system");
    if (piv != c) {
      for (std::size_t k = 0; k < m; ++k) std::swap(A[c * m + k], A[piv * m + k]);
      std::swap(b[c], b[piv]);
    }
    for (std::size_t r = c + 1; r < m; ++r) {
      if (certified_sign(A[r * m + c]) == Certified_sign::zero) continue;  // nothing to eliminate
      const FT f = Tr::quotient(A[r * m + c], A[c * m + c]);
      for (std::size_t k = c; k < m; ++k) A[r * m + k] = FT(A[r * m + k] - FT(f * A[c * m + k]));
      b[r] = FT(b[r] - FT(f * b[c]));
    }
  }
  std::vector<FT> x(m);
  for (std::size_t r = m; r-- > 0;) {
    FT s = b[r];
    for (std::size_t k = r + 1; k < m; ++k) s = FT(s - FT(A[r * m + k] * x[k]));
    x[r] = Tr::quotient(s, A[r * m + r]);
  }
  return x;
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
    const auto edge = edge_point_rule(w, crease, d.kind[a], kx,
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
    const Stencil<FT> s = limit_stencil_of(t, d, w, a);
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

/// FT from an exact rational (parameters), rounded once: to nearest for
/// floating types and MPFR, exact for mpq_class, the tightest enclosure for
/// intervals (Number_traits<FT>::from_rational); number types the layer
/// cannot round to (CGAL's) get the nearest double.
template <class FT>
FT ft_from_rational(const mpq_class& q) {
  if constexpr (Number_traits<FT>::kind == Number_kind::other)
    return FT(round_rational<double>(q, Rounding::to_nearest));
  else
    return Number_traits<FT>::from_rational(q, Rounding::to_nearest);
}

/// Whether the closed triangle u, v >= 0, u + v <= 1 contains (u, v), decided
/// exactly for doubles (TwoSum).
inline bool in_parameter_triangle(double u, double v) {
  if (!(u >= 0 && v >= 0)) return false;
  const double s = u + v;
  const double bv = s - u, err = (u - (s - bv)) + (v - bv);  // u + v = s + err exactly
  return s < 1 || (s == 1 && err <= 0);
}

}  // namespace internal

/// \brief The limit surface of a Loop control mesh, evaluated exactly at any
/// (face, u, v) under kernel K (method: see the file comment).
///
/// Construction analyses the mesh once (topology, features, per-face patch
/// kind and the 12 control slots of regular patches: O(V + F)); it throws
/// like Loop_subdivider (Invalid_mesh, Non_finite_input). Every query is
/// const and allocates its own scratch: one object can serve many threads.
///
/// Meshes with two faces sharing two edges (a vertex of valence 2) are
/// refused with Invalid_input: their Loop refinement is not a manifold.
///
/// Queries validate their input: a face index out of range or (u, v) outside
/// the triangle throws Invalid_surface_parameter; NaN/infinite parameters
/// throw Non_finite_input.
///
/// Complexity: regular and regular-crease patches O(1) (a 15 x 12 integer
/// matrix and a quartic); irregular patches O(levels), levels ~ log2(1/d) + 2
/// with d the parameter distance to the nearest irregular vertex.
template <class K>
class Loop_limit_surface {
 public:
  using FT = typename K::FT;
  using Point = typename K::Point_3;
  using Mesh = Triangle_mesh<Point>;
  using Tr = Loop_kernel_number_traits<K>;

  /// More local levels than any double parameter needs (2^-1074 is the
  /// smallest positive double); exceeding it is reported as a failure.
  static constexpr unsigned max_levels = 1200;

  explicit Loop_limit_surface(const Mesh& control, const Loop_options& options = {}, const K& kernel = K{})
      : kernel_(kernel), weights_(options) {
    for (std::size_t v = 0; v < control.vertices.size(); ++v) {
      if (!internal::point_is_finite(control.vertices[v]))
        throw Non_finite_input("Loop limit surface: vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
      points_.push_back(Point_3<FT>{A::x(control.vertices[v]), A::y(control.vertices[v]), A::z(control.vertices[v])});
    }
    topology_ = Mesh_topology::build(control);
    require_no_faces_sharing_two_edges(topology_, "Loop limit surface");
    features_ = classify_loop_features(topology_, control.tags);
    rules_ = internal::loop_rule_data(topology_, features_);
    Index max_valence = 6;
    for (Index v = 0; v < points_.size(); ++v) max_valence = std::max(max_valence, topology_.valence(v));
    weights_.reserve(max_valence + 1);
    one_24_ = Tr::rational(1, 24);
    const Index nf = static_cast<Index>(control.faces.size());
    kind_.resize(nf);
    slot_index_.assign(nf, invalid_index);
    std::array<internal::Patch_slot, 12> s;
    for (Index f = 0; f < nf; ++f) {
      kind_[f] = internal::classify_loop_patch(topology_, rules_, options, f, &s);
      if (kind_[f] != Loop_patch_kind::irregular) {
        slot_index_[f] = static_cast<Index>(slots_.size());
        slots_.push_back(s);
      }
    }
  }

  const Loop_options& options() const { return weights_.options(); }
  std::size_t number_of_faces() const { return kind_.size(); }
  std::size_t number_of_vertices() const { return points_.size(); }
  const Mesh_topology& topology() const { return topology_; }
  const Loop_features& features() const { return features_; }
  /// The weight table (all valences of the mesh reserved).
  const Loop_weights<K>& weights() const { return weights_; }
  /// The control points in FT.
  const std::vector<Point_3<FT>>& control_points() const { return points_; }
  /// Per-half-edge rule data (internal use: error bounds).
  const internal::Loop_rule_data& rule_data() const { return rules_; }
  /// The 12 control slots of a regular (crease) patch, nullptr for an
  /// irregular one (internal use: error bounds).
  const std::array<internal::Patch_slot, 12>* patch_slots(Index f) const {
    check_face(f);
    return slot_index_[f] == invalid_index ? nullptr : &slots_[slot_index_[f]];
  }
  /// The point of a control slot (a ghost resolved).
  Point_3<FT> slot_point(const internal::Patch_slot& s) const {
    if (!s.is_ghost()) return points_[s.a];
    const Point_3<FT>&a = points_[s.a], &b = points_[s.b], &c = points_[s.c];
    return Point_3<FT>{FT(FT(a.x + b.x) - c.x), FT(FT(a.y + b.y) - c.y), FT(FT(a.z + b.z) - c.z)};
  }

  /// How face f is evaluated. \throws Invalid_surface_parameter for a bad index.
  Loop_patch_kind patch_kind(Index f) const {
    check_face(f);
    return kind_[f];
  }

  /// The 12 control points of a regular (or regular crease) patch, ghosts
  /// resolved, in box_spline.h's order. \throws Invalid_surface_parameter
  /// for an irregular face.
  std::array<Point_3<FT>, 12> control_net(Index f) const {
    check_face(f);
    if (slot_index_[f] == invalid_index)
      throw Invalid_surface_parameter("Loop limit surface: face " + std::to_string(f) + " is not a regular patch");
    std::array<Point_3<FT>, 12> p;
    const auto& s = slots_[slot_index_[f]];
    for (int i = 0; i < 12; ++i) p[i] = slot_point(s[i]);
    return p;
  }

  /// The quartic Bezier form of a regular (or regular crease) patch (for
  /// hull criteria and bounds). \throws Invalid_surface_parameter for an
  /// irregular face.
  Quartic_bezier_patch<FT> bezier_patch(Index f) const { return loop_patch_to_bezier(control_net(f), one_24_); }

  /// The limit surface point at (u, v) of face f.
  Point evaluate(Index f, double u, double v) const {
    const Default_fp_environment_if<K::is_certified> environment;
    check(f, u, v);
    const Point_3<FT> p = kind_[f] != Loop_patch_kind::irregular ? evaluate_regular(f, FT(u), FT(v)) : irregular(f, u, v, false).position;
    return A::make(p.x, p.y, p.z);
  }

  /// Position, partial derivatives and normal at (u, v) of face f.
  Loop_limit_jet<FT> evaluate_with_derivatives(Index f, double u, double v) const {
    const Default_fp_environment_if<K::is_certified> environment;
    check(f, u, v);
    if (kind_[f] != Loop_patch_kind::irregular) {
      const auto j = evaluate_quartic_bezier_jet(bezier_patch_unchecked(f), FT(u), FT(v));
      return jet(j.position, j.du, j.dv, 0);
    }
    return irregular(f, u, v, true);
  }

  /// The (not normalised) normal at (u, v) of face f; see Loop_limit_jet::normal.
  Point_3<FT> normal(Index f, double u, double v) const { return evaluate_with_derivatives(f, u, v).normal; }

  /// The exact limit position of control vertex v (see exact_limit_values).
  /// \throws Invalid_surface_parameter for a bad index.
  Point limit_position(Index v) const {
    if (v >= points_.size())
      throw Invalid_surface_parameter("Loop limit surface: vertex " + std::to_string(v) + " out of range");
    if (topology_.is_isolated(v)) return A::make(points_[v].x, points_[v].y, points_[v].z);
    const Default_fp_environment_if<K::is_certified> environment;
    const auto vals = internal::exact_limit_values(topology_, rules_, weights_, v, 3, &points_[0].x);
    return A::make(vals[0], vals[1], vals[2]);
  }

 private:
  using A = internal::Point_access<Point>;
  static_assert(sizeof(Point_3<FT>) == 3 * sizeof(FT), "Point_3<FT> must be three packed FT");

  void check_face(Index f) const {
    if (f >= kind_.size())
      throw Invalid_surface_parameter("Loop limit surface: face " + std::to_string(f) + " out of range (" +
                                      std::to_string(kind_.size()) + " faces)");
  }
  void check(Index f, double u, double v) const {
    check_face(f);
    if (!std::isfinite(u) || !std::isfinite(v))
      throw Non_finite_input("Loop limit surface: parameter (u, v) is NaN or infinite");
    if (!internal::in_parameter_triangle(u, v))
      throw Invalid_surface_parameter("Loop limit surface: (u, v) = (" + std::to_string(u) + ", " + std::to_string(v) +
                                      ") is outside the triangle u, v >= 0, u + v <= 1");
  }

  Quartic_bezier_patch<FT> bezier_patch_unchecked(Index f) const {
    std::array<Point_3<FT>, 12> p;
    const auto& s = slots_[slot_index_[f]];
    for (int i = 0; i < 12; ++i) p[i] = slot_point(s[i]);
    return loop_patch_to_bezier(p, one_24_);
  }
  // sum_i b_i(u, v) p_i with the 12 box-spline values (one pass, no Bezier net).
  Point_3<FT> evaluate_regular(Index f, const FT& u, const FT& v) const {
    const FT w = FT(FT(FT(1) - u) - v);
    const std::array<FT, 12> b = loop_patch_basis_times_24(w, u, v);
    const auto& s = slots_[slot_index_[f]];
    FT x(0), y(0), z(0);
    for (int i = 0; i < 12; ++i) {
      const Point_3<FT>& a = points_[s[i].a];
      if (!s[i].is_ghost()) {
        x = FT(x + FT(b[i] * a.x)), y = FT(y + FT(b[i] * a.y)), z = FT(z + FT(b[i] * a.z));
      } else {
        const Point_3<FT>&pb = points_[s[i].b], &pc = points_[s[i].c];
        x = FT(x + FT(b[i] * FT(FT(a.x + pb.x) - pc.x)));
        y = FT(y + FT(b[i] * FT(FT(a.y + pb.y) - pc.y)));
        z = FT(z + FT(b[i] * FT(FT(a.z + pb.z) - pc.z)));
      }
    }
    return Point_3<FT>{FT(x * one_24_), FT(y * one_24_), FT(z * one_24_)};
  }

  static Point_3<FT> cross(const Point_3<FT>& a, const Point_3<FT>& b) {
    return {FT(FT(a.y * b.z) - FT(a.z * b.y)), FT(FT(a.z * b.x) - FT(a.x * b.z)), FT(FT(a.x * b.y) - FT(a.y * b.x))};
  }
  static Loop_limit_jet<FT> jet(const Point_3<FT>& p, const Point_3<FT>& du, const Point_3<FT>& dv, unsigned levels) {
    Loop_limit_jet<FT> r;
    r.position = p, r.du = du, r.dv = dv, r.normal = cross(du, dv), r.levels = levels;
    return r;
  }

  // Local subdivision until the sub-patch holding (u, v) is regular. Along
  // the descent towards a smooth extraordinary vertex the local patch repeats
  // itself after one step (same faces, same rule data: Stam's subdivision
  // matrix); the last step's stencils are then reused, skipping the
  // topology, the classification and the extraction.
  Loop_limit_jet<FT> irregular(Index f, double u0, double v0, bool derivatives) const {
    using Patch = internal::Loop_local_patch<FT>;
    using Stencils = std::vector<Stencil<FT>>;
    Patch P = internal::extract_local_patch<FT>(topology_, rules_, f, 3, [&](Index v, FT* out) {
      out[0] = points_[v].x, out[1] = points_[v].y, out[2] = points_[v].z;
    });
    mpq_class u(u0), v(v0);
    const mpq_class half(1, 2), one(1);
    // J = d(s, t) / d(u0, v0) of the current patch's parameters.
    FT J[2][2] = {{FT(1), FT(0)}, {FT(0), FT(1)}};
    const Loop_options& o = options();
    struct Memo {  // the last irregular step: its patch's structure and its child
      std::vector<Triangle> faces;
      internal::Loop_rule_data rules;
      bool corner_regular[3] = {false, false, false};
      int child = -1;
      std::vector<Triangle> child_faces;
      internal::Loop_rule_data child_rules;
      Stencils stencils;
    } memo;
    bool have_memo = false;
    for (unsigned level = 0;; ++level) {
      const bool repeated = have_memo && P.faces == memo.faces && P.rules == memo.rules;
      Mesh_topology t;
      bool corner_regular[3];
      if (repeated) {
        std::copy_n(memo.corner_regular, 3, corner_regular);
      } else {
        t = internal::local_topology(P);
        std::array<internal::Patch_slot, 12> s;
        if (internal::classify_loop_patch(t, P.rules, o, 0, &s) != Loop_patch_kind::irregular) {
          std::array<Point_3<FT>, 12> net;
          for (int i = 0; i < 12; ++i) {
            const FT* a = P.value(s[i].a);
            net[i] = {a[0], a[1], a[2]};
            if (s[i].is_ghost()) {
              const FT *b = P.value(s[i].b), *c = P.value(s[i].c);
              net[i] = {FT(FT(a[0] + b[0]) - c[0]), FT(FT(a[1] + b[1]) - c[1]), FT(FT(a[2] + b[2]) - c[2])};
            }
          }
          const auto bez = loop_patch_to_bezier(net, one_24_);
          const FT us = internal::ft_from_rational<FT>(u), vs = internal::ft_from_rational<FT>(v);
          if (!derivatives) return jet(evaluate_quartic_bezier(bez, us, vs), {}, {}, level);
          const auto j = evaluate_quartic_bezier_jet(bez, us, vs);
          // [S_u0 S_v0] = [Q_s Q_t] J
          const auto comb = [&](const Point_3<FT>& a, const FT& x, const Point_3<FT>& b, const FT& y) {
            return Point_3<FT>{FT(FT(a.x * x) + FT(b.x * y)), FT(FT(a.y * x) + FT(b.y * y)), FT(FT(a.z * x) + FT(b.z * y))};
          };
          return jet(j.position, comb(j.du, J[0][0], j.dv, J[1][0]), comb(j.du, J[0][1], j.dv, J[1][1]), level);
        }
        for (int k = 0; k < 3; ++k) corner_regular[k] = internal::patch_corner_is_regular(t, P.rules, o, 0, k);
      }
      // At an irregular corner itself: its exact limit position and tangent plane.
      int corner = -1;
      if (sgn(u) == 0 && sgn(v) == 0) corner = 0;
      else if (u == one) corner = 1;
      else if (v == one) corner = 2;
      if (corner >= 0 && !corner_regular[corner]) {
        if (repeated) t = internal::local_topology(P);
        const Index a = P.faces[0][corner];
        const auto val = internal::exact_limit_values(t, P.rules, weights_, a, 3, P.values.data());
        Loop_limit_jet<FT> r;
        r.position = {val[0], val[1], val[2]};
        r.has_derivatives = false;
        r.du = r.dv = Point_3<FT>{FT(0), FT(0), FT(0)};
        r.levels = level;
        if (derivatives) r.normal = corner_normal(P, t, corner);
        return r;
      }
      if (level >= max_levels)
        throw Error(Error_code::computation_failure, "Loop limit surface: no regular sub-patch after " +
                                                         std::to_string(max_levels) + " levels");
      const mpq_class w = one - u - v;
      int c;
      mpq_class nu, nv;
      if (w >= half) c = 0, nu = 2 * u, nv = 2 * v;
      else if (u >= half) c = 1, nu = 2 * v, nv = 2 * w;
      else if (v >= half) c = 2, nu = 2 * w, nv = 2 * u;
      else c = 3, nu = one - 2 * w, nv = one - 2 * u;
      u = nu, v = nv;
      if (derivatives) {
        FT N[2][2];
        for (int r = 0; r < 2; ++r)
          for (int k = 0; k < 2; ++k)
            N[r][k] = FT(FT(FT(loop_child_jacobian[c][r][0]) * J[0][k]) + FT(FT(loop_child_jacobian[c][r][1]) * J[1][k]));
        for (int r = 0; r < 2; ++r)
          for (int k = 0; k < 2; ++k) J[r][k] = N[r][k];
      }
      if (repeated && memo.child == c) {
        Patch Q;
        Q.dim = 3;
        Q.faces = memo.child_faces;
        Q.rules = memo.child_rules;
        Q.values.assign(memo.stencils.size() * 3, FT(0));
        for (std::size_t i = 0; i < memo.stencils.size(); ++i) {
          const Stencil<FT>& st = memo.stencils[i];
          for (std::size_t j = 0; j < st.vertices.size(); ++j)
            for (int k = 0; k < 3; ++k)
              Q.values[i * 3 + k] = FT(Q.values[i * 3 + k] + FT(st.weights[j] * P.values[std::size_t(st.vertices[j]) * 3 + k]));
        }
        P = std::move(Q);
        continue;
      }
      if (repeated) t = internal::local_topology(P);
      Stencils st;
      auto children = internal::refine_local_patch<K>(P, t, weights_, 1u << c, &st);
      memo.faces = P.faces, memo.rules = P.rules, memo.child = c;
      std::copy_n(corner_regular, 3, memo.corner_regular);
      memo.child_faces = children[c].faces, memo.child_rules = children[c].rules, memo.stencils = std::move(st);
      have_memo = true;
      P = std::move(children[c]);
    }
  }

  // Tangent-mask normal at corner `corner` of the local patch's face 0.
  Point_3<FT> corner_normal(const internal::Loop_local_patch<FT>& P, const Mesh_topology& t, int corner) const {
    Loop_features lf;
    lf.vertex_kind = P.rules.kind;
    lf.edge_is_crease.assign(t.number_of_edges(), 0);
    lf.edge_is_tagged.assign(t.number_of_edges(), 0);
    for (Index h = 0; h < P.rules.crease.size(); ++h)
      if (P.rules.crease[h]) lf.edge_is_crease[t.edge(h)] = 1;
    lf.crease_degree.assign(P.number_of_vertices(), 0);
    const Index h = Index(corner), a = P.faces[0][corner];
    const auto [s1, s2] = tangent_stencils(t, lf, weights_, a, h);
    std::vector<Point_3<FT>> pts(P.number_of_vertices());
    for (Index i = 0; i < pts.size(); ++i) pts[i] = {P.value(i)[0], P.value(i)[1], P.value(i)[2]};
    return cross(apply_stencil(s1, pts), apply_stencil(s2, pts));
  }

  K kernel_;
  mutable Loop_weights<K> weights_;  // reserved at construction: queries only read it
  std::vector<Point_3<FT>> points_;
  Mesh_topology topology_;
  Loop_features features_;
  internal::Loop_rule_data rules_;
  FT one_24_;
  std::vector<Loop_patch_kind> kind_;
  std::vector<Index> slot_index_;
  std::vector<std::array<internal::Patch_slot, 12>> slots_;
};

/// Convenience: the limit surface point at (u, v) of face f of `control`
/// under kernel K (default: Default_loop_kernel of the point type). Builds a
/// Loop_limit_surface: for many queries keep one.
template <class K = void, class P>
P loop_limit_point(const Triangle_mesh<P>& control, Index f, double u, double v, const Loop_options& options = {}) {
  using Kernel = std::conditional_t<std::is_void_v<K>, typename Default_loop_kernel<P>::type, K>;
  return Loop_limit_surface<Kernel>(control, options).evaluate(f, u, v);
}

}  // namespace relgeo
