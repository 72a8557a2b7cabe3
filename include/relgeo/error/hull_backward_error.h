// relgeo/error/hull_backward_error.h — how far the input must move for a
// computed hull to be exact: the a-posteriori certificate and the a-priori
// bound of graham_fortune.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "relgeo/error/convex_polygon.h"
#include "relgeo/error/hull_error.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/kernel/internal/semi_static_filter.h"

namespace relgeo {

/// A backward-error certificate of a computed hull Y.
struct Hull_backward_error {
  /// Relative perturbation (distance / M, rounded upward) after which Y is the
  /// exact hull of the perturbed input; +inf when the polygon Y is not simple,
  /// strictly convex and counterclockwise.
  double value = 0;
  /// The explicit perturbation: these input points move to their nearest
  /// point of conv(Y); all others stay.
  std::vector<std::size_t> moved_points;
  /// The input point that moves farthest (none when nothing moves).
  std::optional<std::size_t> worst_point;
};

/// \brief Backward-error certificate of the hull `hull_indices` of `input`
/// (what none of the peers offer).
///
/// Y is the polygon the indices list, in that order. If it is simple,
/// strictly convex and counterclockwise (is_ccw_strictly_convex_polygon),
/// moving every input point that lies outside it to its nearest point of Y
/// makes Y the exact hull of the perturbed input. The value, max distance /
/// M, is therefore an upper bound of the smallest relative perturbation; it
/// is 0 exactly when Y is the exact hull. Otherwise (a self-intersecting,
/// non-convex or clockwise polygon, also when its vertex set is right) the
/// value is +inf: no perturbation that keeps the points where a convex
/// polygon needs them is searched for, the polygon is simply not a hull.
/// Exact predicates and distances; O(n log h) plus O(h) per point outside.
/// \throws Non_finite_input for a NaN or infinite input coordinate.
inline Hull_backward_error hull_backward_error(std::span<const Point_2<double>> input,
                                               std::span<const std::size_t> hull_indices) {
  const Default_fp_environment environment;
  internal::require_finite(input, "hull_backward_error");
  Hull_backward_error b;
  const std::vector<Point_2<double>> y = points_at(input, hull_indices);
  if (!is_ccw_strictly_convex_polygon(y)) {
    b.value = std::numeric_limits<double>::infinity();
    return b;
  }
  if (y.empty()) {
    b.value = input.empty() ? 0.0 : std::numeric_limits<double>::infinity();
    return b;
  }
  mpq_class worst = 0;
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (locate(y, input[i]) != Polygon_side::outside) continue;
    b.moved_points.push_back(i);
    mpq_class d = squared_distance(y, input[i]);
    if (!b.worst_point || d > worst) worst = std::move(d), b.worst_point = i;
  }
  const double m = coordinate_bound(input);
  b.value = b.worst_point ? internal::relative_distance(worst, m, "hull_backward_error") : 0.0;
  return b;
}

/// \brief A-priori backward-error bound of graham_fortune under kernel K for
/// this input, relative to M; empty when K gives no such guarantee.
///
/// * Exact predicates: 0 (the output is the exact hull).
/// * Failsafe_kernel<T> (certified, with an a-priori constant eps): when the
///   kernel answers `uncertain` for a triple (a, q, r) with a.x <= q.x <= r.x
///   (the scan always tests such triples, pivot a), the exact determinant is
///   at most 2 eps Mx My (1+u)^2 with Mx = |r.x - a.x|, My <= 2M; so q lies
///   vertically within delta = 4 eps (1+u)^2 M of segment ar. A dropped point
///   is within delta of the chain when dropped; each later pop moves the chain
///   by at most delta over it; there are fewer than n pops. Points dropped by
///   the split lie within delta of segment LR, inside the output hull. Hence
///   every input point is within n delta of conv(Y):
///       bound = 4 n eps (1+u)^2  (+ u_T when T is narrower than double: the
///       input is rounded to T first).
///   The derivation needs the filter to answer within its proven regime: every
///   nonzero |coordinate| in [2^p low_2, high_2 / 2] of T's filter constants,
///   p the significand bits of T, so that two different coordinates differ by
///   at least low_2 (for double about [2^-397, 2^509], for float [2^-7,
///   2^61]); outside that the bound is empty. (The scan runs in the default
///   floating-point environment, which graham_fortune establishes.)
/// * Other kernels (naive, interval, MPFR): empty.
template <OrientationKernel_2 K>
std::optional<double> graham_fortune_backward_error_bound(std::span<const Point_2<double>> input) {
  if constexpr (K::has_exact_predicates) {
    return 0.0;
  } else if constexpr (K::is_certified && std::is_floating_point_v<typename K::FT>) {
    if constexpr (!K::orientation_2_error_bound.has_value()) {
      return std::nullopt;
    } else {
      using T = typename K::FT;
      using C = internal::Orientation_filter_constants<T>;
      const long double lo = std::ldexp(static_cast<long double>(C::low_2), C::digits);
      const long double hi = static_cast<long double>(C::high_2) / 2;
      for (const auto& p : input)
        for (double v : {p.x, p.y})
          if (v != 0 && (std::abs(static_cast<long double>(v)) < lo || std::abs(static_cast<long double>(v)) > hi))
            return std::nullopt;
      const long double u = static_cast<long double>(C::u);
      const long double eps = static_cast<long double>(C::eps_2);
      const long double n = static_cast<long double>(input.size());
      long double bound = 4 * n * eps * (1 + u) * (1 + u);
      if constexpr (std::numeric_limits<T>::digits < std::numeric_limits<double>::digits) bound += u;
      return round_up_to_double(bound * (1 + 0x1p-60L));  // margin for this evaluation's rounding
    }
  } else {
    return std::nullopt;
  }
}

}  // namespace relgeo
