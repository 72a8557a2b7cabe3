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

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/box_spline.h"
#include "relgeo/subdivision/internal/exact_limit.h"
#include "relgeo/subdivision/internal/local_patch.h"
#include "relgeo/subdivision/internal/loop_rules.h"
#include "relgeo/subdivision/internal/patch_classification.h"
#include "relgeo/subdivision/internal/point_algebra.h"
#include "relgeo/subdivision/internal/surface_parameters.h"
#include "relgeo/subdivision/loop_features.h"
#include "relgeo/subdivision/loop_masks.h"
#include "relgeo/subdivision/loop_patch_kind.h"
#include "relgeo/subdivision/loop_subdivision.h"
#include "relgeo/subdivision/loop_weights.h"

namespace relgeo {

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
template <ConstructionKernel_3 K>
class Loop_limit_surface {
 public:
  using FT = typename K::FT;
  using Point = typename K::Point_3;
  using Mesh = Triangle_mesh<Point>;
  using Tr = Loop_kernel_number_traits<K>;

  /// More local levels than any double parameter needs (2^-1074 is the
  /// smallest positive double); exceeding it is reported as a failure.
  static constexpr unsigned max_levels = 1200;

  /// K is a type argument only: evaluation uses its number type, never a
  /// kernel object.
  explicit Loop_limit_surface(const Mesh& control, const Loop_options& options = {})
      : weights_(options) {
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
    Point_3<FT> ghost;
    return internal::slot_point(s, points_, ghost);
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
    return control_net_unchecked(f);
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
      const auto j = evaluate_quartic_bezier_jet(loop_patch_to_bezier(control_net_unchecked(f), one_24_), FT(u), FT(v));
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
  using Patch = internal::Loop_local_patch<FT>;
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

  std::array<Point_3<FT>, 12> control_net_unchecked(Index f) const {
    std::array<Point_3<FT>, 12> p;
    const auto& s = slots_[slot_index_[f]];
    for (int i = 0; i < 12; ++i) p[i] = slot_point(s[i]);
    return p;
  }
  // sum_i b_i(u, v) p_i with the 12 box-spline values (one pass, no Bezier net).
  Point_3<FT> evaluate_regular(Index f, const FT& u, const FT& v) const {
    const FT w = FT(FT(FT(1) - u) - v);
    const std::array<FT, 12> b = loop_patch_basis_times_24(w, u, v);
    const auto& s = slots_[slot_index_[f]];
    FT x(0), y(0), z(0);
    Point_3<FT> ghost;
    for (int i = 0; i < 12; ++i) {
      const Point_3<FT>& a = internal::slot_point(s[i], points_, ghost);
      x = FT(x + FT(b[i] * a.x)), y = FT(y + FT(b[i] * a.y)), z = FT(z + FT(b[i] * a.z));
    }
    return Point_3<FT>{FT(x * one_24_), FT(y * one_24_), FT(z * one_24_)};
  }

  static Loop_limit_jet<FT> jet(const Point_3<FT>& p, const Point_3<FT>& du, const Point_3<FT>& dv, unsigned levels) {
    Loop_limit_jet<FT> r;
    r.position = p, r.du = du, r.dv = dv, r.normal = internal::point_cross(du, dv), r.levels = levels;
    return r;
  }

  // The last irregular step of a descent: its patch's structure, its
  // corners' regularity, the child taken and the stencils of that child's
  // vertices.
  struct Step_memo {
    std::vector<Triangle> faces;
    internal::Loop_rule_data rules;
    std::array<bool, 3> corner_regular{};
    int child = -1;
    std::vector<Triangle> child_faces;
    internal::Loop_rule_data child_rules;
    internal::Stencil_list<FT> stencils;
  };
  // A descent of local subdivision towards a point: the current local patch,
  // the point's exact parameters in it, J = d(s, t) / d(u0, v0) and the memo.
  struct Descent {
    Patch patch;
    mpq_class u, v;
    FT J[2][2] = {{FT(1), FT(0)}, {FT(0), FT(1)}};
    Step_memo memo;
    bool have_memo = false;
  };

  // Local subdivision until the sub-patch holding (u, v) is regular (or
  // (u, v) is an irregular corner). Along the descent towards a smooth
  // extraordinary vertex the local patch repeats itself after one step (same
  // faces, same rule data: Stam's subdivision matrix); the last step's
  // stencils are then reused, skipping the topology, the classification and
  // the extraction.
  Loop_limit_jet<FT> irregular(Index f, double u0, double v0, bool derivatives) const {
    Descent d;
    d.patch = internal::extract_local_patch<FT>(topology_, rules_, f, 3, [&](Index v, FT* out) {
      out[0] = points_[v].x, out[1] = points_[v].y, out[2] = points_[v].z;
    });
    d.u = u0, d.v = v0;
    for (unsigned level = 0;; ++level) {
      const bool repeated = d.have_memo && d.patch.faces == d.memo.faces && d.patch.rules == d.memo.rules;
      Mesh_topology t;
      std::array<bool, 3> corner_regular;
      if (repeated) {
        corner_regular = d.memo.corner_regular;
      } else {
        t = internal::local_topology(d.patch);
        std::array<internal::Patch_slot, 12> s;
        if (internal::classify_loop_patch(t, d.patch.rules, options(), 0, &s) != Loop_patch_kind::irregular)
          return on_regular_sub_patch(d, s, derivatives, level);
        for (int k = 0; k < 3; ++k) corner_regular[k] = internal::patch_corner_is_regular(t, d.patch.rules, options(), 0, k);
      }
      const int corner = sgn(d.u) == 0 && sgn(d.v) == 0 ? 0 : d.u == 1 ? 1 : d.v == 1 ? 2 : -1;
      if (corner >= 0 && !corner_regular[corner]) {
        if (repeated) t = internal::local_topology(d.patch);
        return at_irregular_corner(d.patch, t, corner, derivatives, level);
      }
      if (level >= max_levels)
        throw Error(Error_code::computation_failure, "Loop limit surface: no regular sub-patch after " +
                                                         std::to_string(max_levels) + " levels");
      const int c = internal::descend_to_child(d.u, d.v);
      if (derivatives) internal::descend_jacobian(d.J, c);
      if (repeated && d.memo.child == c) {
        d.patch = repeat_memo(d.memo, d.patch);
        continue;
      }
      if (repeated) t = internal::local_topology(d.patch);
      refine_and_remember(d, t, corner_regular, c);
    }
  }

  // The point (and, with derivatives, the chain-ruled jet) on a regular
  // sub-patch with control slots s.
  Loop_limit_jet<FT> on_regular_sub_patch(const Descent& d, const std::array<internal::Patch_slot, 12>& s,
                                          bool derivatives, unsigned level) const {
    const std::vector<FT> values = internal::patch_net<FT>(s, 3, [&](Index x) { return d.patch.value(x); });
    std::array<Point_3<FT>, 12> net;
    for (int i = 0; i < 12; ++i) net[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
    const auto bez = loop_patch_to_bezier(net, one_24_);
    const FT us = internal::ft_from_rational<FT>(d.u), vs = internal::ft_from_rational<FT>(d.v);
    if (!derivatives) return jet(evaluate_quartic_bezier(bez, us, vs), {}, {}, level);
    const auto j = evaluate_quartic_bezier_jet(bez, us, vs);
    // [S_u0 S_v0] = [Q_s Q_t] J
    return jet(j.position, internal::point_combination(d.J[0][0], j.du, d.J[1][0], j.dv),
               internal::point_combination(d.J[0][1], j.du, d.J[1][1], j.dv), level);
  }

  // At an irregular corner itself: its exact limit position and the
  // tangent-mask normal (no parametric derivatives).
  Loop_limit_jet<FT> at_irregular_corner(const Patch& P, const Mesh_topology& t, int corner, bool derivatives,
                                         unsigned level) const {
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

  // The child patch of a repeated step: the memo's structure, its stencils
  // applied to the current values.
  static Patch repeat_memo(const Step_memo& memo, const Patch& P) {
    Patch Q;
    Q.dim = 3;
    Q.faces = memo.child_faces;
    Q.rules = memo.child_rules;
    const internal::Stencil_list<FT>& st = memo.stencils;
    Q.values.assign(st.size() * 3, FT(0));
    for (std::size_t i = 0; i < st.size(); ++i)
      for (std::size_t j = st.begin[i]; j < st.begin[i + 1]; ++j)
        for (int k = 0; k < 3; ++k)
          Q.values[i * 3 + k] = FT(Q.values[i * 3 + k] + FT(st.weights[j] * P.values[std::size_t(st.vertices[j]) * 3 + k]));
    return Q;
  }

  // One local refinement step to child c, remembered for the next level.
  void refine_and_remember(Descent& d, const Mesh_topology& t, const std::array<bool, 3>& corner_regular, int c) const {
    internal::Stencil_list<FT> st;
    auto children = internal::refine_local_patch<K>(d.patch, t, weights_, 1u << c, &st);
    Step_memo& memo = d.memo;
    memo.faces = d.patch.faces, memo.rules = d.patch.rules, memo.child = c, memo.corner_regular = corner_regular;
    memo.child_faces = children[c].faces, memo.child_rules = children[c].rules, memo.stencils = std::move(st);
    d.have_memo = true;
    d.patch = std::move(children[c]);
  }

  // Tangent-mask normal at corner `corner` of the local patch's face 0.
  Point_3<FT> corner_normal(const Patch& P, const Mesh_topology& t, int corner) const {
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
    return internal::point_cross(apply_stencil(s1, pts), apply_stencil(s2, pts));
  }

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
/// under kernel K (default: Kernel_for_number of the coordinate type). Builds a
/// Loop_limit_surface: for many queries keep one.
template <KernelOrDefault K = void, class P>
P loop_limit_point(const Triangle_mesh<P>& control, Index f, double u, double v, const Loop_options& options = {}) {
  using Kernel = Kernel_or_default<K, Kernel_for_number, P>;
  return Loop_limit_surface<Kernel>(control, options).evaluate(f, u, v);
}

}  // namespace relgeo
