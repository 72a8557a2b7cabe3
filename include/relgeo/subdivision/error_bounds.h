// relgeo/subdivision/error_bounds.h — how far the limit surface can be from
// the limit mesh: per face of the limit mesh at level k, lower and upper
// offsets along the face normal that enclose the limit surface over that face
// (thesis Sec. 5.4.1, eqs. 5.5-5.14; doc/subdivision.md Sec. 7.2).
//
// Notation. Face g of the limit mesh has corners q0, q1, q2 (limit positions
// of the level-k control vertices), E1 = q1 - q0, E2 = q2 - q0 and the normal
// n = E1 x E2 (not normalised, so everything stays rational). Every point x
// is x = q0 + a E1 + b E2 + t n; t is the *height* over the face (t |n| the
// signed distance from the face's plane). The limit surface over g is
// S(u, v) = sum_i b_i(u, v) p_i over the control points p_i around g (the
// 1-ring of g in the level-k mesh; for regular patches the 12 box-spline
// points, ghosts included), sum_i b_i = 1.
//
//  * basis_range (eqs. 5.6-5.8): for a linear functional phi (here t),
//      phi(S) = sum_i phi(p_i) b_i  lies in
//      [sum_i min(phi(p_i) b_i^-, phi(p_i) b_i^+), sum_i max(...)],
//    b_i^- <= b_i <= b_i^+ the ranges of the nodal functions over the face.
//    The thesis estimates the ranges by subdividing Dirac nets and iterating;
//    here they are *enclosures*: Bezier hulls (convex-hull property) of the
//    regular (sub-)patches, refined regular_depth times, and, for the
//    remaining irregular sub-patch after irregular_depth local subdivision
//    steps, the hull of its control values (Loop's weights are all
//    nonnegative, so the limit over a sub-patch is a convex combination of
//    the sub-patch's 1-ring values). In exact arithmetic l_j = l and u_j = u
//    for the three corners (the q_j lie in the face's plane), so eq. 5.8's
//    volume is the slab l <= t |n| <= u (offset along each vertex normal n_j
//    by l / (n . n_j) it passes through the same planes).
//  * tangent_plane (eqs. 5.9-5.14, made provable): the thesis tilts the exact
//    vertex tangent planes (tangent masks, eq. 5.10) to a common angle and
//    assumes the surface stays below them, which it calls approximate. Here
//    each tangent plane P_j = (q_j, n_j) gets a rigorous range
//    g_j^- <= n_j . (S - q_j) <= g_j^+ from the same nodal ranges, and the
//    surface's projection a rigorous triangle D' = {a >= a^-, b >= b^-,
//    a + b <= 1 - c^-}. Then over D'
//      t <= min(u, T_0(a, b), T_1, T_2),  T_j from g_j^+ (n_j . n > 0),
//    a concave piecewise-linear "tent" whose maximum (over the vertices of its
//    arrangement in D') is the upper offset; the lower offset likewise from
//    g_j^- (the "reflected planes"). Never looser than basis_range.
//  * direct (reference, not in the thesis): the same hulls applied to the
//    height t itself instead of to each nodal function.
//  * thesis_estimate: the construction as printed (common angle phi = min
//    theta_j, planes through q_j, reflected below), in double: *not* a
//    bound; tests and `relgeo experiment` count where it fails.
//
// Soundness: the enclosures are exact statements about the kernel's numbers,
// i.e. about the limit surface of the scheme with the kernel's weights:
//  * Interval_kernel (reading lower.inf(), upper.sup(), and the distances):
//    weights enclose Loop's at every valence and all arithmetic is outward,
//    so these bound Loop's own limit surface of the given control mesh;
//  * Exact_kernel: Loop's surface at valences 3, 4, 6 (and crease, corner,
//    BLZ, Warren rules); at other valences the surface of the scheme whose
//    beta is the rational value of a 256-bit cosine (within 2^-250 of
//    Loop's), whose distance to Loop's surface is not bounded here;
//  * double kernels: the rounding errors of their computation (relative
//    ~1e-15, measured in the tests), not certified.
// doc/subdivision.md, "What is certified".
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "relgeo/core/fp_environment.h"
#include "relgeo/core/errors.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/box_spline.h"
#include "relgeo/subdivision/limit_evaluation.h"
#include "relgeo/subdivision/loop_subdivision.h"

namespace relgeo {

/// Options of the error bounds (designated initializers).
struct Loop_bound_options {
  /// Local subdivision steps spent on an irregular patch before its remaining
  /// irregular sub-patch is bounded by the hull of its control values.
  unsigned irregular_depth = 5;
  /// Bezier hulls of regular sub-patches of irregular patches are refined
  /// this many times (4^depth sub-nets). Regular faces use the universal
  /// nodal ranges, refined universal_depth times.
  unsigned regular_depth = 2;
  /// Refinement of the universal nodal ranges of the 12 box-spline functions.
  unsigned universal_depth = 4;
  /// Where the tangent-plane construction takes its ranges of the heights
  /// over the three tangent planes and of the face coordinates: from the
  /// hulls of those functions themselves (default; rigorous and tight) or
  /// from the nodal ranges of eq. 5.7 (as loose as the slab: measured to give
  /// no gain over basis_range).
  enum class Tangent_ranges { direct, basis } tangent_ranges = Tangent_ranges::direct;
  /// Also report the direct hull of the height (reference method; computed
  /// anyway when tangent_ranges is direct).
  bool direct = true;
  /// Also compute the thesis' construction as printed (double, not a bound).
  bool thesis_estimate = true;
};

/// Lower and upper bound of the height t over one face (x = q0 + a E1 + b E2
/// + t n), and the same as signed distances along the unit normal
/// (t |n|, rounded outward to double).
template <class FT>
struct Loop_face_bound {
  FT lower{}, upper{};
  double lower_distance = 0, upper_distance = 0;
};

namespace internal {

/// min and max that stay enclosures for intervals.
template <class FT>
FT min_of(const FT& a, const FT& b) {
  if constexpr (requires { a.inf(); a.sup(); }) return FT(std::min(a.inf(), b.inf()), std::min(a.sup(), b.sup()));
  else return b < a ? b : a;
}
template <class FT>
FT max_of(const FT& a, const FT& b) {
  if constexpr (requires { a.inf(); a.sup(); }) return FT(std::max(a.inf(), b.inf()), std::max(a.sup(), b.sup()));
  else return a < b ? b : a;
}
/// A double <= (>=) the value (rounded outward).
template <class FT>
double lower_double(const FT& x) {
  if constexpr (requires { x.inf(); }) return x.inf();
  else if constexpr (std::is_same_v<FT, double>) return x;
  else return std::nextafter(coordinate_to_double(x), -INFINITY);
}
template <class FT>
double upper_double(const FT& x) {
  if constexpr (requires { x.sup(); }) return x.sup();
  else if constexpr (std::is_same_v<FT, double>) return x;
  else return std::nextafter(coordinate_to_double(x), INFINITY);
}
/// a <= b possibly (exactly for exact types; with a relative tolerance for
/// floating point, where excluding a candidate by rounding would be unsound
/// and including one only loosens).
template <class FT>
bool possibly_le(const FT& a, const FT& b, double tol) {
  if constexpr (requires { a.inf(); b.sup(); }) return a.inf() <= b.sup();
  else if constexpr (std::is_floating_point_v<FT>) return a <= b + tol;
  else return !(b < a);
}

/// Adds the ranges over the Bezier nets of a regular patch (12 x dim values,
/// row-major) refined `depth` times to lo/hi (per dim).
template <class FT>
void regular_net_ranges(const std::vector<FT>& net, std::size_t dim, unsigned depth, const FT& one_24,
                        const FT& one_16, std::vector<FT>& lo, std::vector<FT>& hi, std::vector<bool>& have) {
  if (depth == 0) {
    for (std::size_t d = 0; d < dim; ++d) {
      const std::array<FT, 15> b = loop_patch_bezier_times_24(net.data() + d, dim);
      for (const FT& x24 : b) {
        const FT x = FT(x24 * one_24);
        lo[d] = have[d] ? min_of(lo[d], x) : x;
        hi[d] = have[d] ? max_of(hi[d], x) : x;
        have[d] = true;
      }
    }
    return;
  }
  std::vector<FT> child(12 * dim);
  for (int c = 0; c < 4; ++c) {
    for (std::size_t d = 0; d < dim; ++d) {
      const std::array<FT, 12> r = loop_patch_child_times_16(net.data() + d, c, dim);
      for (int i = 0; i < 12; ++i) child[i * dim + d] = FT(r[i] * one_16);
    }
    regular_net_ranges(child, dim, depth - 1, one_24, one_16, lo, hi, have);
  }
}

/// The vertices whose values the limit over face f depends on: the vertices
/// of the faces around each corner of f, except, at a crease vertex or
/// corner, the faces of its other sectors (crease rules never look across a
/// crease). The limit over f is a convex combination of these values (Loop's
/// weights are nonnegative and the children's sets are built from them).
inline std::vector<Index> influence_vertices(const Mesh_topology& t, const Loop_rule_data& d, Index f) {
  std::vector<Index> out;
  const auto add_face = [&](Index g) {
    for (Index v : t.faces()[g])
      if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
  };
  for (int k = 0; k < 3; ++k) {
    const Index h = 3 * f + Index(k), a = t.source(h);
    if (!d.special(a)) {
      t.for_each_outgoing(a, [&](Index g) { add_face(Mesh_topology::face(g)); });
      continue;
    }
    Index first = h;  // clockwise to the crease half-edge starting the sector
    for (Index guard = 0; guard <= t.number_of_incident_faces(a) && !d.crease[first]; ++guard)
      first = Mesh_topology::next(t.opposite(first));
    Index g = first;
    for (Index guard = 0; guard < t.number_of_incident_faces(a) && g != invalid_index; ++guard) {
      add_face(Mesh_topology::face(g));
      g = t.ccw_outgoing(g);
      if (g == invalid_index || d.crease[g]) break;
    }
  }
  return out;
}

/// Ranges (per dim) of the limit of a local patch's values over its face 0:
/// Bezier hulls of regular sub-patches, hull of the control values of the
/// irregular sub-patch left after irregular_depth steps.
template <class K>
void local_patch_ranges(const Loop_local_patch<typename K::FT>& P, const Loop_weights<K>& w,
                        unsigned irregular_depth, unsigned regular_depth, const typename K::FT& one_24,
                        const typename K::FT& one_16, std::vector<typename K::FT>& lo,
                        std::vector<typename K::FT>& hi, std::vector<bool>& have) {
  using FT = typename K::FT;
  const std::size_t dim = P.dim;
  const Mesh_topology t = local_topology(P);
  std::array<Patch_slot, 12> s;
  if (classify_loop_patch(t, P.rules, w.options(), 0, &s) != Loop_patch_kind::irregular) {
    std::vector<FT> net(12 * dim);
    for (int i = 0; i < 12; ++i) {
      const FT* a = P.value(s[i].a);
      for (std::size_t d = 0; d < dim; ++d) net[i * dim + d] = a[d];
      if (s[i].is_ghost()) {
        const FT *b = P.value(s[i].b), *c = P.value(s[i].c);
        for (std::size_t d = 0; d < dim; ++d) net[i * dim + d] = FT(FT(a[d] + b[d]) - c[d]);
      }
    }
    regular_net_ranges(net, dim, regular_depth, one_24, one_16, lo, hi, have);
    return;
  }
  if (irregular_depth == 0) {
    for (Index v : influence_vertices(t, P.rules, 0))
      for (std::size_t d = 0; d < dim; ++d) {
        const FT& x = P.value(v)[d];
        lo[d] = have[d] ? min_of(lo[d], x) : x;
        hi[d] = have[d] ? max_of(hi[d], x) : x;
        have[d] = true;
      }
    return;
  }
  const auto children = refine_local_patch<K>(P, t, w, 0xFu);
  for (const auto& c : children)
    local_patch_ranges<K>(c, w, irregular_depth - 1, regular_depth, one_24, one_16, lo, hi, have);
}

/// An affine function tau + rho a + sigma b of the face coordinates.
template <class FT>
struct Affine_2 {
  FT tau, rho, sigma;
  FT operator()(const FT& a, const FT& b) const { return FT(FT(tau + FT(rho * a)) + FT(sigma * b)); }
};

/// max over D' = {a >= amin, b >= bmin, a + b <= s} of min_k f_k(a, b),
/// from the vertices of the arrangement (D''s corners, crossings of the lines
/// f_k = f_l with D''s edges, points where three f are equal). False when a
/// determinant cannot be certified nonzero-or-zero (intervals).
template <class FT, class Tr>
bool tent_maximum(const std::vector<Affine_2<FT>>& f, const FT& amin, const FT& bmin, const FT& s, double tol,
                  FT& result) {
  struct Line {
    FT p, q, r;  // p a + q b = r
  };
  std::vector<Line> lines{{FT(1), FT(0), amin}, {FT(0), FT(1), bmin}, {FT(1), FT(1), s}};
  const std::size_t nedge = 3;
  for (std::size_t k = 0; k < f.size(); ++k)
    for (std::size_t l = k + 1; l < f.size(); ++l)
      lines.push_back({FT(f[k].rho - f[l].rho), FT(f[k].sigma - f[l].sigma), FT(f[l].tau - f[k].tau)});
  bool have = false, ok = true;
  const auto consider = [&](const FT& a, const FT& b) {
    if (!possibly_le(amin, a, tol) || !possibly_le(bmin, b, tol) || !possibly_le(FT(a + b), s, tol)) return;
    FT v = f[0](a, b);
    for (std::size_t k = 1; k < f.size(); ++k) v = min_of(v, f[k](a, b));
    result = have ? max_of(result, v) : v;
    have = true;
  };
  const auto intersect = [&](const Line& x, const Line& y) {
    const FT det = FT(FT(x.p * y.q) - FT(y.p * x.q));
    if constexpr (requires { det.inf(); }) {
      if (det.inf() == 0 && det.sup() == 0) return;
      if (!(det.inf() > 0 || det.sup() < 0)) {
        ok = false;
        return;
      }
    } else {
      if (det == FT(0)) return;
    }
    consider(Tr::quotient(FT(FT(x.r * y.q) - FT(y.r * x.q)), det), Tr::quotient(FT(FT(x.p * y.r) - FT(y.p * x.r)), det));
  };
  for (std::size_t i = 0; i < nedge; ++i)
    for (std::size_t j = i + 1; j < lines.size(); ++j) intersect(lines[i], lines[j]);
  // three equal functions: two of the pair lines through a common k
  for (std::size_t k = 0; k < f.size(); ++k)
    for (std::size_t l = k + 1; l < f.size(); ++l)
      for (std::size_t m = l + 1; m < f.size(); ++m)
        intersect(Line{FT(f[k].rho - f[l].rho), FT(f[k].sigma - f[l].sigma), FT(f[l].tau - f[k].tau)},
                  Line{FT(f[k].rho - f[m].rho), FT(f[k].sigma - f[m].sigma), FT(f[m].tau - f[k].tau)});
  return ok && have;
}

}  // namespace internal

/// \brief The limit mesh at a level with, per face, enclosures of the limit
/// surface over it (see the file comment for the methods).
template <class K>
struct Loop_limit_mesh_bounds {
  using FT = typename K::FT;
  using Point = typename K::Point_3;
  unsigned level = 0;
  Triangle_mesh<Point> refined;     ///< the control mesh refined `level` times
  Triangle_mesh<Point> limit_mesh;  ///< its limit mesh (same faces)
  /// Per face: n = (q1 - q0) x (q2 - q0) and |n| (double, rounded to nearest;
  /// the distances of the bounds use |n| rounded outward).
  std::vector<Point_3<FT>> normal;
  std::vector<double> normal_length;
  /// Per face: the face is degenerate (n = 0; no bound computed).
  std::vector<std::uint8_t> degenerate;
  std::vector<Loop_patch_kind> patch_kind;
  std::vector<Loop_face_bound<FT>> basis_range, tangent_plane, direct;
  /// The thesis' construction as printed (distances; not a bound).
  std::vector<std::pair<double, double>> thesis_estimate;

  /// The height t of point x over face f (x = q0 + a E1 + b E2 + t n).
  FT height(Index f, const Point_3<FT>& x) const {
    using A = internal::Point_access<Point>;
    const Point& q = limit_mesh.vertices[limit_mesh.faces[f][0]];
    const Point_3<FT>& n = normal[f];
    const FT nn = FT(FT(FT(n.x * n.x) + FT(n.y * n.y)) + FT(n.z * n.z));
    const FT d = FT(FT(FT(n.x * FT(x.x - A::x(q))) + FT(n.y * FT(x.y - A::y(q)))) + FT(n.z * FT(x.z - A::z(q))));
    return Loop_kernel_number_traits<K>::quotient(d, nn);
  }
};

/// \brief Computes limit meshes with per-face error bounds under kernel K.
///
/// compute(control, k) refines the control mesh k times, takes the limit
/// mesh, and bounds the limit surface over each of its faces (local patches
/// of the refined mesh). Requirements and errors as Loop_subdivider; also
/// Error (computation_failure) when a face normal overflows the number type.
/// Complexity: O(F) with a per-face constant: regular faces reuse the
/// universal ranges of the 12 box-spline functions (computed once per
/// object), irregular faces (one per face around an irregular vertex)
/// subdivide locally (~3 irregular_depth regular sub-patches).
template <class K>
class Loop_error_bounds {
 public:
  using FT = typename K::FT;
  using Point = typename K::Point_3;
  using Mesh = Triangle_mesh<Point>;
  using Tr = Loop_kernel_number_traits<K>;

  explicit Loop_error_bounds(const Loop_options& options = {}, const Loop_bound_options& bounds = {}, const K& kernel = K{})
      : options_(options), bounds_(bounds), kernel_(kernel), one_24_(Tr::rational(1, 24)), one_16_(Tr::rational(1, 16)) {
    universal_ = universal_ranges(bounds.universal_depth, one_24_, one_16_);
  }

  const Loop_options& options() const { return options_; }
  const Loop_bound_options& bound_options() const { return bounds_; }
  /// Enclosures [min, max] over the triangle of the 12 box-spline functions
  /// (box_spline.h order).
  const std::array<std::pair<FT, FT>, 12>& regular_basis_ranges() const { return universal_; }

  /// The limit mesh at `level` and its per-face bounds.
  Loop_limit_mesh_bounds<K> compute(const Mesh& control, unsigned level) const {
    const Default_fp_environment environment;  // the bounds are rounded outward in hardware
    Loop_limit_mesh_bounds<K> r;
    r.level = level;
    Loop_subdivider<K> sub(options_, kernel_);
    r.refined = sub.refine(control, level);
    r.limit_mesh = sub.limit_mesh(control, level);
    const Loop_limit_surface<K> surface(r.refined, options_, kernel_);
    Loop_weights<K> w(options_);
    Index max_valence = 6;
    for (Index v = 0; v < r.refined.vertices.size(); ++v) max_valence = std::max(max_valence, surface.topology().valence(v));
    w.reserve(max_valence + 1);
    const std::size_t nf = r.refined.faces.size();
    r.normal.resize(nf), r.normal_length.resize(nf), r.degenerate.assign(nf, 0), r.patch_kind.resize(nf);
    r.basis_range.resize(nf), r.tangent_plane.resize(nf);
    if (bounds_.direct) r.direct.resize(nf);
    if (bounds_.thesis_estimate) r.thesis_estimate.resize(nf);
    const std::vector<Point_3<FT>>& p = surface.control_points();
    std::vector<Point_3<FT>> q(r.limit_mesh.vertices.size());
    for (std::size_t v = 0; v < q.size(); ++v) q[v] = {A::x(r.limit_mesh.vertices[v]), A::y(r.limit_mesh.vertices[v]), A::z(r.limit_mesh.vertices[v])};
    for (Index g = 0; g < nf; ++g) face_bounds(surface, w, p, q, g, r);
    return r;
  }

 private:
  using A = internal::Point_access<Point>;
  using P3 = Point_3<FT>;

  static P3 sub3(const P3& a, const P3& b) { return {FT(a.x - b.x), FT(a.y - b.y), FT(a.z - b.z)}; }
  static FT dot(const P3& a, const P3& b) { return FT(FT(FT(a.x * b.x) + FT(a.y * b.y)) + FT(a.z * b.z)); }
  static P3 cross(const P3& a, const P3& b) {
    return {FT(FT(a.y * b.z) - FT(a.z * b.y)), FT(FT(a.z * b.x) - FT(a.x * b.z)), FT(FT(a.x * b.y) - FT(a.y * b.x))};
  }
  static P3 scale(const P3& a, const FT& s) { return {FT(a.x * s), FT(a.y * s), FT(a.z * s)}; }
  static P3 divide(const P3& a, const FT& s) { return {Tr::quotient(a.x, s), Tr::quotient(a.y, s), Tr::quotient(a.z, s)}; }

  // phi(x) = dir . x + offset
  struct Functional {
    P3 dir;
    FT offset;
    FT operator()(const P3& x) const { return FT(dot(dir, x) + offset); }
  };

  static bool certainly_zero_or_contains_zero(const FT& x) {
    if constexpr (requires { x.inf(); }) return !(x.inf() > 0 || x.sup() < 0);
    else return x == FT(0);
  }
  static bool certainly_positive(const FT& x) {
    if constexpr (requires { x.inf(); }) return x.inf() > 0;
    else return FT(0) < x;
  }
  static bool certainly_negative(const FT& x) {
    if constexpr (requires { x.sup(); }) return x.sup() < 0;
    else return x < FT(0);
  }

  void face_bounds(const Loop_limit_surface<K>& surface, Loop_weights<K>& w, const std::vector<P3>& p,
                   const std::vector<P3>& q, Index g, Loop_limit_mesh_bounds<K>& r) const {
    const Triangle& tri = r.refined.faces[g];
    const P3 &q0 = q[tri[0]], &q1 = q[tri[1]], &q2 = q[tri[2]];
    const P3 E1 = sub3(q1, q0), E2 = sub3(q2, q0), n = cross(E1, E2);
    const FT nn = dot(n, n);
    r.normal[g] = n;
    const double len = std::sqrt(internal::coordinate_to_double(nn));
    r.normal_length[g] = len;
    r.patch_kind[g] = surface.patch_kind(g);
    // Finite input can overflow here in floating point (|n| ~ |E|^2): refuse
    // rather than return NaN bounds (test/data/bad/coordinates_1e300.off).
    if (!is_finite_number(nn))
      throw Error(Error_code::computation_failure, "Loop error bounds: the normal of limit-mesh face " +
                                                       std::to_string(g) +
                                                       " overflows (coordinates too large for the number type)");
    if (certainly_zero_or_contains_zero(nn) || !(len > 0)) {
      r.degenerate[g] = 1;
      return;
    }
    const Length_bounds length = length_bounds(nn);
    // The functionals: t, a, b, c = 1 - a - b, psi_j = n_j . (x - q_j).
    std::vector<Functional> phi;
    const auto affine = [&](const P3& dir) { return Functional{dir, FT(-dot(dir, q0))}; };
    phi.push_back(affine(divide(n, nn)));
    phi.push_back(affine(divide(cross(E2, n), nn)));
    phi.push_back(affine(divide(cross(n, E1), nn)));
    phi.push_back(Functional{scale(sub3(phi[1].dir, scale(phi[2].dir, FT(-1))), FT(-1)),
                             FT(FT(FT(1) - phi[1].offset) - phi[2].offset)});
    std::array<P3, 3> nj;
    for (int j = 0; j < 3; ++j) {
      const auto [s1, s2] = tangent_stencils(surface.topology(), surface.features(), w, tri[j], 3 * g + Index(j));
      nj[j] = cross(apply_stencil(s1, p), apply_stencil(s2, p));
      phi.push_back(Functional{nj[j], FT(-dot(nj[j], q[tri[j]]))});
    }
    const std::size_t nphi = phi.size();  // 7
    std::vector<FT> lo(nphi), hi(nphi);
    // eq. 5.7 over the control points and nodal ranges.
    const auto accumulate = [&](const P3& point, const FT& bmin, const FT& bmax, bool first) {
      for (std::size_t k = 0; k < nphi; ++k) {
        const FT c = phi[k](point);
        const FT x = FT(c * bmin), y = FT(c * bmax);
        const FT mn = internal::min_of(x, y), mx = internal::max_of(x, y);
        lo[k] = first ? mn : FT(lo[k] + mn);
        hi[k] = first ? mx : FT(hi[k] + mx);
      }
    };
    const auto* slots = surface.patch_slots(g);
    std::vector<P3> cps;  // control points (direct method)
    internal::Loop_local_patch<FT> local;
    if (slots) {
      for (int i = 0; i < 12; ++i) {
        cps.push_back(surface.slot_point((*slots)[i]));
        accumulate(cps.back(), universal_[i].first, universal_[i].second, i == 0);
      }
    } else {
      std::vector<Index> ids;
      local = internal::extract_local_patch<FT>(surface.topology(), surface.rule_data(), g, 1,
                                                [](Index, FT* o) { *o = FT(0); }, &ids);
      // Dirac nets: one unit vector per local vertex.
      const std::size_t nloc = ids.size();
      local.dim = nloc;
      local.values.assign(nloc * nloc, FT(0));
      for (std::size_t i = 0; i < nloc; ++i) local.values[i * nloc + i] = FT(1);
      std::vector<FT> blo(nloc), bhi(nloc);
      std::vector<bool> have(nloc, false);
      internal::local_patch_ranges<K>(local, w, bounds_.irregular_depth, bounds_.regular_depth, one_24_, one_16_, blo, bhi, have);
      for (std::size_t i = 0; i < nloc; ++i) {
        cps.push_back(p[ids[i]]);
        accumulate(cps.back(), blo[i], bhi[i], i == 0);
      }
    }
    const FT L = lo[0], U = hi[0];
    r.basis_range[g] = make_bound(L, U, length);
    // Direct hulls of the 7 functionals (Bezier hulls of regular patches,
    // local subdivision of irregular ones).
    const bool need_direct = bounds_.direct || bounds_.tangent_ranges == Loop_bound_options::Tangent_ranges::direct;
    std::vector<FT> dlo(nphi), dhi(nphi);
    if (need_direct) {
      std::vector<bool> have(nphi, false);
      if (slots) {
        std::vector<FT> net(12 * nphi);
        for (int i = 0; i < 12; ++i)
          for (std::size_t k = 0; k < nphi; ++k) net[i * nphi + k] = phi[k](cps[i]);
        internal::regular_net_ranges(net, nphi, bounds_.regular_depth, one_24_, one_16_, dlo, dhi, have);
      } else {
        internal::Loop_local_patch<FT> hp = local;
        hp.dim = nphi;
        hp.values.resize(cps.size() * nphi);
        for (std::size_t i = 0; i < cps.size(); ++i)
          for (std::size_t k = 0; k < nphi; ++k) hp.values[i * nphi + k] = phi[k](cps[i]);
        internal::local_patch_ranges<K>(hp, w, bounds_.irregular_depth, bounds_.regular_depth, one_24_, one_16_, dlo, dhi, have);
      }
      if (bounds_.direct) r.direct[g] = make_bound(dlo[0], dhi[0], length);
    }
    const bool aux_direct = bounds_.tangent_ranges == Loop_bound_options::Tangent_ranges::direct;
    const std::vector<FT>& alo = aux_direct ? dlo : lo;
    const std::vector<FT>& ahi = aux_direct ? dhi : hi;
    // Tangent planes: t <= T_j(a, b) (upper), t >= B_j(a, b) (lower).
    std::vector<internal::Affine_2<FT>> upper{{U, FT(0), FT(0)}}, lower{{FT(-L), FT(0), FT(0)}};
    for (int j = 0; j < 3; ++j) {
      const FT kappa = dot(nj[j], n), alpha = dot(nj[j], E1), beta = dot(nj[j], E2);
      const FT k0 = dot(nj[j], sub3(q0, q[tri[j]]));
      const FT gm = alo[4 + j], gp = ahi[4 + j];
      // psi = k0 + alpha a + beta b + kappa t in [gm, gp]
      const auto bound_from = [&](const FT& gval) {  // t = (gval - k0 - alpha a - beta b) / kappa
        return internal::Affine_2<FT>{Tr::quotient(FT(gval - k0), kappa), Tr::quotient(FT(-alpha), kappa),
                                      Tr::quotient(FT(-beta), kappa)};
      };
      const auto negate = [](internal::Affine_2<FT> a) {
        return internal::Affine_2<FT>{FT(-a.tau), FT(-a.rho), FT(-a.sigma)};
      };
      if (certainly_positive(kappa)) {
        upper.push_back(bound_from(gp));
        lower.push_back(negate(bound_from(gm)));
      } else if (certainly_negative(kappa)) {
        upper.push_back(bound_from(gm));
        lower.push_back(negate(bound_from(gp)));
      }
    }
    const FT amin = alo[1], bmin = alo[2], s = FT(FT(1) - alo[3]);
    const double tol = 1e-9 * (1 + std::abs(internal::coordinate_to_double(s)));
    FT tu = U, tl = FT(-L);
    if (!internal::tent_maximum<FT, Tr>(upper, amin, bmin, s, tol, tu)) tu = U;
    if (!internal::tent_maximum<FT, Tr>(lower, amin, bmin, s, tol, tl)) tl = FT(-L);
    r.tangent_plane[g] = make_bound(internal::max_of(L, FT(-tl)), internal::min_of(U, tu), length);
    if (bounds_.thesis_estimate) r.thesis_estimate[g] = thesis(q0, q1, q2, nj, L, U, len);
  }

  // Distances t |n| in double, widened by 2^-50 relative (|n| and the
  // product are rounded).
  // Universal ranges of the 12 box-spline functions over the triangle,
  // computed once per number type and depth (4^depth Bezier nets).
  static std::array<std::pair<FT, FT>, 12> universal_ranges(unsigned depth, const FT& one_24, const FT& one_16) {
    static std::mutex mutex;
    static std::map<unsigned, std::array<std::pair<FT, FT>, 12>> cache;
    const std::lock_guard<std::mutex> lock(mutex);
    const auto it = cache.find(depth);
    if (it != cache.end()) return it->second;
    std::vector<FT> identity(144, FT(0));
    for (int i = 0; i < 12; ++i) identity[i * 12 + i] = FT(1);
    std::vector<FT> lo(12), hi(12);
    std::vector<bool> have(12, false);
    internal::regular_net_ranges(identity, 12, depth, one_24, one_16, lo, hi, have);
    std::array<std::pair<FT, FT>, 12> r;
    for (int i = 0; i < 12; ++i) r[i] = {lo[i], hi[i]};
    return cache.emplace(depth, r).first->second;
  }

  // Lower and upper bound of |n| = sqrt(n . n), rounded outward (sqrt is
  // correctly rounded, so one step out bounds it): from the ends of n . n,
  // not from an approximation of it, so an interval n . n as wide as its
  // value (a thin face) still gives bounds.
  struct Length_bounds {
    double lo, hi;
  };
  static Length_bounds length_bounds(const FT& nn) {
    const double lo = internal::lower_double(nn), hi = internal::upper_double(nn);
    return {lo > 0 ? std::nextafter(std::sqrt(lo), 0.0) : 0.0, std::nextafter(std::sqrt(hi), INFINITY)};
  }

  // The heights [lo, hi] as signed distances t |n|, rounded outward (a
  // product rounded to nearest is within half an ulp, so one step out bounds
  // it; for a negative height the larger length gives the lower distance).
  static Loop_face_bound<FT> make_bound(const FT& lo, const FT& hi, const Length_bounds& len) {
    Loop_face_bound<FT> b{lo, hi, 0, 0};
    const double l = internal::lower_double(lo), u = internal::upper_double(hi);
    b.lower_distance = std::nextafter(l * (l >= 0 ? len.lo : len.hi), -INFINITY);
    b.upper_distance = std::nextafter(u * (u >= 0 ? len.hi : len.lo), INFINITY);
    return b;
  }

  // The thesis' construction in double (eqs. 5.11-5.14 as printed): common
  // angle phi = min theta_j, planes through q_j tilted away from the centre,
  // cut by the basis-range slab; reflected below.
  static std::pair<double, double> thesis(const P3& q0f, const P3& q1f, const P3& q2f, const std::array<P3, 3>& njf,
                                          const FT& L, const FT& U, double len) {
    using D3 = std::array<double, 3>;
    const auto d3 = [](const P3& a) -> D3 {
      return {internal::coordinate_to_double(a.x), internal::coordinate_to_double(a.y), internal::coordinate_to_double(a.z)};
    };
    const auto sub = [](D3 a, D3 b) -> D3 { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    const auto dt = [](D3 a, D3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    const auto cr = [](D3 a, D3 b) -> D3 {
      return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    const auto unit = [&](D3 a) -> D3 {
      const double l = std::sqrt(dt(a, a));
      return l > 0 ? D3{a[0] / l, a[1] / l, a[2] / l} : a;
    };
    const D3 qs[3] = {d3(q0f), d3(q1f), d3(q2f)};
    const D3 E1 = sub(qs[1], qs[0]), E2 = sub(qs[2], qs[0]);
    const D3 nh = unit(cr(E1, E2));
    double phi = 1;
    for (const P3& v : njf) phi = std::min(phi, dt(nh, unit(d3(v))));
    phi = std::clamp(phi, -1.0, 1.0);
    const double tan_a = std::sqrt(std::max(0.0, 1 - phi * phi)) / std::max(phi, 1e-300);
    const D3 c = {(qs[0][0] + qs[1][0] + qs[2][0]) / 3, (qs[0][1] + qs[1][1] + qs[2][1]) / 3,
                  (qs[0][2] + qs[1][2] + qs[2][2]) / 3};
    const double Ud = internal::upper_double(U) * len, Ld = internal::lower_double(L) * len;
    std::vector<internal::Affine_2<double>> up{{Ud, 0, 0}}, dn{{-Ld, 0, 0}};
    for (int j = 0; j < 3; ++j) {
      D3 d = sub(c, qs[j]);
      const double along = dt(d, nh);
      d = unit(D3{d[0] - along * nh[0], d[1] - along * nh[1], d[2] - along * nh[2]});
      // height (distance) of plane j over q0 + a E1 + b E2: tan_a d . (x - q_j)
      const internal::Affine_2<double> h{tan_a * dt(d, sub(qs[0], qs[j])), tan_a * dt(d, E1), tan_a * dt(d, E2)};
      up.push_back(h);
      dn.push_back(h);  // reflected: -t <= h
    }
    double tu = Ud, tl = -Ld;
    if (!internal::tent_maximum<double, Loop_number_traits<double>>(up, 0.0, 0.0, 1.0, 1e-12, tu)) tu = Ud;
    if (!internal::tent_maximum<double, Loop_number_traits<double>>(dn, 0.0, 0.0, 1.0, 1e-12, tl)) tl = -Ld;
    return {std::max(Ld, -tl), std::min(Ud, tu)};
  }

  Loop_options options_;
  Loop_bound_options bounds_;
  K kernel_;
  FT one_24_, one_16_;
  std::array<std::pair<FT, FT>, 12> universal_;
};

/// Convenience: the limit mesh of `control` at `level` with its error bounds
/// under kernel K (default: Default_loop_kernel of the point type).
template <class K = void, class P>
auto loop_limit_mesh_bounds(const Triangle_mesh<P>& control, unsigned level, const Loop_options& options = {},
                            const Loop_bound_options& bounds = {}) {
  using Kernel = std::conditional_t<std::is_void_v<K>, typename Default_loop_kernel<P>::type, K>;
  return Loop_error_bounds<Kernel>(options, bounds).compute(control, level);
}

}  // namespace relgeo
