// relgeo/kernel/internal/implicit_enclosed.h — implicit points as enclosures
// of their homogeneous coordinates: Failsafe_kernel<T> (values with a bound
// on their rounding error in T, filtered_value.h) and Interval_kernel (intervals). There is no exact
// fallback: a predicate answers `uncertain` when its enclosure contains 0, and
// a point whose denominator W cannot be certified nonzero is not built.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "relgeo/core/fp_environment.h"
#include "relgeo/core/interval.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/core/rounding.h"
#include "relgeo/kernel/implicit_point.h"
#include "relgeo/kernel/internal/implicit_predicates.h"
#include "relgeo/kernel/internal/lpi_filter.h"

namespace relgeo::internal {

/// An Interval containing the exact value an enclosure stands for.
inline Interval enclosure_interval(const Interval& v) { return v; }
template <class T>
Interval enclosure_interval(const Filtered_value<T>& v) {
  const double e = upper_double(v.error_bound());
  return Interval(sub_down(lower_double(v.value), e), add_up(upper_double(v.value), e));
}

/// The midpoint of an enclosure of X / W and its half-width, rounded up
/// (infinite when W's enclosure contains 0 or anything overflowed).
template <class NT>
Approximate_point_3 approximate_from_enclosure(const Homogeneous_3<NT>& h) {
  Approximate_point_3 a;
  const Interval w = h.unit ? Interval(1.0) : enclosure_interval(h.w);
  if (!(w.inf() > 0 || w.sup() < 0)) return a;
  double error = 0;
  double* out[3] = {&a.point.x, &a.point.y, &a.point.z};
  for (int axis = 0; axis < 3; ++axis) {
    const Interval c = enclosure_interval(h[axis]) / w;
    const double mid = 0.5 * c.inf() + 0.5 * c.sup();
    // An overflowed enclosure ([-inf, inf]: NaN midpoint) bounds nothing;
    // std::max would silently drop the NaN and state a finite error.
    if (!std::isfinite(mid)) return a;
    *out[axis] = mid;
    error = std::max({error, sub_up(c.sup(), mid), sub_up(mid, c.inf())});
  }
  a.error = std::isfinite(error) ? error : std::numeric_limits<double>::infinity();
  return a;
}

/// Whether an enclosure bounds a finite value: no NaN or infinity in its
/// ends (an interval) or in its value and error bound (Filtered_value).
inline bool is_finite_enclosure(const Interval& v) { return std::isfinite(v.inf()) && std::isfinite(v.sup()); }
template <class T>
bool is_finite_enclosure(const Filtered_value<T>& v) {
  return std::isfinite(v.value) && std::isfinite(v.magnitude);
}
template <class NT>
bool is_finite_enclosure(const Homogeneous_3<NT>& h) {
  return is_finite_enclosure(h.x) && is_finite_enclosure(h.y) && is_finite_enclosure(h.z) && is_finite_enclosure(h.w);
}

/// Policy of Implicit_kernel_base for kernels whose implicit points are
/// enclosures in NT (Filtered_value<T> or Interval), built from explicit
/// points of type Explicit (Point_3<T> or Point_3<Interval>).
///
/// A point whose enclosure is not finite (an explicit point with a NaN or
/// infinite coordinate, or coordinates that overflowed) gives `uncertain` in
/// every predicate: interval arithmetic on [inf, inf] gives definite signs
/// that mean nothing.
template <class Explicit_, class NT>
struct Enclosed_implicit_policy {
  using Explicit = Explicit_;
  // Filtered_value<T> over points of T: the closed-form paths of lpi_filter.h.
  static constexpr bool closed_form = std::is_same_v<NT, Filtered_value<decltype(Explicit{}.x)>>;
  struct Point {
    Homogeneous_3<NT> h;
    Implicit_point_kind kind = Implicit_point_kind::explicit_point;
  };

  static Point_3<NT> to_nt(const Explicit& p) { return {NT(p.x), NT(p.y), NT(p.z)}; }
  static Point make(const Explicit& p) { return {explicit_coordinates(to_nt(p)), Implicit_point_kind::explicit_point}; }

  static std::optional<Point> lpi(const Explicit& p, const Explicit& q, const Explicit& r, const Explicit& s,
                                  const Explicit& t) {
    if (!finite(make(p), make(q), make(r), make(s), make(t))) return std::nullopt;
    return in_default_fp_environment([&] {
      if constexpr (closed_form) return checked(lpi_filter(p, q, r, s, t), Implicit_point_kind::lpi);
      else return checked(lpi_coordinates(to_nt(p), to_nt(q), to_nt(r), to_nt(s), to_nt(t)), Implicit_point_kind::lpi);
    });
  }
  static std::optional<Point> tpi(const std::array<Explicit, 9>& v) {
    for (const Explicit& p : v)
      if (!finite(make(p))) return std::nullopt;
    return in_default_fp_environment([&] {
      std::array<Point_3<NT>, 9> n;
      for (int i = 0; i < 9; ++i) n[i] = to_nt(v[i]);
      return checked(tpi_coordinates(n), Implicit_point_kind::tpi);
    });
  }
  static Certified_sign orientation_3(const Point& a, const Point& b, const Point& c, const Point& d) {
    return in_default_fp_environment([&] {
      if (!finite(a, b, c, d)) return Certified_sign::uncertain;
      return orientation_3_sign<NT>({&a.h, &b.h, &c.h, &d.h});
    });
  }
  /// d against the plane of three input points.
  static Certified_sign orientation_3(const Explicit& a, const Explicit& b, const Explicit& c, const Point& d) {
    if constexpr (closed_form)
      return in_default_fp_environment([&] {
        if (!finite(make(a), make(b), make(c), d)) return Certified_sign::uncertain;
        return orientation_3_filter(a, b, c, d.h).sign() * sign_of_w(d.h);
      });
    else
      return orientation_3(make(a), make(b), make(c), d);
  }
  static Certified_sign orientation_2(const Point& a, const Point& b, const Point& c, int axis) {
    return in_default_fp_environment([&] {
      if (!finite(a, b, c)) return Certified_sign::uncertain;
      return orientation_2_sign<NT>({&a.h, &b.h, &c.h}, axis);
    });
  }
  static Certified_sign compare_xyz(const Point& a, const Point& b) {
    return in_default_fp_environment([&] {
      if (!finite(a, b)) return Certified_sign::uncertain;
      return compare_xyz_sign(a.h, b.h);
    });
  }
  static Approximate_point_3 approximate(const Point& a) {
    return in_default_fp_environment([&] { return approximate_from_enclosure(a.h); });
  }

 private:
  template <class... Points>
  static bool finite(const Points&... p) {
    return (is_finite_enclosure(p.h) && ...);
  }
  // Built only when W is certainly nonzero (and from finite points: an
  // interval W of infinite inputs can look certainly nonzero).
  static std::optional<Point> checked(const Homogeneous_3<NT>& h, Implicit_point_kind kind) {
    const Certified_sign w = certified_sign_of(h.w);
    if (!certainly(w, Certified_sign::positive) && !certainly(w, Certified_sign::negative)) return std::nullopt;
    return Point{h, kind};
  }
};

}  // namespace relgeo::internal
