// relgeo/kernel/internal/implicit_cgal.h — implicit points of a CGAL kernel
// with exact constructions (Epeck): the LPI/TPI point constructed in the
// kernel's own lazy exact number type (a CGAL point whose coordinates are
// lazy exact quotients), the predicates CGAL's own filtered exact ones on it.
// This is how CGAL's corefinement represents its new vertices, so relgeo's
// Booleans under Cgal_kernel<Epeck> compare CGAL's arithmetic with relgeo's
// on the same algorithm.
#pragma once

#include <CGAL/number_utils.h>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "relgeo/core/fp_environment.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/core/rounding.h"
#include "relgeo/kernel/implicit_point.h"
#include "relgeo/kernel/internal/implicit_coordinates.h"

namespace relgeo::internal {

/// Policy of Implicit_kernel_base for relgeo kernel RK = Cgal_kernel<CK>
/// (CK with exact constructions). Only RK's predicate functors are used, in
/// member functions: RK may be incomplete where the policy is named.
template <class RK, class CK>
struct Cgal_implicit_policy : Constructed_point_orientations<Cgal_implicit_policy<RK, CK>, RK> {
  friend struct Constructed_point_orientations<Cgal_implicit_policy, RK>;
  using FT = typename CK::FT;
  using Explicit = typename CK::Point_3;
  struct Point {
    Explicit point;
    Implicit_point_kind kind = Implicit_point_kind::explicit_point;
  };

  static Point make(const Explicit& p) { return {p, Implicit_point_kind::explicit_point}; }
  // Lazy numbers keep interval approximations: built, like CGAL's filters
  // evaluated, in the default environment.
  static std::optional<Point> lpi(const Explicit& p, const Explicit& q, const Explicit& r, const Explicit& s,
                                  const Explicit& t) {
    return in_default_environment(
        [&] { return divided(lpi_coordinates(in(p), in(q), in(r), in(s), in(t)), Implicit_point_kind::lpi); });
  }
  static std::optional<Point> tpi(const std::array<Explicit, 9>& v) {
    return in_default_environment([&] {
      std::array<Point_3<FT>, 9> w;
      for (int i = 0; i < 9; ++i) w[i] = in(v[i]);
      return divided(tpi_coordinates(w), Implicit_point_kind::tpi);
    });
  }
  static Certified_sign compare_xyz(const Point& a, const Point& b) {
    return in_default_environment(
        [&] { return static_cast<Certified_sign>(static_cast<int>(typename CK::Compare_xyz_3()(a.point, b.point))); });
  }
  /// The nearest doubles of the exact coordinates when CGAL's exact type is
  /// a GMP rational (Epeck's), with error at most half a unit in the last
  /// place; otherwise the midpoint of CGAL's enclosure, refined to the exact
  /// value's when wider than a few units in the last place.
  static Approximate_point_3 approximate(const Point& a) {
    const Default_fp_environment environment;
    Approximate_point_3 r;
    double e = 0;
    double* out[3] = {&r.point.x, &r.point.y, &r.point.z};
    const FT c[3] = {a.point.x(), a.point.y(), a.point.z()};
    for (int i = 0; i < 3; ++i) {
      double mid, lo, hi;
      if constexpr (requires { mpq_class(c[i].exact().backend().data()); }) {
        const mpq_class q(c[i].exact().backend().data());
        mid = nearest_double(q), lo = lower_double(q), hi = upper_double(q);
      } else {
        std::pair<double, double> iv = CGAL::to_interval(c[i]);
        if (!(iv.second - iv.first <= 4 * 0x1p-52 * std::max(std::abs(iv.first), std::abs(iv.second)))) {
          if constexpr (requires { c[i].exact(); }) (void)c[i].exact();  // refines the lazy enclosure
          iv = CGAL::to_interval(c[i]);
        }
        lo = iv.first, hi = iv.second;
        mid = lo == hi ? lo : lo + (hi - lo) / 2;
      }
      *out[i] = mid;
      if (!std::isfinite(mid)) e = std::numeric_limits<double>::infinity();
      else e = std::max({e, sub_up(hi, mid), sub_up(mid, lo)});
    }
    r.error = e;
    return r;
  }

 private:
  static Point_3<FT> in(const Explicit& p) { return {p.x(), p.y(), p.z()}; }
  static typename CK::Point_2 project(const Explicit& p, int axis) {
    const FT c[3] = {p.x(), p.y(), p.z()};
    return typename CK::Point_2(c[(axis + 1) % 3], c[(axis + 2) % 3]);
  }
  template <class F>
  static auto in_default_environment(const F& f) {
    if (is_default_fp_environment()) return f();
    const Default_fp_environment environment;
    return f();
  }
  static std::optional<Point> divided(const Homogeneous_3<FT>& h, Implicit_point_kind kind) {
    if (CGAL::sign(h.w) == CGAL::ZERO) return std::nullopt;
    return Point{Explicit(FT(h.x / h.w), FT(h.y / h.w), FT(h.z / h.w)), kind};
  }
};

}  // namespace relgeo::internal
