// relgeo/kernel/filtered_exact_kernel.h — exact predicates at floating-point speed.
#pragma once

#include <array>
#include <cmath>
#include <utility>
#include <optional>
#include <string>

#include "relgeo/core/fp_environment.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/kernel/internal/exact_dyadic.h"
#include "relgeo/kernel/internal/filtered_predicate.h"
#include "relgeo/kernel/internal/expansion_orientation.h"
#include "relgeo/kernel/internal/expansion_orientation_3.h"
#include "relgeo/kernel/internal/kernel_base.h"
#include "relgeo/kernel/internal/implicit_staged.h"
#include "relgeo/kernel/internal/semi_static_filter.h"

namespace relgeo {

/// \brief Double-coordinate kernel with exact predicates (like CGAL's Epick):
/// each predicate tries
///  1. the semi-static epsilon test of Failsafe_kernel<double> (valid in
///     every floating-point environment; the later stages run in the default
///     one, established for them when the caller changed it),
///  2. when every coordinate is 0 or of moderate magnitude, the exact sign in
///     floating-point expansions specialised for the predicate, which always
///     decides: orientation_2 in [2^-400, 2^500] as a sum of 16 doubles
///     (internal/expansion_orientation.h), orientation_3 in [2^-250, 2^300]
///     (internal/expansion_orientation_3.h: the determinant of the rounded
///     differences exactly, plus their tails to first order under a proven
///     bound, else everything exactly),
///  3. otherwise the generic filtered predicate (internal/filtered_predicate.h)
///     on the formula of internal/determinants.h: intervals, then generic
///     expansions on the coordinates scaled by a power of two (exact when
///     the coordinates' bits span at most 687 positions in 3D), then GMP
///     integers,
/// and returns the first definite answer, which is always the exact sign.
/// Predicates on implicit points go the same way (internal/implicit_staged.h).
/// Constructions are plain double.
///
/// The only `uncertain` answer is for NaN or infinite coordinates, whose sign
/// is undefined.
class Filtered_exact_kernel : public internal::Kernel_base<Filtered_exact_kernel, double>,
                              public internal::Implicit_kernel_base<internal::Staged_implicit_policy> {
 public:
  static std::string name() { return "filtered"; }
  static constexpr double unit_roundoff = unit_roundoff_v<double>;  // of constructions
  static constexpr bool is_certified = true;
  static constexpr bool has_exact_predicates = true;
  static constexpr bool has_exact_constructions = false;
  static constexpr std::optional<double> orientation_2_error_bound = 0.0;
  static constexpr std::optional<double> orientation_3_error_bound = 0.0;

  static FT from_double(double v) { return v; }
  static Certified_sign compare_ft(const FT& a, const FT& b) {
    return internal::compare_certified(a, b);
  }
  /// The exact rational coordinates of an implicit point (GMP, no filter:
  /// for converting results, e.g. to Exact_kernel's points, not for
  /// predicates).
  static std::array<mpq_class, 3> exact_coordinates(const Implicit_point_3& p) {
    return internal::Staged_implicit_policy::exact_coordinates(p);
  }

  /// The sign and the stage that decided it (for statistics and tests).
  static std::pair<Certified_sign, Filter_stage> orientation_2_with_stage(const Point_2& p,
                                                                         const Point_2& q,
                                                                         const Point_2& r) {
    const Certified_sign s = internal::filtered_orientation_2<double>(p.x, p.y, q.x, q.y, r.x, r.y);
    if (is_certain(s)) return {s, Filter_stage::semi_static};
    return after_semi_static_2(p, q, r);
  }
  static std::pair<Certified_sign, Filter_stage> orientation_3_with_stage(const Point_3& p,
                                                                         const Point_3& q,
                                                                         const Point_3& r,
                                                                         const Point_3& s) {
    const Certified_sign o = internal::filtered_orientation_3<double>(
        p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z, s.x, s.y, s.z);
    if (is_certain(o)) return {o, Filter_stage::semi_static};
    return after_semi_static_3(p, q, r, s);
  }

  // The fast path branches once, on whether the epsilon test decided (well
  // predicted), never on the sign itself (unpredictable on random input).
  struct Orientation_2 {
    Certified_sign operator()(const Point_2& p, const Point_2& q, const Point_2& r) const {
      const internal::Epsilon_test t =
          internal::orientation_2_epsilon_test<double>(p.x, p.y, q.x, q.y, r.x, r.y);
      if (t.decided) [[likely]]
        return t.sign;
      return after_semi_static_2(p, q, r).first;
    }
  };
  struct Orientation_3 {
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r,
                              const Point_3& s) const {
      const internal::Epsilon_test t = internal::orientation_3_epsilon_test<double>(
          p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z, s.x, s.y, s.z);
      if (t.decided) [[likely]]
        return t.sign;
      return after_semi_static_3(p, q, r, s).first;
    }
  };
  /// Orientation_3 of several points s against one plane (p, q, r): the
  /// filter's minors of (p, q, r) computed once, the same answers (a
  /// triangle's three corners against another's plane).
  class Orientation_3_against_plane {
   public:
    Orientation_3_against_plane(const Point_3& p, const Point_3& q, const Point_3& r)
        : p_(p), q_(q), r_(r), test_(p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z) {}
    Certified_sign operator()(const Point_3& s) const {
      const internal::Epsilon_test t = test_(s.x, s.y, s.z);
      if (t.decided) [[likely]]
        return t.sign;
      return after_semi_static_3(p_, q_, r_, s).first;
    }

   private:
    Point_3 p_, q_, r_;
    internal::Orientation_3_plane_epsilon_test<double> test_;
  };
  Orientation_2 orientation_2_object() const { return {}; }
  Orientation_3 orientation_3_object() const { return {}; }
 private:
  // The later stages, out of line so the inlined fast path stays small. They
  // rely on round to nearest without FTZ/DAZ (error-free transformations,
  // outward rounding, decoding doubles), so they run in the default
  // floating-point environment whatever the caller set (core/fp_environment.h).
  [[gnu::noinline]] static std::pair<Certified_sign, Filter_stage> after_semi_static_2(
      const Point_2& p, const Point_2& q, const Point_2& r) {
    if (!all_finite(p.x, p.y, q.x, q.y, r.x, r.y))
      return {Certified_sign::uncertain, Filter_stage::undecidable};
    if (internal::exactly_degenerate_2(p.x, p.y, q.x, q.y, r.x, r.y))
      return {Certified_sign::zero, Filter_stage::semi_static};
    const Default_fp_environment environment;
    // In its range the expansion always decides, and faster than intervals
    // that may not (56 -> 41 ns per call on near-collinear input).
    if (const auto e = internal::expansion_orientation_2(p.x, p.y, q.x, q.y, r.x, r.y))
      return {*e, Filter_stage::expansion};
    const std::array<double, 6> c{p.x, p.y, q.x, q.y, r.x, r.y};
    return internal::filtered_exact_sign(c, 2, true, internal::orientation_2_formula(c));
  }
  [[gnu::noinline]] static std::pair<Certified_sign, Filter_stage> after_semi_static_3(
      const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s) {
    if (!all_finite(p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z, s.x, s.y, s.z))
      return {Certified_sign::uncertain, Filter_stage::undecidable};
    if (internal::exactly_degenerate_3(p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z, s.x, s.y, s.z))
      return {Certified_sign::zero, Filter_stage::semi_static};
    const Default_fp_environment environment;
    const std::array<double, 12> c{p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z, s.x, s.y, s.z};
    // As in 2D: in its range the expansion always decides, faster than
    // intervals (which decide 31% of near-coplanar input) and GMP.
    if (const auto e = internal::expansion_orientation_3(c)) return {*e, Filter_stage::expansion};
    return internal::filtered_exact_sign(c, 3, true, internal::orientation_3_formula(c));
  }
};

}  // namespace relgeo
