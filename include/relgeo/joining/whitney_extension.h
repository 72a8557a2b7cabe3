// relgeo/joining/whitney_extension.h — the Whitney extension of boundary
// heights (thesis Sec. 4.3.1), evaluated in floating point with its two
// guarantees proven for the computed values, not only in exact arithmetic.
//
// Data: boundary samples q_i in the (u,v) domain with heights e_i (the
// discrepancy of the boundary curves from the surface, thesis Sec. 4.3.1).
// With L >= the data's Lipschitz constant L* = max |e_i - e_j| / |q_i - q_j|,
//   l(p) = max_i (e_i - L |p - q_i|),  u(p) = min_i (e_i + L |p - q_i|),
//   a(p) = (l(p) + u(p)) / 2
// is L-Lipschitz, interpolates the data and |a| <= M = max |e_i|.
//
// What the computed value a^(p) satisfies (doc/joining.md, "The
// floating-point proof"; every statement about exact reals):
//  (G1) |a^(p)| <= M;
//  (G2) |a^(p) - e_i| <= L |p - q_i| for every sample i (the Whitney
//       condition towards the boundary: slope <= L between any vertex and any
//       boundary vertex), and a^(q_i) = e_i;
//  (G3) |a^(p) - a(p)| <= deviation(p), a certified bound of a few units in
//       the last place, so |a^(p) - a^(p')| <= L |p - p'| + deviation(p) +
//       deviation(p') between any two points.
// (G1) and (G2) hold because a^(p) is chosen in [l^, u^] intersected with
// [-M, M], where l^ >= l(p) and u^ <= u(p) are computed with a proven
// one-sided error (the per-sample cones are shifted by kappa |e_i| + tau and
// their slope by a factor 1 - kappa, kappa = 2^-48, which covers every
// rounding of the cone's evaluation in round-to-nearest). When that bracket is
// empty (p within about 2^-18 of a sample, relative to the data's scale), l
// and u are computed again in MPFR at 256 bits with directed rounding and a
// double inside [l, u] cut with [-M, M] is chosen; only when no double lies
// in it is the value reported as uncertified (never seen in the tests). L is
// L* rounded upward and enlarged by slope_margin (2^-30), which keeps [l, u]
// wide enough to hold a double away from the samples.
//
// The maximum over samples runs through a kd-tree whose nodes carry the
// largest shifted height: a node is skipped when the same round-to-nearest
// formula, applied to the node's box, cannot exceed the best value found.
// Rounding to nearest is monotone, so every skipped cone is no larger than the
// result: the value is the brute-force maximum bit for bit (tested). This
// needs the default floating-point environment (held here) and no
// contraction into fused multiply-adds (relgeo's targets compile with
// -ffp-contract=off).
#pragma once

#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/mpfr_number.h"
#include "relgeo/core/rounding.h"
#include "relgeo/joining/error_measures.h"
#include "relgeo/kernel/point.h"

namespace relgeo {

/// A boundary sample: parameters and height.
struct Whitney_sample {
  Point_2<double> q;
  double e = 0;
};

/// Options of Whitney_extension.
struct Whitney_options {
  /// L = L* (1 + slope_margin), rounded up [2^-30].
  double slope_margin = 0x1p-30;
  /// Evaluate through the kd-tree (false: every sample; the same values bit
  /// for bit, slower) [true].
  bool use_index = true;
};

/// The value at one point and what is known about it.
struct Whitney_value {
  double height = 0;     ///< a^(p)
  double lower = 0;      ///< a double <= ... the bracket a^ was chosen in: lower >= l(p)
  double upper = 0;      ///< upper <= u(p)
  double deviation = 0;  ///< |a^(p) - a(p)| <= deviation (rounded up)
  bool certified = true; ///< (G1) and (G2) proven for this value
  bool fallback = false; ///< decided by the MPFR stage
  std::uint32_t argmax = 0, argmin = 0;  ///< samples attaining l^ and u^ (seeds for the next query)
  std::uint32_t cones = 0;  ///< cone pairs evaluated for this value (the index's work)
};

/// \brief The Whitney extension of boundary samples (thesis Sec. 4.3.1), with
/// the floating-point guarantees (G1)-(G3) of the file comment.
class Whitney_extension {
 public:
  static constexpr double kappa = 0x1p-48;
  /// Largest magnitude of coordinates, heights and L accepted (the proof's
  /// range: no overflow anywhere).
  static constexpr double max_magnitude = 0x1p500;

  /// \throws Invalid_input for no sample, non-finite or too large values, or
  /// two samples at the same (u,v) with different heights (no Lipschitz
  /// extension exists).
  explicit Whitney_extension(std::vector<Whitney_sample> samples, const Whitney_options& options = {})
      : options_(options) {
    const Default_fp_environment environment;
    if (samples.empty()) throw Invalid_input("Whitney_extension: no boundary sample");
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const auto& s = samples[i];
      if (!all_finite(s.q.x, s.q.y, s.e))
        throw Non_finite_input("Whitney_extension: sample " + std::to_string(i) + " is not finite");
      if (std::abs(s.q.x) > max_magnitude || std::abs(s.q.y) > max_magnitude || std::abs(s.e) > max_magnitude)
        throw Invalid_input("Whitney_extension: sample " + std::to_string(i) + " beyond 2^500");
    }
    // One sample per (u,v) position; equal positions with different heights
    // admit no Lipschitz extension.
    std::sort(samples.begin(), samples.end(), [](const Whitney_sample& a, const Whitney_sample& b) {
      return a.q.x != b.q.x ? a.q.x < b.q.x : (a.q.y != b.q.y ? a.q.y < b.q.y : a.e < b.e);
    });
    std::vector<Whitney_sample> distinct;
    for (const auto& s : samples) {
      if (!distinct.empty() && distinct.back().q.x == s.q.x && distinct.back().q.y == s.q.y) {
        if (distinct.back().e != s.e)
          throw Invalid_input("Whitney_extension: two samples at (" + std::to_string(s.q.x) + ", " +
                              std::to_string(s.q.y) + ") with different heights");
        continue;
      }
      distinct.push_back(s);
    }
    samples_ = std::move(distinct);
    for (const auto& s : samples_) max_abs_ = std::max(max_abs_, std::abs(s.e));
    data_slope_ = data_lipschitz_upper_bound(samples_);
    slope_ = data_slope_ == 0 ? 0.0 : mul_up(data_slope_, add_up(1.0, options_.slope_margin));
    if (!(slope_ <= max_magnitude))
      throw Invalid_input("Whitney_extension: the boundary data's slope " + std::to_string(slope_) +
                          " is beyond 2^500 (nearly coincident samples with different heights)");
    tau_ = add_up(mul_up(slope_, 0x1p-530), 0x1p-1000);
    slope_low_ = mul_down(slope_, 1 - kappa);
    build_tree();
  }

  /// L: the slope of the cones, >= every pairwise slope of the data.
  double lipschitz_constant() const { return slope_; }
  /// L*: the largest pairwise slope of the data, rounded upward.
  double data_lipschitz_constant() const { return data_slope_; }
  /// M = max |e_i|.
  double max_abs_height() const { return max_abs_; }
  /// The distinct samples (sorted).
  std::span<const Whitney_sample> samples() const { return samples_; }

  /// a^(p) with its bracket and deviation bound. `seed` (the previous
  /// query's argmax/argmin) only speeds up the search.
  Whitney_value evaluate(const Point_2<double>& p, std::pair<std::uint32_t, std::uint32_t> seed = {0, 0}) const {
    const Default_fp_environment environment;
    if (!all_finite(p.x, p.y) || std::abs(p.x) > max_magnitude || std::abs(p.y) > max_magnitude)
      throw Non_finite_input("Whitney_extension::evaluate: the point is not finite or beyond 2^500");
    if (slope_ == 0) {  // constant data: a = e exactly
      Whitney_value v;
      v.height = v.lower = v.upper = samples_[0].e;
      return v;
    }
    std::uint32_t imax = std::min<std::uint32_t>(seed.first, static_cast<std::uint32_t>(size() - 1));
    std::uint32_t imin = std::min<std::uint32_t>(seed.second, static_cast<std::uint32_t>(size() - 1));
    double lo = upper_cone(imax, p), hi = lower_cone(imin, p);
    std::uint32_t cones = 2;
    if (options_.use_index) {
      search_max(0, p, lo, imax, cones);
      search_min(0, p, hi, imin, cones);
    } else {
      for (std::uint32_t i = 0; i < size(); ++i) {
        const double c = upper_cone(i, p), d = lower_cone(i, p);
        if (c > lo) lo = c, imax = i;
        if (d < hi) hi = d, imin = i;
      }
      cones += static_cast<std::uint32_t>(2 * size());
    }
    Whitney_value v = choose(p, lo, hi, imax, imin);
    v.cones = cones / 2;
    return v;
  }

  /// Every point, each query seeded by the previous one's samples.
  std::vector<Whitney_value> evaluate_all(std::span<const Point_2<double>> points) const {
    std::vector<Whitney_value> out;
    out.reserve(points.size());
    std::pair<std::uint32_t, std::uint32_t> seed{0, 0};
    for (const auto& p : points) {
      out.push_back(evaluate(p, seed));
      seed = {out.back().argmax, out.back().argmin};
    }
    return out;
  }

 private:
  std::size_t size() const { return samples_.size(); }

  // The computed distance d~ = RN(sqrt(RN(RN(dx^2) + RN(dy^2)))), the same
  // expression for samples and (monotone) for boxes.
  static double rn_distance(double dx, double dy) { return std::sqrt(dx * dx + dy * dy); }
  // c^_i >= e_i - L |p - q_i| and v^_i <= e_i + L |p - q_i|.
  double upper_cone(std::uint32_t i, const Point_2<double>& p) const {
    return e_hi_[i] - slope_low_ * rn_distance(p.x - qx_[i], p.y - qy_[i]);
  }
  double lower_cone(std::uint32_t i, const Point_2<double>& p) const {
    return e_lo_[i] + slope_low_ * rn_distance(p.x - qx_[i], p.y - qy_[i]);
  }

  // Upper bound of |e_i - e_j| / |q_i - q_j| over all pairs, rounded up. The
  // certified bound costs more than plain arithmetic, so a pair is bounded in
  // full only when de^2 >= best^2 (1 - 2^-38) d^2 in plain double (the plain
  // products are within 2^-50 of the exact ones when d^2 > 2^-900 and the
  // right side is above 2^-1000; otherwise the pair is bounded in full). O(n^2) multiplications: 0.1 s at 10^4
  // samples.
  static double data_lipschitz_upper_bound(const std::vector<Whitney_sample>& s) {
    double best = 0, threshold = 0;  // threshold = best^2 (1 - 2^-38)
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double xi = s[i].q.x, yi = s[i].q.y, ei = s[i].e;
      for (std::size_t j = i + 1; j < s.size(); ++j) {
        const double dx = xi - s[j].q.x, dy = yi - s[j].q.y, de = ei - s[j].e;
        const double d2 = dx * dx + dy * dy;
        const double bar = threshold * d2;
        if (d2 > 0x1p-900 && bar > 0x1p-1000 && de * de < bar) continue;
        const double b = slope_upper_bound(s[i].q, ei, s[j].q, s[j].e);
        if (b > best) best = b, threshold = best * best * (1 - 0x1p-38);
      }
    }
    return best;
  }

  // The kd-tree: samples in tree order (structure of arrays), nodes with
  // their box and the extreme shifted heights.
  struct Node {
    std::uint32_t begin, end, left = 0, right = 0;
    double x0, y0, x1, y1;
    double e_hi_max, e_lo_min;
  };
  void build_tree() {
    std::vector<std::uint32_t> order(size());
    std::iota(order.begin(), order.end(), 0u);
    nodes_.clear();
    build(order, 0, static_cast<std::uint32_t>(size()));
    std::vector<Whitney_sample> ordered;
    for (std::uint32_t i : order) ordered.push_back(samples_[i]);
    samples_ = std::move(ordered);
    qx_.clear(), qy_.clear(), e_hi_.clear(), e_lo_.clear();
    for (const auto& s : samples_) {
      qx_.push_back(s.q.x), qy_.push_back(s.q.y);
      // e_i + kappa |e_i| + tau upward, e_i - kappa |e_i| - tau downward.
      e_hi_.push_back(add_up(add_up(s.e, mul_up(kappa, std::abs(s.e))), tau_));
      e_lo_.push_back(sub_down(sub_down(s.e, mul_up(kappa, std::abs(s.e))), tau_));
    }
    for (Node& n : nodes_) {
      n.e_hi_max = -std::numeric_limits<double>::infinity(), n.e_lo_min = std::numeric_limits<double>::infinity();
      for (std::uint32_t i = n.begin; i < n.end; ++i)
        n.e_hi_max = std::max(n.e_hi_max, e_hi_[i]), n.e_lo_min = std::min(n.e_lo_min, e_lo_[i]);
    }
  }
  std::uint32_t build(std::vector<std::uint32_t>& order, std::uint32_t begin, std::uint32_t end) {
    const auto id = static_cast<std::uint32_t>(nodes_.size());
    Node n{begin, end, 0, 0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), 0, 0};
    for (std::uint32_t i = begin; i < end; ++i) {
      const auto& q = samples_[order[i]].q;
      n.x0 = std::min(n.x0, q.x), n.y0 = std::min(n.y0, q.y), n.x1 = std::max(n.x1, q.x), n.y1 = std::max(n.y1, q.y);
    }
    nodes_.push_back(n);
    if (end - begin <= 8) return id;
    const bool by_x = n.x1 - n.x0 >= n.y1 - n.y0;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end, [&](std::uint32_t a, std::uint32_t b) {
      return by_x ? samples_[a].q.x < samples_[b].q.x : samples_[a].q.y < samples_[b].q.y;
    });
    const std::uint32_t l = build(order, begin, mid);
    const std::uint32_t r = build(order, mid, end);
    nodes_[id].left = l, nodes_[id].right = r;
    return id;
  }
  // The computed distance to any sample of the box is >= this (monotonicity
  // of round-to-nearest: |RN(p.x - q.x)| >= RN(box.x0 - p.x) when p.x < x0 <= q.x).
  static double box_distance(const Node& n, const Point_2<double>& p) {
    const double dx = p.x < n.x0 ? n.x0 - p.x : (p.x > n.x1 ? p.x - n.x1 : 0.0);
    const double dy = p.y < n.y0 ? n.y0 - p.y : (p.y > n.y1 ? p.y - n.y1 : 0.0);
    return rn_distance(dx, dy);
  }
  double node_max_bound(const Node& n, const Point_2<double>& p) const {
    return n.e_hi_max - slope_low_ * box_distance(n, p);
  }
  double node_min_bound(const Node& n, const Point_2<double>& p) const {
    return n.e_lo_min + slope_low_ * box_distance(n, p);
  }
  void search_max(std::uint32_t id, const Point_2<double>& p, double& best, std::uint32_t& arg,
                  std::uint32_t& cones) const {
    const Node& n = nodes_[id];
    if (n.left == 0) {
      cones += n.end - n.begin;
      for (std::uint32_t i = n.begin; i < n.end; ++i) {
        const double c = upper_cone(i, p);
        if (c > best) best = c, arg = i;
      }
      return;
    }
    const double bl = node_max_bound(nodes_[n.left], p), br = node_max_bound(nodes_[n.right], p);
    const std::uint32_t first = bl >= br ? n.left : n.right, second = bl >= br ? n.right : n.left;
    if (std::max(bl, br) > best) search_max(first, p, best, arg, cones);
    if (std::min(bl, br) > best) search_max(second, p, best, arg, cones);
  }
  void search_min(std::uint32_t id, const Point_2<double>& p, double& best, std::uint32_t& arg,
                  std::uint32_t& cones) const {
    const Node& n = nodes_[id];
    if (n.left == 0) {
      cones += n.end - n.begin;
      for (std::uint32_t i = n.begin; i < n.end; ++i) {
        const double c = lower_cone(i, p);
        if (c < best) best = c, arg = i;
      }
      return;
    }
    const double bl = node_min_bound(nodes_[n.left], p), br = node_min_bound(nodes_[n.right], p);
    const std::uint32_t first = bl <= br ? n.left : n.right, second = bl <= br ? n.right : n.left;
    if (std::min(bl, br) < best) search_min(first, p, best, arg, cones);
    if (std::max(bl, br) < best) search_min(second, p, best, arg, cones);
  }

  // a^ from the certified bracket, or from the MPFR stage when it is empty.
  Whitney_value choose(const Point_2<double>& p, double lo, double hi, std::uint32_t imax, std::uint32_t imin) const {
    Whitney_value v;
    v.argmax = imax, v.argmin = imin;
    const double a = std::max(lo, -max_abs_), b = std::min(hi, max_abs_);
    if (a <= b) {
      const double mid = 0.5 * lo + 0.5 * hi;
      v.height = std::clamp(mid, a, b), v.lower = lo, v.upper = hi;
      // l >= l^ - err(imax), u <= u^ + err(imin): a(p) lies within half of
      // those of the bracket's midpoint.
      const double err_l = cone_error(imax, p), err_u = cone_error(imin, p);
      const double mid_lo = add_down(mul_down(0.5, sub_down(lo, err_l)), mul_down(0.5, hi));
      const double mid_hi = add_up(mul_up(0.5, lo), mul_up(0.5, add_up(hi, err_u)));
      v.deviation = std::max(sub_up(v.height, mid_lo), sub_up(mid_hi, v.height));
      return v;
    }
    return choose_exactly(p, v);
  }
  // Upper bound of c^_i - c_i (and of v_i - v^_i): (kappa + 7.1u)(|e_i| +
  // L d_i) + 3 tau (doc/joining.md), taken generously as 2^-46 (|e_i| + L d~_i) + 4 tau.
  double cone_error(std::uint32_t i, const Point_2<double>& p) const {
    const double d = rn_distance(p.x - qx_[i], p.y - qy_[i]);
    return add_up(mul_up(0x1p-46, add_up(std::abs(samples_[i].e), mul_up(slope_, mul_up(d, 1 + 0x1p-50)))),
                  mul_up(4.0, tau_));
  }

  // l and u at 256 bits, directed: l_hi >= l, u_lo <= u; then a double in
  // [max(l_hi, -M), min(u_lo, M)].
  Whitney_value choose_exactly(const Point_2<double>& p, Whitney_value v) const {
    v.fallback = true;
    constexpr mpfr_prec_t bits = 256;
    Mpfr_value l_hi(bits), u_lo(bits), l_lo(bits), u_hi(bits), d_lo(bits), d_hi(bits), t(bits);
    mpfr_set_inf(l_hi.get(), -1), mpfr_set_inf(l_lo.get(), -1), mpfr_set_inf(u_lo.get(), 1), mpfr_set_inf(u_hi.get(), 1);
    for (std::uint32_t i = 0; i < size(); ++i) {
      // The exact squared distance, its precision sized from the exponents:
      // a fixed 2200 bits (before) rounded it when the coordinates' bits span
      // more than 1100 (a sample at 2^400 and a point at 2^-1074), so d_lo
      // and d_hi were not certainly bounds (doc/joining.md).
      const std::array<std::array<double, 2>, 2> differences{{{p.x, qx_[i]}, {p.y, qy_[i]}}};
      const Mpfr_value squared = internal::exact_sum_of_squared_differences(differences);
      mpfr_sqrt(d_lo.get(), squared.get(), MPFR_RNDD), mpfr_sqrt(d_hi.get(), squared.get(), MPFR_RNDU);
      const double e = samples_[i].e;
      // upper bound of e - L d: e - RD(L d_lo) rounded up; lower bound: e - RU(L d_hi) rounded down.
      mpfr_mul_d(t.get(), d_lo.get(), slope_, MPFR_RNDD), mpfr_d_sub(t.get(), e, t.get(), MPFR_RNDU);
      mpfr_max(l_hi.get(), l_hi.get(), t.get(), MPFR_RNDU);
      mpfr_mul_d(t.get(), d_hi.get(), slope_, MPFR_RNDU), mpfr_d_sub(t.get(), e, t.get(), MPFR_RNDD);
      mpfr_max(l_lo.get(), l_lo.get(), t.get(), MPFR_RNDD);
      mpfr_mul_d(t.get(), d_lo.get(), slope_, MPFR_RNDD), mpfr_add_d(t.get(), t.get(), e, MPFR_RNDD);
      mpfr_min(u_lo.get(), u_lo.get(), t.get(), MPFR_RNDD);
      mpfr_mul_d(t.get(), d_hi.get(), slope_, MPFR_RNDU), mpfr_add_d(t.get(), t.get(), e, MPFR_RNDU);
      mpfr_min(u_hi.get(), u_hi.get(), t.get(), MPFR_RNDU);
    }
    // [A, B] = [max(l_hi, -M), min(u_lo, M)]; the smallest double >= A.
    Mpfr_value A(bits), B(bits), mid(bits);
    mpfr_max_d(A, l_hi, -max_abs_);
    mpfr_min_d(B, u_lo, max_abs_);
    v.lower = round_mpfr<double>(l_hi.get(), Rounding::upward);
    v.upper = round_mpfr<double>(u_lo.get(), Rounding::downward);
    mpfr_add(mid.get(), l_lo.get(), u_hi.get(), MPFR_RNDN), mpfr_div_2ui(mid.get(), mid.get(), 1, MPFR_RNDN);
    const double candidate = round_mpfr<double>(mid.get(), Rounding::to_nearest);
    const double first_above = round_mpfr<double>(A.get(), Rounding::upward);
    double chosen = candidate;
    if (mpfr_cmp_d(A.get(), chosen) > 0 || mpfr_cmp_d(B.get(), chosen) < 0) chosen = first_above;
    v.certified = mpfr_cmp_d(A.get(), chosen) <= 0 && mpfr_cmp_d(B.get(), chosen) >= 0;
    if (!v.certified) chosen = std::clamp(candidate, -max_abs_, max_abs_);
    v.height = chosen;
    // a in [(l_lo + u_lo) / 2, (l_hi + u_hi) / 2].
    Mpfr_value a_lo(bits), a_hi(bits);
    mpfr_add(a_lo.get(), l_lo.get(), u_lo.get(), MPFR_RNDD), mpfr_div_2ui(a_lo.get(), a_lo.get(), 1, MPFR_RNDD);
    mpfr_add(a_hi.get(), l_hi.get(), u_hi.get(), MPFR_RNDU), mpfr_div_2ui(a_hi.get(), a_hi.get(), 1, MPFR_RNDU);
    mpfr_d_sub(a_lo.get(), chosen, a_lo.get(), MPFR_RNDU), mpfr_sub_d(a_hi.get(), a_hi.get(), chosen, MPFR_RNDU);
    v.deviation = std::max(round_mpfr<double>(a_lo.get(), Rounding::upward), round_mpfr<double>(a_hi.get(), Rounding::upward));
    return v;
  }
  static void mpfr_max_d(Mpfr_value& r, const Mpfr_value& x, double d) {
    if (mpfr_cmp_d(x.get(), d) >= 0) mpfr_set(r.get(), x.get(), MPFR_RNDN);
    else mpfr_set_d(r.get(), d, MPFR_RNDN);
  }
  static void mpfr_min_d(Mpfr_value& r, const Mpfr_value& x, double d) {
    if (mpfr_cmp_d(x.get(), d) <= 0) mpfr_set(r.get(), x.get(), MPFR_RNDN);
    else mpfr_set_d(r.get(), d, MPFR_RNDN);
  }

  Whitney_options options_;
  std::vector<Whitney_sample> samples_;
  std::vector<double> qx_, qy_, e_hi_, e_lo_;
  std::vector<Node> nodes_;
  double max_abs_ = 0, data_slope_ = 0, slope_ = 0, slope_low_ = 0, tau_ = 0;
};

}  // namespace relgeo
