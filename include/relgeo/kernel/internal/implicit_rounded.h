// relgeo/kernel/internal/implicit_rounded.h — implicit points constructed in
// the kernel's own number type: exact for Exact_kernel (rationals), rounded
// for Naive_kernel<T> and Mpfr_kernel<B>, whose predicates then test the
// rounded point (and may be wrong: that is what they show).
#pragma once

#include <algorithm>
#include <limits>
#include <optional>

#include "relgeo/core/number_traits.h"
#include "relgeo/core/rounding.h"
#include "relgeo/kernel/implicit_point.h"
#include "relgeo/kernel/internal/implicit_coordinates.h"

namespace relgeo::internal {

/// Policy of Implicit_kernel_base for a kernel K over FT that constructs
/// implicit points as points of FT (X/W, Y/W, Z/W computed in FT).
template <class K, class FT>
struct Rounded_implicit_policy : Constructed_point_orientations<Rounded_implicit_policy<K, FT>, K> {
  friend struct Constructed_point_orientations<Rounded_implicit_policy, K>;
  using Explicit = Point_3<FT>;
  struct Point {
    Point_3<FT> point;
    Implicit_point_kind kind = Implicit_point_kind::explicit_point;
  };

  static Point make(const Explicit& p) { return {p, Implicit_point_kind::explicit_point}; }
  static std::optional<Point> lpi(const Explicit& p, const Explicit& q, const Explicit& r, const Explicit& s,
                                  const Explicit& t) {
    return divided(lpi_coordinates(p, q, r, s, t), Implicit_point_kind::lpi);
  }
  static std::optional<Point> tpi(const std::array<Explicit, 9>& v) {
    return divided(tpi_coordinates(v), Implicit_point_kind::tpi);
  }
  static Certified_sign compare_xyz(const Point& a, const Point& b) {
    Certified_sign s = K::compare_ft(a.point.x, b.point.x);
    if (certainly(s, Certified_sign::zero)) s = K::compare_ft(a.point.y, b.point.y);
    if (certainly(s, Certified_sign::zero)) s = K::compare_ft(a.point.z, b.point.z);
    return s;
  }
  /// Exact kernels know the error of rounding their point; naive ones do not
  /// know how far their point is from the exact one (infinite error).
  static Approximate_point_3 approximate(const Point& a) {
    Approximate_point_3 r{{nearest_double(a.point.x), nearest_double(a.point.y), nearest_double(a.point.z)}};
    if constexpr (K::has_exact_constructions) {
      double e = 0;
      const FT* c[3] = {&a.point.x, &a.point.y, &a.point.z};
      const double n[3] = {r.point.x, r.point.y, r.point.z};
      for (int i = 0; i < 3; ++i) {
        // An enclosure that overflowed (e.g. [-inf, inf] at huge magnitudes)
        // has no finite nearest double: no bound (std::max would drop a NaN).
        if (!std::isfinite(n[i])) e = std::numeric_limits<double>::infinity();
        else e = std::max({e, sub_up(upper_double(*c[i]), n[i]), sub_up(n[i], lower_double(*c[i]))});
      }
      r.error = e;
    }
    return r;
  }

 private:
  static Point_2<FT> project(const Point_3<FT>& p, int axis) {
    const FT* c[3] = {&p.x, &p.y, &p.z};
    return Point_2<FT>{*c[(axis + 1) % 3], *c[(axis + 2) % 3]};
  }
  static std::optional<Point> divided(const Homogeneous_3<FT>& h, Implicit_point_kind kind) {
    const Certified_sign w = K::compare_ft(h.w, FT(0));
    if (!certainly(w, Certified_sign::positive) && !certainly(w, Certified_sign::negative)) return std::nullopt;
    return Point{Point_3<FT>{FT(h.x / h.w), FT(h.y / h.w), FT(h.z / h.w)}, kind};
  }
};

}  // namespace relgeo::internal
