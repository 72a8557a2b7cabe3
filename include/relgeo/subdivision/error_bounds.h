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
#include <utility>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/errors.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/core/rounding.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/box_spline.h"
#include "relgeo/subdivision/internal/bound_ranges.h"
#include "relgeo/subdivision/internal/local_patch.h"
#include "relgeo/subdivision/internal/point_algebra.h"
#include "relgeo/subdivision/internal/tent.h"
#include "relgeo/subdivision/limit_evaluation.h"
#include "relgeo/subdivision/loop_masks.h"
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


/// \brief The limit mesh at a level with, per face, enclosures of the limit
/// surface over it (see the file comment for the methods).
template <ConstructionKernel_3 K>
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
    const Point& qp = limit_mesh.vertices[limit_mesh.faces[f][0]];
    const Point_3<FT> q{A::x(qp), A::y(qp), A::z(qp)};
    const Point_3<FT>& n = normal[f];
    return Loop_kernel_number_traits<K>::quotient(internal::point_dot(n, internal::point_difference(x, q)),
                                                  internal::point_dot(n, n));
  }
};

/// \brief Computes limit meshes with per-face error bounds under kernel K.
///
/// compute(control, k) refines the control mesh k times, takes the limit
/// mesh, and bounds the limit surface over each of its faces (local patches
/// of the refined mesh). Requirements and errors as Loop_subdivider; also
/// Error (computation_failure) when a face normal overflows the number type.
/// Complexity: O(F) with a per-face constant: regular faces reuse the
/// universal ranges of the 12 box-spline functions (computed once, by the
/// constructor), irregular faces (one per face around an irregular vertex)
/// subdivide locally (~3 irregular_depth regular sub-patches).
/// Thread safety: the object is immutable after construction and compute()
/// keeps its scratch on its own stack: one object can serve many threads.
template <ConstructionKernel_3 K>
class Loop_error_bounds {
 public:
  using FT = typename K::FT;
  using Point = typename K::Point_3;
  using Mesh = Triangle_mesh<Point>;
  using Tr = Loop_kernel_number_traits<K>;

  /// K is a type argument only: the bounds use its number type, never a
  /// kernel object.
  explicit Loop_error_bounds(const Loop_options& options = {}, const Loop_bound_options& bounds = {})
      : options_(options), bounds_(bounds), one_24_(fraction(1, 24)), one_16_(fraction(1, 16)),
        universal_(universal_ranges(bounds.universal_depth, one_24_, one_16_)) {}

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
    Loop_subdivider<K> sub(options_);
    r.refined = sub.refine(control, level);
    r.limit_mesh = sub.limit_mesh(control, level);
    const Loop_limit_surface<K> surface(r.refined, options_);
    Loop_weights<K> w(options_);
    Index max_valence = 6;
    for (Index v = 0; v < r.refined.vertices.size(); ++v) max_valence = std::max(max_valence, surface.topology().valence(v));
    w.reserve(max_valence + 1);
    const std::size_t nf = r.refined.faces.size();
    r.normal.resize(nf), r.normal_length.resize(nf), r.degenerate.assign(nf, 0), r.patch_kind.resize(nf);
    r.basis_range.resize(nf), r.tangent_plane.resize(nf);
    if (bounds_.direct) r.direct.resize(nf);
    if (bounds_.thesis_estimate) r.thesis_estimate.resize(nf);
    std::vector<P3> q(r.limit_mesh.vertices.size());
    for (std::size_t v = 0; v < q.size(); ++v) q[v] = {A::x(r.limit_mesh.vertices[v]), A::y(r.limit_mesh.vertices[v]), A::z(r.limit_mesh.vertices[v])};
    for (Index g = 0; g < nf; ++g) face_bounds(surface, w, q, g, r);
    return r;
  }

 private:
  using A = internal::Point_access<Point>;
  using P3 = Point_3<FT>;

  // phi(x) = dir . x + offset
  struct Functional {
    P3 dir;
    FT offset;
    FT operator()(const P3& x) const { return FT(internal::point_dot(dir, x) + offset); }
  };
  // Lower and upper bound of |n| (see length_bounds).
  struct Length_bounds {
    double lo, hi;
  };
  // Face g of the limit mesh: corners q_j, E1 = q1 - q0, E2 = q2 - q0,
  // n = E1 x E2, the exact limit normals n_j at the corners.
  struct Face_frame {
    P3 q[3], E1, E2, n;
    FT nn;
    Length_bounds length;
    std::array<P3, 3> nj;
  };
  // The control points the limit over a face depends on, with the ranges of
  // their nodal functions over the face; for an irregular face also its
  // local patch (geometry not filled in).
  struct Face_control {
    std::vector<P3> points;
    std::vector<FT> bmin, bmax;
    bool regular = false;
    internal::Loop_local_patch<FT> local;
  };

  static P3 divide(const P3& a, const FT& s) { return {Tr::quotient(a.x, s), Tr::quotient(a.y, s), Tr::quotient(a.z, s)}; }

  void face_bounds(const Loop_limit_surface<K>& surface, Loop_weights<K>& w, const std::vector<P3>& q, Index g,
                   Loop_limit_mesh_bounds<K>& r) const {
    const Triangle& tri = r.refined.faces[g];
    r.patch_kind[g] = surface.patch_kind(g);
    Face_frame fr;
    if (!face_frame(q, tri, g, r, fr)) return;
    for (int j = 0; j < 3; ++j) {
      const auto [s1, s2] = tangent_stencils(surface.topology(), surface.features(), w, tri[j], 3 * g + Index(j));
      fr.nj[j] = internal::point_cross(apply_stencil(s1, surface.control_points()), apply_stencil(s2, surface.control_points()));
    }
    const std::vector<Functional> phi = functionals(fr);
    const Face_control control = face_control(surface, w, g);
    std::vector<FT> lo, hi;
    nodal_ranges(phi, control, lo, hi);
    const FT L = lo[0], U = hi[0];
    r.basis_range[g] = make_bound(L, U, fr.length);
    const bool aux_direct = bounds_.tangent_ranges == Loop_bound_options::Tangent_ranges::direct;
    std::vector<FT> dlo, dhi;
    if (bounds_.direct || aux_direct) {
      direct_ranges(phi, control, w, dlo, dhi);
      if (bounds_.direct) r.direct[g] = make_bound(dlo[0], dhi[0], fr.length);
    }
    r.tangent_plane[g] = tangent_plane_bound(fr, L, U, aux_direct ? dlo : lo, aux_direct ? dhi : hi);
    if (bounds_.thesis_estimate) r.thesis_estimate[g] = thesis(fr, L, U, r.normal_length[g]);
  }

  // The face's corners, edges and normal; false (and marked) when degenerate.
  static bool face_frame(const std::vector<P3>& q, const Triangle& tri, Index g, Loop_limit_mesh_bounds<K>& r,
                         Face_frame& fr) {
    for (int j = 0; j < 3; ++j) fr.q[j] = q[tri[j]];
    fr.E1 = internal::point_difference(fr.q[1], fr.q[0]), fr.E2 = internal::point_difference(fr.q[2], fr.q[0]);
    fr.n = internal::point_cross(fr.E1, fr.E2);
    fr.nn = internal::point_dot(fr.n, fr.n);
    // Finite input can overflow here in floating point (|n| ~ |E|^2): refuse
    // rather than return NaN bounds (test/data/bad/coordinates_1e300.off).
    if (!is_finite_number(fr.nn))
      throw Error(Error_code::computation_failure, "Loop error bounds: the normal of limit-mesh face " +
                                                       std::to_string(g) +
                                                       " overflows (coordinates too large for the number type)");
    r.normal[g] = fr.n;
    const double len = std::sqrt(nearest_double(fr.nn));
    r.normal_length[g] = len;
    const Certified_sign s = certified_sign(fr.nn);
    if (!(certainly(s, Certified_sign::positive) || certainly(s, Certified_sign::negative)) || !(len > 0)) {
      r.degenerate[g] = 1;
      return false;
    }
    fr.length = length_bounds(fr.nn);
    return true;
  }

  // The functionals: t, a, b, c = 1 - a - b, psi_j = n_j . (x - q_j).
  static std::vector<Functional> functionals(const Face_frame& fr) {
    std::vector<Functional> phi;
    const auto affine = [&](const P3& dir) { return Functional{dir, FT(-internal::point_dot(dir, fr.q[0]))}; };
    phi.push_back(affine(divide(fr.n, fr.nn)));
    phi.push_back(affine(divide(internal::point_cross(fr.E2, fr.n), fr.nn)));
    phi.push_back(affine(divide(internal::point_cross(fr.n, fr.E1), fr.nn)));
    phi.push_back(Functional{internal::point_scale(FT(-1), internal::point_difference(phi[1].dir, internal::point_scale(FT(-1), phi[2].dir))),
                             FT(FT(FT(1) - phi[1].offset) - phi[2].offset)});
    for (int j = 0; j < 3; ++j) phi.push_back(Functional{fr.nj[j], FT(-internal::point_dot(fr.nj[j], fr.q[j]))});
    return phi;
  }

  // Regular faces: the 12 control slots with the universal nodal ranges.
  // Irregular faces: the local patch's vertices with the ranges of their
  // Dirac nets (one unit vector per local vertex) under local subdivision.
  Face_control face_control(const Loop_limit_surface<K>& surface, const Loop_weights<K>& w, Index g) const {
    Face_control c;
    if (const auto* slots = surface.patch_slots(g)) {
      c.regular = true;
      for (int i = 0; i < 12; ++i) {
        c.points.push_back(surface.slot_point((*slots)[i]));
        c.bmin.push_back(universal_[i].first), c.bmax.push_back(universal_[i].second);
      }
      return c;
    }
    std::vector<Index> ids;
    c.local = internal::extract_local_patch<FT>(surface.topology(), surface.rule_data(), g, 1,
                                                [](Index, FT* o) { *o = FT(0); }, &ids);
    const std::size_t nloc = ids.size();
    internal::Loop_local_patch<FT> dirac = c.local;
    dirac.dim = nloc;
    dirac.values.assign(nloc * nloc, FT(0));
    for (std::size_t i = 0; i < nloc; ++i) dirac.values[i * nloc + i] = FT(1);
    c.bmin.resize(nloc), c.bmax.resize(nloc);
    std::vector<bool> have(nloc, false);
    internal::local_patch_ranges<K>(dirac, w, bounds_.irregular_depth, bounds_.regular_depth, one_24_, one_16_, c.bmin,
                                    c.bmax, have);
    for (std::size_t i = 0; i < nloc; ++i) c.points.push_back(surface.control_points()[ids[i]]);
    return c;
  }

  // eq. 5.7: the range of each functional over the control points and
  // their nodal ranges.
  static void nodal_ranges(const std::vector<Functional>& phi, const Face_control& c, std::vector<FT>& lo,
                           std::vector<FT>& hi) {
    const std::size_t nphi = phi.size();
    lo.resize(nphi), hi.resize(nphi);
    for (std::size_t i = 0; i < c.points.size(); ++i)
      for (std::size_t k = 0; k < nphi; ++k) {
        const FT v = phi[k](c.points[i]);
        const FT x = FT(v * c.bmin[i]), y = FT(v * c.bmax[i]);
        const FT mn = internal::min_of(x, y), mx = internal::max_of(x, y);
        lo[k] = i == 0 ? mn : FT(lo[k] + mn);
        hi[k] = i == 0 ? mx : FT(hi[k] + mx);
      }
  }

  // Direct hulls of the functionals themselves (Bezier hulls of regular
  // patches, local subdivision of irregular ones).
  void direct_ranges(const std::vector<Functional>& phi, const Face_control& c, const Loop_weights<K>& w,
                     std::vector<FT>& dlo, std::vector<FT>& dhi) const {
    const std::size_t nphi = phi.size();
    dlo.resize(nphi), dhi.resize(nphi);
    std::vector<bool> have(nphi, false);
    std::vector<FT> values(c.points.size() * nphi);
    for (std::size_t i = 0; i < c.points.size(); ++i)
      for (std::size_t k = 0; k < nphi; ++k) values[i * nphi + k] = phi[k](c.points[i]);
    if (c.regular) {
      internal::regular_net_ranges(values, nphi, bounds_.regular_depth, one_24_, one_16_, dlo, dhi, have);
      return;
    }
    internal::Loop_local_patch<FT> hp = c.local;
    hp.dim = nphi;
    hp.values = std::move(values);
    internal::local_patch_ranges<K>(hp, w, bounds_.irregular_depth, bounds_.regular_depth, one_24_, one_16_, dlo, dhi, have);
  }

  // Tangent planes: t <= T_j(a, b) (upper), t >= B_j(a, b) (lower), from the
  // ranges [gm, gp] of psi_j = k0 + alpha a + beta b + kappa t; the tents'
  // maxima over D' cut by the slab [L, U].
  Loop_face_bound<FT> tangent_plane_bound(const Face_frame& fr, const FT& L, const FT& U, const std::vector<FT>& alo,
                                          const std::vector<FT>& ahi) const {
    std::vector<internal::Affine_2<FT>> upper{{U, FT(0), FT(0)}}, lower{{FT(-L), FT(0), FT(0)}};
    for (int j = 0; j < 3; ++j) {
      const P3& nj = fr.nj[j];
      const FT kappa = internal::point_dot(nj, fr.n), alpha = internal::point_dot(nj, fr.E1),
               beta = internal::point_dot(nj, fr.E2);
      const FT k0 = internal::point_dot(nj, internal::point_difference(fr.q[0], fr.q[j]));
      const FT &gm = alo[4 + j], &gp = ahi[4 + j];
      const auto bound_from = [&](const FT& gval) {  // t = (gval - k0 - alpha a - beta b) / kappa
        return internal::Affine_2<FT>{Tr::quotient(FT(gval - k0), kappa), Tr::quotient(FT(-alpha), kappa),
                                      Tr::quotient(FT(-beta), kappa)};
      };
      const auto negate = [](internal::Affine_2<FT> a) {
        return internal::Affine_2<FT>{FT(-a.tau), FT(-a.rho), FT(-a.sigma)};
      };
      const Certified_sign ks = certified_sign(kappa);
      if (certainly(ks, Certified_sign::positive)) {
        upper.push_back(bound_from(gp));
        lower.push_back(negate(bound_from(gm)));
      } else if (certainly(ks, Certified_sign::negative)) {
        upper.push_back(bound_from(gm));
        lower.push_back(negate(bound_from(gp)));
      }
    }
    const FT amin = alo[1], bmin = alo[2], s = FT(FT(1) - alo[3]);
    const double tol = 1e-9 * (1 + std::abs(nearest_double(s)));
    FT tu = U, tl = FT(-L);
    if (!internal::tent_maximum<FT, Tr>(upper, amin, bmin, s, tol, tu)) tu = U;
    if (!internal::tent_maximum<FT, Tr>(lower, amin, bmin, s, tol, tl)) tl = FT(-L);
    return make_bound(internal::max_of(L, FT(-tl)), internal::min_of(U, tu), fr.length);
  }

  // p / q in FT, in the default floating-point environment (as compute()).
  static FT fraction(long p, long q) {
    const Default_fp_environment environment;
    return Tr::rational(p, q);
  }

  // Universal ranges of the 12 box-spline functions over the triangle
  // (4^depth Bezier nets), computed once per object by the constructor.
  static std::array<std::pair<FT, FT>, 12> universal_ranges(unsigned depth, const FT& one_24, const FT& one_16) {
    const Default_fp_environment environment;  // rounded outward in hardware, whatever the caller set
    std::vector<FT> identity(144, FT(0));
    for (int i = 0; i < 12; ++i) identity[i * 12 + i] = FT(1);
    std::vector<FT> lo(12), hi(12);
    std::vector<bool> have(12, false);
    internal::regular_net_ranges(identity, 12, depth, one_24, one_16, lo, hi, have);
    std::array<std::pair<FT, FT>, 12> r;
    for (int i = 0; i < 12; ++i) r[i] = {lo[i], hi[i]};
    return r;
  }

  // Lower and upper bound of |n| = sqrt(n . n), rounded outward (sqrt is
  // correctly rounded, so one step out bounds it): from the ends of n . n,
  // not from an approximation of it, so an interval n . n as wide as its
  // value (a thin face) still gives bounds.
  static Length_bounds length_bounds(const FT& nn) { return {sqrt_down(lower_double(nn)), sqrt_up(upper_double(nn))}; }

  // The heights [lo, hi] as signed distances t |n|, rounded outward (a
  // product rounded to nearest is within half an ulp, so one step out bounds
  // it; for a negative height the larger length gives the lower distance).
  // A zero height is at distance zero whatever |n|: an exact |n| beyond
  // double's range has the upper length +inf, and 0 * inf is NaN.
  static Loop_face_bound<FT> make_bound(const FT& lo, const FT& hi, const Length_bounds& len) {
    Loop_face_bound<FT> b{lo, hi, 0, 0};
    const double l = lower_double(lo), u = upper_double(hi);
    const auto distance = [](double t, double length) { return t == 0 ? 0.0 : t * length; };
    b.lower_distance = next_down(distance(l, l >= 0 ? len.lo : len.hi));
    b.upper_distance = next_up(distance(u, u >= 0 ? len.hi : len.lo));
    return b;
  }

  // The thesis' construction in double (eqs. 5.11-5.14 as printed): common
  // angle phi = min theta_j, planes through q_j tilted away from the centre,
  // cut by the basis-range slab; reflected below.
  static std::pair<double, double> thesis(const Face_frame& fr, const FT& L, const FT& U, double len) {
    using D3 = Point_3<double>;
    using internal::point_cross, internal::point_difference, internal::point_dot;
    const auto d3 = [](const P3& a) { return D3{nearest_double(a.x), nearest_double(a.y), nearest_double(a.z)}; };
    const auto unit = [](const D3& a) {
      const double l = std::sqrt(point_dot(a, a));
      return l > 0 ? D3{a.x / l, a.y / l, a.z / l} : a;
    };
    const D3 qs[3] = {d3(fr.q[0]), d3(fr.q[1]), d3(fr.q[2])};
    const D3 E1 = point_difference(qs[1], qs[0]), E2 = point_difference(qs[2], qs[0]);
    const D3 nh = unit(point_cross(E1, E2));
    double phi = 1;
    for (const P3& v : fr.nj) phi = std::min(phi, point_dot(nh, unit(d3(v))));
    phi = std::clamp(phi, -1.0, 1.0);
    const double tan_a = std::sqrt(std::max(0.0, 1 - phi * phi)) / std::max(phi, 1e-300);
    const D3 c = {(qs[0].x + qs[1].x + qs[2].x) / 3, (qs[0].y + qs[1].y + qs[2].y) / 3, (qs[0].z + qs[1].z + qs[2].z) / 3};
    const double Ud = upper_double(U) * len, Ld = lower_double(L) * len;
    std::vector<internal::Affine_2<double>> up{{Ud, 0, 0}}, dn{{-Ld, 0, 0}};
    for (int j = 0; j < 3; ++j) {
      D3 d = point_difference(c, qs[j]);
      const double along = point_dot(d, nh);
      d = unit(D3{d.x - along * nh.x, d.y - along * nh.y, d.z - along * nh.z});
      // height (distance) of plane j over q0 + a E1 + b E2: tan_a d . (x - q_j)
      const internal::Affine_2<double> h{tan_a * point_dot(d, point_difference(qs[0], qs[j])), tan_a * point_dot(d, E1),
                                         tan_a * point_dot(d, E2)};
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
  FT one_24_, one_16_;
  std::array<std::pair<FT, FT>, 12> universal_;
};

/// Convenience: the limit mesh of `control` at `level` with its error bounds
/// under kernel K (default: Kernel_for_number of the coordinate type).
template <KernelOrDefault K = void, class P>
auto loop_limit_mesh_bounds(const Triangle_mesh<P>& control, unsigned level, const Loop_options& options = {},
                            const Loop_bound_options& bounds = {}) {
  using Kernel = Kernel_or_default<K, Kernel_for_number, P>;
  return Loop_error_bounds<Kernel>(options, bounds).compute(control, level);
}

}  // namespace relgeo
