// relgeo/curves/extrusion.h — certified well-formedness of extruded objects
// (thesis Sec. 3.4.1): three sufficient conditions, each a planar
// convex-hull problem solved with the caller's kernel and hull algorithm,
// each with its maximal admissible perturbation, and a verdict under a stated
// input uncertainty plus the rounding error of the computation itself.
//
// The extruded object. A contour of M planar Bezier curves R^m of degree v_m
// with R^m_{v_m} = R^{m+1}_0 (indices mod M; relgeo::Bezier_contour), a unit
// direction d and heights l1 < l2 define
//     E = { x in R^3 : l1 <= d.x <= l2,  Q[x - (d.x) d] in Int(Gamma) },
// Q the rotation carrying d to the z axis (relgeo::rotation_to_z). E is well
// formed when Gamma is a simple closed curve: no curve self-intersects,
// adjacent curves meet only at their shared end, other curves do not meet.
//
// The sufficient conditions (thesis, after Andersson, Peters and Stewart,
// "Self-intersection of composite curves and surfaces", CAGD 1998):
//  1. q = { R^m_{i+1} - R^m_i : 0 <= i < v } with 0 not in conv(q). Proof: a
//     line through 0 missing conv(q) has a normal e with e.q_i > 0 for all i,
//     so e.R'(t) = v sum_i B_i(t) e.q_i > 0 and e.R(t) is strictly increasing:
//     R^m is injective. Margin: dist(0, conv(q)).
//  2. With u = 1 - w, R~^m(u) = R^m(1 - u) has control points R~^m_i =
//     R^m_{v-i} and R~^m(0) = R^{m+1}(0) = P. The thesis' sets are
//       Q'  = { R^{m+1}_{i+1} - R~^m_j  : 0 <= i <= v-1, 0 <= j <= v },
//       Q'' = { R^{m+1}_j - R~^m_{i+1}  : 0 <= i <= v-1, 0 <= j <= v },
//     v(v+1) points each (the thesis' "n = v(v+1)", 12 for cubics); condition:
//     0 not in conv(Q') and 0 not in conv(Q''). (The scan of the thesis is
//     garbled here; these sets are the ones its index ranges and its count
//     n = v(v+1) determine, and the proof below shows they work.)
//     Derivation. The difference D(u, s) = R^{m+1}(s) - R~^m(u) is a
//     tensor-product Bernstein polynomial with coefficients
//     d_ij = R^{m+1}_j - R~^m_i, d_00 = 0; Q' holds the d_ij with j >= 1, Q''
//     those with i >= 1. Write R^{m+1}(s) - P = s A(s) and R~^m(u) - P =
//     u C(u), with A(s) = sum_j B^{v-1}_j(s) (v/(j+1)) (R^{m+1}_{j+1} - P) and
//     C likewise (B^v_{j+1}(s) = s (v/(j+1)) B^{v-1}_j(s)). So D = s A(s) +
//     u (-C(u)) is, for (u, s) != (0, 0), a nontrivial nonnegative
//     combination of E = { R^{m+1}_j - P : j >= 1 } u { P - R~^m_i : i >= 1 },
//     and never 0 when 0 is not in conv(E): the curves meet only at P
//     (u = s = 0), and neither returns to P. Finally
//       0 not in conv(E)  <=>  0 not in conv(Q') and 0 not in conv(Q''):
//     "=>": a normal e with e.x > 0 on E gives e.d_ij = e.(R^{m+1}_j - P) +
//     e.(P - R~^m_i) > 0 on Q' and on Q''. "<=": if 0 in conv(E), some
//     A' in conv{R^{m+1}_j - P} and B' in conv{P - R~^m_i} satisfy
//     l A' + m B' = 0 (l, m >= 0, not both 0); l = 0 or m = 0 puts 0 in
//     conv(Q'') or conv(Q'); otherwise B' = -(l/m) A', and A' + B' (a convex
//     combination of d_ij, i, j >= 1, in both sets) equals (1 - l/m) A':
//     l = m gives 0 in both hulls, l < m puts A' + B' and B' (both in Q'') on
//     opposite sides of 0, l > m does the same for A' + B' and A' in Q'.
//     Margin: min(dist(0, conv Q'), dist(0, conv Q'')) — the condition needs
//     both, so a perturbation that puts 0 into either hull voids it (the
//     thesis writes max{...} for this maximal perturbation; min is what the
//     condition as stated supports).
//  3. For non-adjacent curves, conv(control points) disjoint (the convex-hull
//     property of Bezier curves). Margin: the separation of the two hulls.
//
// Margins are exact (relgeo/curves/convex_separation.h) and rounded toward
// -inf: a margin is never overstated. Signed: a violated condition has margin
// <= 0 (minus the distance from 0 to the hull's boundary, or minus the
// penetration depth of the two hulls).
//
// Verdict of one hull problem. Its input points move by at most
//   uncertainty  = max over its points of the bound of their perturbation:
//                  eps(R) = delta ||R|| + delta_abs for a control point (the
//                  thesis' |dR| <= 1e-3 ||R||), eps(a) + eps(b) for a
//                  difference a - b;
// and the computation adds at most
//   computation_error = rounding of the differences to double (u |w| each,
//                  u = 2^-53)  +  the hull algorithm's backward error (the
//                  a-posteriori certificate relgeo::hull_backward_error times
//                  M; 0 under exact predicates; +inf when the output is not in
//                  convex position or the algorithm failed)  +  2 x the
//                  rotation error of 3D input (Plane_projection).
// A perturbation of every input point by at most r moves a convex hull by at
// most r (Hausdorff), so the condition holds for every admissible input when
//   margin > uncertainty + computation_error        -> certified;
// it fails for the stored data when
//   margin (rounded up) <= the rounding and rotation terms  -> refused;
// otherwise it holds for the stored data but not robustly -> uncertain.
// The contour is certified when every problem is; refused when one is.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/rounding.h"
#include "relgeo/curves/contour.h"
#include "relgeo/curves/convex_separation.h"
#include "relgeo/error/hull_backward_error.h"
#include "relgeo/hull/graham_fortune.h"
#include "relgeo/hull/graham_incremental.h"
#include "relgeo/hull/monotone_chain.h"
#include "relgeo/kernel/concepts.h"

namespace relgeo {

// ---- hull algorithms as function objects ----------------------------------------

/// relgeo::graham_fortune as a function object (the default: stable).
struct Graham_fortune_hull {
  static constexpr std::string_view name = "graham-fortune";
  template <OrientationKernel_2 K>
  Hull_result<typename K::Point_2> operator()(std::span<const typename K::Point_2> p, const K& k) const {
    return graham_fortune<K>(p, k);
  }
};
/// relgeo::monotone_chain as a function object.
struct Monotone_chain_hull {
  static constexpr std::string_view name = "monotone-chain";
  template <OrientationKernel_2 K>
  Hull_result<typename K::Point_2> operator()(std::span<const typename K::Point_2> p, const K& k) const {
    return monotone_chain<K>(p, k);
  }
};
/// relgeo::graham_incremental as a function object (unstable with naive kernels).
struct Graham_incremental_hull {
  static constexpr std::string_view name = "graham-incremental";
  template <OrientationKernel_2 K>
  Hull_result<typename K::Point_2> operator()(std::span<const typename K::Point_2> p, const K& k) const {
    return graham_incremental<K>(p, k);
  }
};

// ---- report types ------------------------------------------------------------------

/// The three sufficient conditions of thesis Sec. 3.4.1.
enum class Extrusion_condition : int {
  no_self_intersection = 1,  ///< 0 not in conv(q) for each curve
  adjacent_curves = 2,       ///< 0 not in conv(Q'), conv(Q'') for each adjacent pair
  disjoint_curves = 3        ///< disjoint control hulls for each non-adjacent pair
};

/// Verdict of a hull problem, a condition or the contour.
enum class Extrusion_verdict {
  certified,  ///< holds for every input within the stated uncertainty
  uncertain,  ///< holds for the stored data, but the margin does not cover the uncertainty
  refused     ///< the sufficient condition fails for the stored data
};

constexpr std::string_view to_string(Extrusion_verdict v) noexcept {
  switch (v) {
    case Extrusion_verdict::certified: return "certified";
    case Extrusion_verdict::uncertain: return "uncertain";
    case Extrusion_verdict::refused: return "refused";
  }
  return "?";
}
constexpr std::string_view to_string(Extrusion_condition c) noexcept {
  switch (c) {
    case Extrusion_condition::no_self_intersection: return "no-self-intersection";
    case Extrusion_condition::adjacent_curves: return "adjacent-curves";
    case Extrusion_condition::disjoint_curves: return "disjoint-curves";
  }
  return "?";
}

/// Options of check_extrusion.
struct Extrusion_options {
  /// delta: each control point R may be off by delta ||R|| + absolute_uncertainty
  /// (||R|| = the contour's scale of the point). Default: the thesis' 1e-3.
  double relative_uncertainty = 1e-3;
  /// Added to every control point's uncertainty (same units as the coordinates).
  double absolute_uncertainty = 0;
  /// Bound of the error of the 3D -> 2D projection of every control point
  /// (Plane_projection::rotation_error); 0 for planar input.
  double rotation_error = 0;
  /// Condition 3 with a spatial prune (sweep over bounding boxes); false:
  /// every non-adjacent pair exactly (M(M-3)/2 separations).
  bool prune = true;
  /// At most this many not-certified problems are listed in the report
  /// (all are counted).
  std::size_t max_listed = 1000;
};

/// One planar hull problem and its outcome.
struct Extrusion_problem {
  Extrusion_condition condition = Extrusion_condition::no_self_intersection;
  /// "q" (condition 1), "Q'" or "Q''" (condition 2), "hulls" (condition 3).
  std::string_view set;
  std::size_t curve_a = 0, curve_b = 0;  ///< curves involved (a == b for condition 1; b = a+1 for 2)
  double margin = 0;             ///< signed, exact, rounded toward -inf
  double uncertainty = 0;        ///< rounded upward
  double computation_error = 0;  ///< rounded upward; +inf when the hull is unusable
  Extrusion_verdict verdict = Extrusion_verdict::certified;
  /// margin - uncertainty - computation_error (in double; -inf when the
  /// computation error is infinite): > 0 exactly when certified.
  double slack() const { return margin - uncertainty - computation_error; }
};

/// What one condition looks like over the contour.
struct Extrusion_condition_summary {
  Extrusion_condition condition = Extrusion_condition::no_self_intersection;
  std::size_t problems = 0;  ///< hull problems decided exactly
  std::size_t certified = 0, uncertain = 0, refused = 0;  ///< of `problems`
  /// Condition 3 with the prune: pairs certified by their bounding boxes
  /// alone (axis gap > prune radius), not among `problems`.
  std::size_t pruned = 0;
  /// The smallest margin (+inf with no problem). For condition 3 with the
  /// prune, pairs farther apart than the prune radius are not computed: then
  /// min_margin = min(smallest computed, prune radius), a lower bound, and
  /// min_margin_is_prune_bound says the radius was the smaller.
  double min_margin = std::numeric_limits<double>::infinity();
  bool min_margin_is_prune_bound = false;
  /// The problem with the smallest slack (none without problems).
  std::optional<Extrusion_problem> worst;
  Extrusion_verdict verdict = Extrusion_verdict::certified;
};

/// The result of check_extrusion.
struct Extrusion_report {
  Extrusion_verdict verdict = Extrusion_verdict::certified;
  std::array<Extrusion_condition_summary, 3> conditions;
  /// The problems that are not certified, smallest slack first (at most
  /// options.max_listed; `offending_total` counts all).
  std::vector<Extrusion_problem> offending;
  std::size_t offending_total = 0;
  std::size_t curves = 0;
  // hull algorithm statistics
  std::size_t hull_runs = 0, hull_failures = 0, non_convex_hulls = 0;
  std::size_t predicate_calls = 0, uncertain_answers = 0;
  double max_hull_backward_error = 0;  ///< largest certificate (absolute distance), +inf if any unusable
  // condition 3
  std::size_t non_adjacent_pairs = 0;  ///< M(M-3)/2 for M >= 3 (0 below)
  std::size_t pairs_computed = 0;      ///< separations computed exactly
  double prune_radius = 0;             ///< 0 without prune
  double rotation_error = 0;
};

namespace internal {

/// A point set handed to the hull algorithm, with its uncertainty and the
/// rounding error of its construction.
struct Hull_problem_input {
  std::vector<Point_2<double>> points;
  double uncertainty = 0;  ///< max perturbation of a point induced by the input uncertainty
  double rounding = 0;     ///< max rounding error of a point (differences: u |w|)
};

/// The computed hull of one point set: its vertices, and the distance by
/// which it may miss input points (the backward error, absolute).
struct Computed_hull {
  std::vector<Point_2<double>> vertices;  ///< the input points the algorithm returned
  double backward = 0;                    ///< +inf when unusable
};

/// The hull algorithm of a check, behind one type per kernel: the check is
/// compiled once per kernel, not once per (kernel, algorithm) pair (a call
/// through it costs nothing next to a hull).
template <OrientationKernel_2 K>
using Hull_function =
    std::function<Hull_result<typename K::Point_2>(std::span<const typename K::Point_2>, const K&)>;

template <OrientationKernel_2 K>
Computed_hull run_hull(std::span<const Point_2<double>> pts, const K& k, const Hull_function<K>& algorithm,
                       Extrusion_report& rep) {
  using P = typename K::Point_2;
  const auto construct = k.construct_point_2_object();
  std::vector<P> kp;
  kp.reserve(pts.size());
  for (const auto& p : pts) kp.push_back(construct(p.x, p.y));
  const Hull_result<P> r = algorithm(std::span<const P>(kp), k);
  ++rep.hull_runs;
  rep.predicate_calls += r.predicate_calls;
  rep.uncertain_answers += r.uncertain_answers;
  Computed_hull h;
  for (std::size_t i : r.indices) h.vertices.push_back(pts[i]);
  if (!r.ok() || r.indices.empty()) {
    ++rep.hull_failures;
    h.backward = std::numeric_limits<double>::infinity();
    if (h.vertices.empty()) h.vertices.push_back(pts[0]);  // keep margins defined
  } else if constexpr (!K::has_exact_predicates) {
    // Exact predicates return the exact hull (soundness rule): backward error 0.
    const Hull_backward_error b = hull_backward_error(pts, r.indices);
    if (std::isinf(b.value)) ++rep.non_convex_hulls;
    h.backward = std::isinf(b.value) ? b.value : mul_up(b.value, coordinate_bound(pts));
  }
  rep.max_hull_backward_error = std::max(rep.max_hull_backward_error, h.backward);
  return h;
}

/// Upper bound of the rounding error of fl(a - b) over a set: u (1 + 2u) |fl(a-b)|.
inline double difference_rounding(std::span<const Point_2<double>> w) {
  double m = 0;
  for (const auto& p : w) m = std::max(m, norm_up(p.x, p.y));
  return mul_up(0x1.0000000000002p-53, m);
}

inline Extrusion_verdict decide(double margin_lower, double margin_upper, double uncertainty,
                                double computation_error, double data_error) {
  if (margin_lower > add_up(uncertainty, computation_error)) return Extrusion_verdict::certified;
  if (margin_upper <= data_error) return Extrusion_verdict::refused;
  return Extrusion_verdict::uncertain;
}

/// The steps of check_extrusion, sharing the contour, the options, the
/// kernel and hull algorithm, and the report being filled: one member per
/// condition, and the bookkeeping of each hull problem.
template <OrientationKernel_2 K>
class Extrusion_check {
 public:
  Extrusion_check(const Bezier_contour& contour, const Extrusion_options& options, const K& k,
                  const Hull_function<K>& hull)
      : contour_(contour), options_(options), k_(k), hull_(hull), M_(contour.size()),
        rho2_(mul_up(2.0, options.rotation_error)) {  // a difference or a pair moves by 2 rho
    rep_.curves = M_;
    rep_.rotation_error = options.rotation_error;
    for (int c = 0; c < 3; ++c) rep_.conditions[c].condition = static_cast<Extrusion_condition>(c + 1);
  }

  /// Condition 1: q = { R_{i+1} - R_i } of each curve.
  void no_self_intersection() {
    for (std::size_t m = 0; m < M_; ++m) {
      const auto& c = contour_[m];
      Hull_problem_input in;
      for (std::size_t i = 0; i < c.degree(); ++i) {
        in.points.push_back({c[i + 1].x - c[i].x, c[i + 1].y - c[i].y});
        in.uncertainty = std::max(in.uncertainty, add_up(eps(m, i + 1), eps(m, i)));
      }
      in.rounding = difference_rounding(in.points);
      origin_problem(Extrusion_condition::no_self_intersection, "q", m, m, in);
    }
  }

  /// Condition 2: Q' and Q'' of each adjacent pair (m, m+1).
  void adjacent_curves() {
    for (std::size_t m = 0; m < M_; ++m) {
      const std::size_t n = (m + 1) % M_;
      const auto& a = contour_[m];  // R^m, ends at P
      const auto& b = contour_[n];  // R^{m+1}, starts at P
      Hull_problem_input q1, q2;
      // Q' = { R^{m+1}_{i+1} - R^m_j : i < v_{m+1}, j <= v_m }
      for (std::size_t i = 0; i < b.degree(); ++i)
        for (std::size_t j = 0; j <= a.degree(); ++j) {
          q1.points.push_back({b[i + 1].x - a[j].x, b[i + 1].y - a[j].y});
          q1.uncertainty = std::max(q1.uncertainty, add_up(eps(n, i + 1), eps(m, j)));
        }
      // Q'' = { R^{m+1}_j - R^m_i : i < v_m, j <= v_{m+1} }   (R~^m_{i'+1} = R^m_{v-1-i'})
      for (std::size_t i = 0; i < a.degree(); ++i)
        for (std::size_t j = 0; j <= b.degree(); ++j) {
          q2.points.push_back({b[j].x - a[i].x, b[j].y - a[i].y});
          q2.uncertainty = std::max(q2.uncertainty, add_up(eps(n, j), eps(m, i)));
        }
      q1.rounding = difference_rounding(q1.points);
      q2.rounding = difference_rounding(q2.points);
      origin_problem(Extrusion_condition::adjacent_curves, "Q'", m, n, q1);
      origin_problem(Extrusion_condition::adjacent_curves, "Q''", m, n, q2);
    }
  }

  /// Condition 3: the control hulls of each non-adjacent pair, all pairs or
  /// those the spatial prune cannot certify by their bounding boxes.
  void disjoint_curves() {
    if (M_ < 4) return;
    rep_.non_adjacent_pairs = M_ * (M_ - 3) / 2;
    control_hulls();
    if (options_.prune) pairs_near_in_boxes();
    else all_pairs();
  }

  /// The verdicts of the conditions and of the contour, and the list of the
  /// problems not certified, smallest slack first.
  Extrusion_report report() && {
    rep_.verdict = Extrusion_verdict::certified;
    for (auto& s : rep_.conditions) {
      s.verdict = s.refused ? Extrusion_verdict::refused
                  : s.uncertain ? Extrusion_verdict::uncertain
                                : Extrusion_verdict::certified;
      if (s.verdict == Extrusion_verdict::refused) rep_.verdict = Extrusion_verdict::refused;
      else if (s.verdict == Extrusion_verdict::uncertain && rep_.verdict == Extrusion_verdict::certified)
        rep_.verdict = Extrusion_verdict::uncertain;
    }
    std::sort(not_certified_.begin(), not_certified_.end(),
              [](const Extrusion_problem& x, const Extrusion_problem& y) { return x.slack() < y.slack(); });
    rep_.offending_total = not_certified_.size();
    if (not_certified_.size() > options_.max_listed) not_certified_.resize(options_.max_listed);
    rep_.offending = std::move(not_certified_);
    return std::move(rep_);
  }

 private:
  struct Box {
    double xmin, ymin, xmax, ymax;
  };

  /// The bound of the perturbation of control point i of curve m.
  double eps(std::size_t m, std::size_t i) const {
    return add_up(mul_up(options_.relative_uncertainty, contour_.scale(m, i)), options_.absolute_uncertainty);
  }

  /// Counts a decided problem in its condition's summary.
  void record(const Extrusion_problem& p) {
    auto& s = rep_.conditions[static_cast<int>(p.condition) - 1];
    ++s.problems;
    s.min_margin = std::min(s.min_margin, p.margin);
    if (!s.worst || p.slack() < s.worst->slack()) s.worst = p;
    switch (p.verdict) {
      case Extrusion_verdict::certified: ++s.certified; break;
      case Extrusion_verdict::uncertain: ++s.uncertain; break;
      case Extrusion_verdict::refused: ++s.refused; break;
    }
    if (p.verdict != Extrusion_verdict::certified) not_certified_.push_back(p);
  }

  /// A problem on a difference set: margin = signed dist(0, conv(computed hull)).
  void origin_problem(Extrusion_condition cond, std::string_view set, std::size_t a, std::size_t b,
                      const Hull_problem_input& in) {
    const Computed_hull h = run_hull(std::span<const Point_2<double>>(in.points), k_, hull_, rep_);
    const Signed_distance d = signed_distance_to_hull(h.vertices, Point_2<double>{0.0, 0.0});
    Extrusion_problem p;
    p.condition = cond, p.set = set, p.curve_a = a, p.curve_b = b;
    p.margin = d.lower();
    p.uncertainty = in.uncertainty;
    const double data_error = add_up(in.rounding, rho2_);
    p.computation_error = add_up(data_error, h.backward);
    p.verdict = decide(p.margin, d.upper(), p.uncertainty, p.computation_error, data_error);
    record(p);
  }

  /// The computed hull of each curve's control points, its exact hull, the
  /// largest uncertainty of its points and its bounding box.
  void control_hulls() {
    eps_max_.assign(M_, 0.0);
    boxes_.resize(M_);
    for (std::size_t m = 0; m < M_; ++m) {
      const auto pts = contour_[m].control_points();
      hulls_.push_back(run_hull(pts, k_, hull_, rep_));
      exact_hulls_.push_back(exact_hull(hulls_.back().vertices));
      Box bx{pts[0].x, pts[0].y, pts[0].x, pts[0].y};
      for (std::size_t i = 0; i < pts.size(); ++i) {
        eps_max_[m] = std::max(eps_max_[m], eps(m, i));
        bx.xmin = std::min(bx.xmin, pts[i].x), bx.xmax = std::max(bx.xmax, pts[i].x);
        bx.ymin = std::min(bx.ymin, pts[i].y), bx.ymax = std::max(bx.ymax, pts[i].y);
      }
      boxes_[m] = bx;
    }
  }

  bool adjacent(std::size_t a, std::size_t b) const { return a == b || (a + 1) % M_ == b || (b + 1) % M_ == a; }

  /// The separation problem of curves a < b.
  void pair_problem(std::size_t a, std::size_t b) {
    const Signed_distance d = separation_of_hulls(exact_hulls_[a], exact_hulls_[b]);
    Extrusion_problem p;
    p.condition = Extrusion_condition::disjoint_curves, p.set = "hulls", p.curve_a = a, p.curve_b = b;
    p.margin = d.lower();
    p.uncertainty = add_up(eps_max_[a], eps_max_[b]);
    p.computation_error = add_up(rho2_, add_up(hulls_[a].backward, hulls_[b].backward));
    p.verdict = decide(p.margin, d.upper(), p.uncertainty, p.computation_error, rho2_);
    ++rep_.pairs_computed;
    record(p);
  }

  /// Without the prune: every non-adjacent pair, exactly.
  void all_pairs() {
    for (std::size_t a = 0; a < M_; ++a)
      for (std::size_t b = a + 1; b < M_; ++b)
        if (!adjacent(a, b)) pair_problem(a, b);
  }

  /// The prune radius: at least twice the largest pair requirement (so that
  /// every pair farther apart is certified by its boxes alone), and at least
  /// the median box diagonal (so that the margin reported is the real
  /// smallest separation for contours of similar curves).
  double prune_radius() const {
    double need = 0;
    for (double e : eps_max_) need = std::max(need, e);
    need = add_up(add_up(need, need), rho2_);
    std::vector<double> diag(M_);
    for (std::size_t m = 0; m < M_; ++m)
      diag[m] = std::hypot(boxes_[m].xmax - boxes_[m].xmin, boxes_[m].ymax - boxes_[m].ymin);
    std::nth_element(diag.begin(), diag.begin() + static_cast<std::ptrdiff_t>(M_ / 2), diag.end());
    return std::max(mul_up(2.0, need), diag[M_ / 2]);
  }

  /// With the prune: a sweep over the boxes sorted by x; pairs whose boxes
  /// are farther apart than the radius on an axis are certified unseen.
  void pairs_near_in_boxes() {
    const double r = prune_radius();
    rep_.prune_radius = r;
    // Boxes whose axis gap exceeds r: the hulls are farther apart than r
    // (the max of the axis gaps is at most the Euclidean distance of the
    // boxes), so their pair is certified: r > uncertainty + 2 rho.
    std::vector<std::size_t> order(M_);
    for (std::size_t m = 0; m < M_; ++m) order[m] = m;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return boxes_[a].xmin < boxes_[b].xmin; });
    for (std::size_t s = 0; s < M_; ++s) {
      const std::size_t a = order[s];
      const double reach = boxes_[a].xmax + r;
      for (std::size_t t = s + 1; t < M_ && boxes_[order[t]].xmin <= reach; ++t) {
        const std::size_t b = order[t];
        if (adjacent(a, b)) continue;
        if (boxes_[b].ymin > boxes_[a].ymax + r || boxes_[a].ymin > boxes_[b].ymax + r) continue;
        pair_problem(std::min(a, b), std::max(a, b));
      }
    }
    // The gap tests above are in double with r as computed; a pair skipped
    // has a computed gap > r. Each gap is one subtraction, exact to half an
    // ulp, and r >= 2 need, so the true gap exceeds need: certified.
    auto& s3 = rep_.conditions[2];
    s3.pruned = rep_.non_adjacent_pairs - rep_.pairs_computed;
    const double r_lower = r * (1 - 0x1p-50);  // covers the rounding of the gap tests
    if (s3.pruned > 0 && r_lower < s3.min_margin) s3.min_margin = r_lower, s3.min_margin_is_prune_bound = true;
  }

  const Bezier_contour& contour_;
  const Extrusion_options& options_;
  const K& k_;
  const Hull_function<K>& hull_;
  const std::size_t M_;
  const double rho2_;
  Extrusion_report rep_;
  std::vector<Extrusion_problem> not_certified_;
  // condition 3
  std::vector<Computed_hull> hulls_;
  std::vector<std::vector<Point_2<double>>> exact_hulls_;  // conv of each computed hull, exactly
  std::vector<double> eps_max_;
  std::vector<Box> boxes_;
};

/// check_extrusion for one kernel, whatever the hull algorithm.
template <OrientationKernel_2 K>
Extrusion_report check_extrusion_with(const Bezier_contour& contour, const Extrusion_options& options, const K& k,
                                      const Hull_function<K>& hull) {
  // Margins are rounded in hardware: whatever the caller's environment, in
  // round to nearest without FTZ/DAZ (the same for every kernel: a naive one
  // can only downgrade the verdict, never make it depend on the caller).
  const Default_fp_environment environment;
  const double delta = options.relative_uncertainty, delta_abs = options.absolute_uncertainty;
  if (!(delta >= 0) || !std::isfinite(delta) || !(delta_abs >= 0) || !std::isfinite(delta_abs) ||
      !(options.rotation_error >= 0))
    throw Invalid_input("extrusion: uncertainties must be finite and nonnegative");
  Extrusion_check<K> check(contour, options, k, hull);
  check.no_self_intersection();
  check.adjacent_curves();
  check.disjoint_curves();
  return std::move(check).report();
}

}  // namespace internal

/// \brief Checks the three sufficient conditions for the extruded object over
/// `contour` (thesis Sec. 3.4.1) with kernel K and hull algorithm `hull`, and
/// returns every margin and the verdict (see the top of this header).
///
/// \tparam K any OrientationKernel_2 (relgeo's kernels, Cgal_kernel<...>).
/// \tparam Algorithm a function object `(std::span<const K::Point_2>, const K&)
///   -> Hull_result<K::Point_2>`: Graham_fortune_hull (default),
///   Monotone_chain_hull, Graham_incremental_hull, or your own.
/// \throws Invalid_input for a negative or non-finite uncertainty.
/// Complexity: 4M hull problems of at most v(v+1) points, plus condition 3:
///   with the prune, a sweep over the M bounding boxes (sorted by x) and one
///   exact separation per pair of boxes closer than the prune radius —
///   O(M log M + K) for K such pairs (O(M) for a contour whose curves are of
///   comparable size); without it M(M-3)/2 separations.
template <OrientationKernel_2 K, class Algorithm = Graham_fortune_hull>
Extrusion_report check_extrusion(const Bezier_contour& contour, const Extrusion_options& options = {},
                                 const K& k = K{}, const Algorithm& hull = Algorithm{}) {
  return internal::check_extrusion_with<K>(contour, options, k, internal::Hull_function<K>(std::cref(hull)));
}

}  // namespace relgeo
