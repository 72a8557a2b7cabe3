// relgeo/core/interval.h — closed intervals of doubles with outward rounding.
//
// Each operation is evaluated in round-to-nearest and its result widened by
// (at least) one ulp on the side of the exact value (found with TwoSum and
// TwoProduct for sums and products of points; on both sides otherwise: the
// bounds of core/rounding.h). This
// needs no change of the rounding mode (no fesetround, no -frounding-math) and
// is sound because a correctly rounded result lies within one ulp of the exact
// one, also under underflow (error <= half the smallest subnormal) and
// overflow (rounded to +-inf, whose neighbour is the largest finite double).
// It assumes the default floating-point environment (round to nearest, no
// FTZ/DAZ): relgeo's kernels and algorithms establish it around their interval
// computations (Default_fp_environment, core/fp_environment.h); a client doing
// interval arithmetic of its own under another environment must do the same.
//
// Exact operations stay exact (a product with the point factor [0,0] too), so
// exactly collinear points with representable differences give the point
// interval [0,0] and an exact `zero` instead of a spurious `uncertain`.
//
// NaN endpoints propagate and make every comparison uncertain.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/errors.h"
#include "relgeo/core/rounding.h"

namespace relgeo {

class Interval {
 public:
  constexpr Interval() = default;
  /// The point interval [v, v].
  constexpr Interval(double v) : lo_(v), hi_(v) {}  // NOLINT(google-explicit-constructor): a double is an exact interval
  constexpr Interval(double lo, double hi) : lo_(lo), hi_(hi) {}

  constexpr double inf() const { return lo_; }
  constexpr double sup() const { return hi_; }
  constexpr bool is_point() const { return lo_ == hi_; }
  constexpr bool is_zero() const { return lo_ == 0 && hi_ == 0; }
  constexpr bool has_nan() const { return lo_ != lo_ || hi_ != hi_; }

  /// Certified sign: definite only when the interval excludes 0 or is exactly [0,0].
  constexpr Certified_sign sign() const {
    if (lo_ > 0) return Certified_sign::positive;
    if (hi_ < 0) return Certified_sign::negative;
    if (lo_ == 0 && hi_ == 0) return Certified_sign::zero;
    return Certified_sign::uncertain;
  }

  /// Identity of the two intervals (not a certified comparison of their values).
  friend constexpr bool operator==(const Interval&, const Interval&) = default;

  friend Interval operator-(const Interval& a) { return {-a.hi_, -a.lo_}; }

  friend Interval operator+(const Interval& a, const Interval& b) {
    return {add_bounds(a.lo_, b.lo_).lo, add_bounds(a.hi_, b.hi_).hi};
  }
  friend Interval operator-(const Interval& a, const Interval& b) {
    return {add_bounds(a.lo_, -b.hi_).lo, add_bounds(a.hi_, -b.lo_).hi};
  }
  friend Interval operator*(const Interval& a, const Interval& b) {
    if (a.has_nan() || b.has_nan()) return nan();
    if (a.is_zero() || b.is_zero()) return {0.0, 0.0};  // exact, even against infinities
    if (a.is_point() && b.is_point()) {
      const Double_bounds p = mul_bounds(a.lo_, b.lo_);
      return {p.lo, p.hi};
    }
    const double c[4] = {a.lo_ * b.lo_, a.lo_ * b.hi_, a.hi_ * b.lo_, a.hi_ * b.hi_};
    double lo = c[0], hi = c[0];
    for (double v : c) {
      if (std::isnan(v)) return nan();  // 0 * inf inside a wide interval
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    return {std::isfinite(lo) ? step_down(lo) : next_down(lo), std::isfinite(hi) ? step_up(hi) : next_up(hi)};
  }
  /// a / b. \pre b does not contain 0 (throws Precondition_violation).
  /// Exact quotients of point intervals stay points.
  friend Interval operator/(const Interval& a, const Interval& b) {
    if (a.has_nan() || b.has_nan()) return nan();
    if (!(b.lo_ > 0 || b.hi_ < 0)) throw Precondition_violation("Interval division: the divisor contains 0");
    if (a.is_point() && b.is_point()) {
      const Double_bounds q = div_bounds(a.lo_, b.lo_);
      return {q.lo, q.hi};
    }
    const double c[4] = {a.lo_ / b.lo_, a.lo_ / b.hi_, a.hi_ / b.lo_, a.hi_ / b.hi_};
    double lo = c[0], hi = c[0];
    for (double v : c) lo = std::min(lo, v), hi = std::max(hi, v);
    return {next_down(lo), next_up(hi)};
  }
  /// Enclosures of min(x, y) and max(x, y) for x in a, y in b.
  friend Interval min(const Interval& a, const Interval& b) {
    return {std::min(a.lo_, b.lo_), std::min(a.hi_, b.hi_)};
  }
  friend Interval max(const Interval& a, const Interval& b) {
    return {std::max(a.lo_, b.lo_), std::max(a.hi_, b.hi_)};
  }

  Interval& operator+=(const Interval& b) { return *this = *this + b; }
  Interval& operator-=(const Interval& b) { return *this = *this - b; }
  Interval& operator*=(const Interval& b) { return *this = *this * b; }
  Interval& operator/=(const Interval& b) { return *this = *this / b; }

  /// Certified comparison of two intervals: definite when they do not overlap
  /// (or are the same point).
  friend Certified_sign compare(const Interval& a, const Interval& b) { return (a - b).sign(); }

 private:
  static constexpr Interval nan() {
    return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  }
  double lo_ = 0, hi_ = 0;
};

}  // namespace relgeo
