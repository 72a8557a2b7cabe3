// relgeo/kernel/interval.h — closed intervals of doubles with outward rounding.
//
// Each operation is evaluated in round-to-nearest and its result widened by
// (at least) one ulp on the side of the exact value (found with TwoSum and
// TwoProduct for sums and products of points; on both sides otherwise). This
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

#include "relgeo/kernel/certified_sign.h"
#include "relgeo/kernel/internal/error_free.h"

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
    return {sum_down(a.lo_, b.lo_), sum_up(a.hi_, b.hi_)};
  }
  friend Interval operator-(const Interval& a, const Interval& b) {
    return {sum_down(a.lo_, -b.hi_), sum_up(a.hi_, -b.lo_)};
  }
  friend Interval operator*(const Interval& a, const Interval& b) {
    if (a.has_nan() || b.has_nan()) return nan();
    if (a.is_zero() || b.is_zero()) return {0.0, 0.0};  // exact, even against infinities
    if (a.is_point() && b.is_point()) return point_product(a.lo_, b.lo_);
    const double c[4] = {a.lo_ * b.lo_, a.lo_ * b.hi_, a.hi_ * b.lo_, a.hi_ * b.hi_};
    double lo = c[0], hi = c[0];
    for (double v : c) {
      if (std::isnan(v)) return nan();  // 0 * inf inside a wide interval
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    return {std::isfinite(lo) ? down(lo) : std::nextafter(lo, -kInf),
            std::isfinite(hi) ? up(hi) : std::nextafter(hi, kInf)};
  }

  Interval& operator+=(const Interval& b) { return *this = *this + b; }
  Interval& operator-=(const Interval& b) { return *this = *this - b; }
  Interval& operator*=(const Interval& b) { return *this = *this * b; }

  /// Certified comparison of two intervals: definite when they do not overlap
  /// (or are the same point).
  friend Certified_sign compare(const Interval& a, const Interval& b) { return (a - b).sign(); }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  static constexpr Interval nan() {
    return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  }
  // At least one ulp outward, inline (libm's nextafter is a call): Rump,
  // Zimmermann, Boldo, Melquiond, "Computing predecessor and successor in
  // rounding to nearest", BIT 49 (2009): for finite x,
  // fl(x + fl(phi |x| + eta)) >= succ(x) with phi = u (1 + 2u), eta = 2^-1074
  // (one ulp more in rare cases, e.g. next to a power of two: still an outer
  // bound). The caller handles infinities.
  static double up(double x) {
    const double c = 0x1p-53 * (1 + 0x1p-52) * std::abs(x) + 0x1p-1074;
    return x + c;
  }
  static double down(double x) {
    const double c = 0x1p-53 * (1 + 0x1p-52) * std::abs(x) + 0x1p-1074;
    return x - c;
  }
  // Rounded sum x + y moved down (up) to a bound of the exact sum. The exact
  // rounding error comes from Knuth's TwoSum, so an exact sum is not widened
  // and an inexact one only on the side where the exact value lies.
  static double sum_down(double x, double y) {
    const auto [s, error] = internal::two_sum(x, y);
    if (!std::isfinite(s)) [[unlikely]] return std::nextafter(s, -kInf);
    const double d = down(s);
    return error >= 0 ? s : d;
  }
  static double sum_up(double x, double y) {
    const auto [s, error] = internal::two_sum(x, y);
    if (!std::isfinite(s)) [[unlikely]] return std::nextafter(s, kInf);
    const double u = up(s);
    return error <= 0 ? s : u;
  }
  // Product of two nonzero doubles; product_error gives the exact rounding
  // error while the product is far from underflow.
  static Interval point_product(double x, double y) {
    const double p = x * y;
    if (!std::isfinite(p) || std::abs(p) < 0x1p-960) [[unlikely]]
      return {std::nextafter(p, -kInf), std::nextafter(p, kInf)};
    const double e = product_error(x, y, p);
    const double lo = down(p), hi = up(p);
    if (!std::isfinite(e)) [[unlikely]] return {lo, hi};  // no exact error: widen both sides
    return {e >= 0 ? p : lo, e <= 0 ? p : hi};
  }
  static double product_error(double x, double y, double p) { return internal::two_product_error(x, y, p); }

  double lo_ = 0, hi_ = 0;
};

}  // namespace relgeo
