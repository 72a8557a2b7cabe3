// relgeo/surfaces/internal/vector_ops.h — fixed-size vectors of any number
// type (std::array<FT, D>) and the few operations the spline code needs (dot
// and cross: relgeo/kernel/vector_3.h), plus
// the square root of each number type relgeo knows.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "relgeo/core/interval.h"
#include "relgeo/core/mpfr_number.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/core/rounding.h"
#include "relgeo/kernel/point.h"
#include "relgeo/kernel/vector_3.h"

namespace relgeo {

/// A vector (difference of points, derivative) of dimension D in FT.
template <class FT, int D>
using Vector_nd = std::array<FT, D>;
template <class FT>
using Vector_2 = Vector_nd<FT, 2>;
template <class FT>
using Vector_3 = Vector_nd<FT, 3>;

namespace internal {

template <class FT, int D>
Vector_nd<FT, D> zero_vector() {
  Vector_nd<FT, D> r;
  r.fill(FT(0));
  return r;
}
template <class FT, int D>
Vector_nd<FT, D> operator_add(const Vector_nd<FT, D>& a, const Vector_nd<FT, D>& b) {
  Vector_nd<FT, D> r;
  for (int i = 0; i < D; ++i) r[i] = a[i] + b[i];
  return r;
}
template <class FT, int D>
Vector_nd<FT, D> operator_sub(const Vector_nd<FT, D>& a, const Vector_nd<FT, D>& b) {
  Vector_nd<FT, D> r;
  for (int i = 0; i < D; ++i) r[i] = a[i] - b[i];
  return r;
}
template <class FT, int D>
Vector_nd<FT, D> scaled(const Vector_nd<FT, D>& a, const FT& s) {
  Vector_nd<FT, D> r;
  for (int i = 0; i < D; ++i) r[i] = a[i] * s;
  return r;
}
/// a += s * b
template <class FT, int D>
void add_scaled(Vector_nd<FT, D>& a, const FT& s, const Vector_nd<FT, D>& b) {
  for (int i = 0; i < D; ++i) a[i] += s * b[i];
}

template <class FT>
Vector_3<FT> to_vector(const Point_3<FT>& p) {
  return {p.x, p.y, p.z};
}
template <class FT>
Vector_2<FT> to_vector(const Point_2<FT>& p) {
  return {p.x, p.y};
}
template <class FT>
Point_3<FT> to_point(const Vector_3<FT>& v) {
  return {v[0], v[1], v[2]};
}
template <class FT>
Point_2<FT> to_point(const Vector_2<FT>& v) {
  return {v[0], v[1]};
}

/// Square root in FT where FT has one: double (rounded to nearest),
/// Interval (an enclosure, outward by one ulp), Mpfr_number<B>. Rationals have
/// none (a unit normal is not rational): callers use the unnormalised normal.
template <class FT>
FT square_root(const FT& x) {
  if constexpr (std::is_floating_point_v<FT>) {
    return std::sqrt(x);
  } else if constexpr (std::is_same_v<FT, Interval>) {
    if (x.has_nan() || x.sup() < 0) return Interval(std::numeric_limits<double>::quiet_NaN());
    return Interval(sqrt_down(std::max(0.0, x.inf())), sqrt_up(x.sup()));
  } else {
    return sqrt(x);  // Mpfr_number and other types with an ADL sqrt
  }
}
template <class FT>
inline constexpr bool has_square_root_v = std::is_floating_point_v<FT> || std::is_same_v<FT, Interval> ||
                                          requires(const FT& x) { sqrt(x); };

/// One value of FT in FT2: exact where FT2 holds FT's values (double ->
/// Interval, mpq_class, Mpfr_number), to nearest when FT2 is a floating-point
/// type, through the exact rational otherwise (mpq_class -> Interval: the
/// tightest enclosure).
template <class FT2, class FT>
FT2 convert_number(const FT& x) {
  if constexpr (std::is_same_v<FT, FT2>) return x;
  else if constexpr (std::is_floating_point_v<FT>) return Number_traits<FT2>::from_double(static_cast<double>(x));
  else if constexpr (std::is_floating_point_v<FT2>) return static_cast<FT2>(nearest_double(x));
  else return Number_traits<FT2>::from_rational(Number_traits<FT>::to_rational(x));
}

}  // namespace internal
}  // namespace relgeo
