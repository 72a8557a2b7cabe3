// relgeo/core/internal/error_free.h — error-free transformations of double
// arithmetic: a + b and a * b as a rounded result plus its exact error
// (Knuth's TwoSum; Dekker's TwoProduct with Veltkamp's splitting, or one fma
// where the target has it). Used by Interval's outward rounding and by the
// expansion stage of the exact predicates.
#pragma once

#include <cmath>

namespace relgeo::internal {

/// s = fl(a + b) and e with a + b = s + e exactly (no overflow).
struct Two_terms {
  double value, error;
};
inline Two_terms two_sum(double a, double b) {
  const double s = a + b;
  const double bv = s - a;
  return {s, (a - (s - bv)) + (b - bv)};
}
inline Two_terms two_diff(double a, double b) { return two_sum(a, -b); }

/// The exact error x*y - p of p = fl(x * y) (finite), without calling std::fma
/// (a libm call unless the target has FMA, e.g. -march=haswell). Dekker's
/// product is exact while no split overflows (|x|, |y| < 2^995), the product
/// of the high parts does not overflow (they exceed x and y by up to 2^-26
/// relative, so their product can pass DBL_MAX when p is within about 2^-26
/// of it: |p| < 2^1020 excludes that) and p does not underflow
/// (|p| >= 2^-969); outside it falls back to the correctly rounded fma.
#if defined(__FMA__) || defined(__FP_FAST_FMA)
inline double two_product_error(double x, double y, double p) { return __builtin_fma(x, y, -p); }
#else
inline void veltkamp_split(double a, double& hi, double& lo) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  hi = c - (c - a);
  lo = a - hi;
}
inline double two_product_error(double x, double y, double p) {
  if (std::abs(x) >= 0x1p995 || std::abs(y) >= 0x1p995 || std::abs(p) >= 0x1p1020) [[unlikely]]
    return std::fma(x, y, -p);
  double xh, xl, yh, yl;
  veltkamp_split(x, xh, xl);
  veltkamp_split(y, yh, yl);
  const double e1 = p - xh * yh;  // Shewchuk's Two_Product_Tail: each step exact
  const double e2 = e1 - xl * yh;
  const double e3 = e2 - xh * yl;
  return xl * yl - e3;
}
#endif
/// p = fl(x * y) and e with x * y = p + e exactly (in the range above).
inline Two_terms two_product(double x, double y) {
  const double p = x * y;
  return {p, two_product_error(x, y, p)};
}

}  // namespace relgeo::internal
