// relgeo/kernel/internal/kernel_base.h — what relgeo's own kernels share.
//
// A kernel derived from Kernel_base<Derived, FT> supplies:
//   static FT from_double(double)                       — coordinate conversion
//   static Certified_sign compare_ft(const FT&, const FT&)
//   struct Orientation_2, struct Orientation_3          — its certified predicates
// and inherits the point types, point construction, compare_xy_2, the
// coplanar orientation (built on its own Orientation_2, as CGAL's
// coplanar_orientationC3 is) and the simple constructions.
//
// Constructions compute in FT. Over intervals they are enclosures only in
// the default floating-point environment (outward rounding from round to
// nearest: core/interval.h), so they run in it whatever the caller set;
// over floating-point types they are plain floating point in the caller's
// environment, and over exact or MPFR types the environment plays no part.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <span>

#include "relgeo/core/errors.h"
#include "relgeo/core/certified_sign.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/kernel/internal/semi_static_filter.h"
#include "relgeo/kernel/point.h"

namespace relgeo::internal {

template <class Derived, class FT_>
class Kernel_base {
 public:
  using FT = FT_;
  using Point_2 = relgeo::Point_2<FT>;
  using Point_3 = relgeo::Point_3<FT>;

  /// Point_2 from double coordinates (rounded to FT as FT's conversion does).
  struct Construct_point_2 {
    Point_2 operator()(double x, double y) const {
      return Point_2{Derived::from_double(x), Derived::from_double(y)};
    }
  };
  /// Point_3 from double coordinates.
  struct Construct_point_3 {
    Point_3 operator()(double x, double y, double z) const {
      return Point_3{Derived::from_double(x), Derived::from_double(y), Derived::from_double(z)};
    }
  };

  /// Lexicographic comparison of (x, y): negative when p < q.
  struct Compare_xy_2 {
    Certified_sign operator()(const Point_2& p, const Point_2& q) const {
      if (refuses(p) || refuses(q)) return Certified_sign::uncertain;
      const Certified_sign sx = Derived::compare_ft(p.x, q.x);
      return certainly(sx, Certified_sign::zero) ? Derived::compare_ft(p.y, q.y) : sx;
    }
  };

  /// Orientation of coplanar points inside their plane (CGAL's
  /// Coplanar_orientation_3): the projection onto the first of the xy, yz, xz
  /// planes in which p, q, r are not collinear.
  ///  * (p, q, r): `zero` iff p, q, r are collinear, otherwise a sign that is
  ///    consistent for all triples of the plane;
  ///  * (p, q, r, s): `positive` when s and r lie on the same side of line pq,
  ///    `negative` on opposite sides, `zero` when p, q, s are collinear.
  ///    \pre p, q, r are not collinear (throws Precondition_violation).
  /// `uncertain` as soon as a projected orientation it depends on is.
  struct Coplanar_orientation_3 {
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r) const {
      if (refuses(p) || refuses(q) || refuses(r)) return Certified_sign::uncertain;
      for (int plane = 0; plane < 3; ++plane) {
        const Certified_sign o = orient(plane, p, q, r);
        if (!certainly(o, Certified_sign::zero) || plane == 2) return o;
      }
      return Certified_sign::zero;  // unreachable
    }
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r,
                              const Point_3& s) const {
      if (refuses(p) || refuses(q) || refuses(r) || refuses(s)) return Certified_sign::uncertain;
      for (int plane = 0; plane < 3; ++plane) {
        const Certified_sign o = orient(plane, p, q, r);
        if (!is_certain(o)) return o;
        if (!certainly(o, Certified_sign::zero)) return o * orient(plane, p, q, s);
      }
      throw Precondition_violation("coplanar_orientation(p,q,r,s): p, q, r are collinear");
    }

   private:
    static Point_2 project(int plane, const Point_3& p) {
      switch (plane) {
        case 0: return Point_2{p.x, p.y};
        case 1: return Point_2{p.y, p.z};
        default: return Point_2{p.x, p.z};
      }
    }
    static Certified_sign orient(int plane, const Point_3& p, const Point_3& q, const Point_3& r) {
      return typename Derived::Orientation_2{}(project(plane, p), project(plane, q),
                                               project(plane, r));
    }
  };

  /// Midpoint, computed in FT ((p + q) / 2 coordinate-wise).
  struct Construct_midpoint_2 {
    Point_2 operator()(const Point_2& p, const Point_2& q) const {
      return in_construction_environment(
          [&] { return Point_2{FT(FT(p.x + q.x) / FT(2)), FT(FT(p.y + q.y) / FT(2))}; });
    }
  };
  struct Construct_midpoint_3 {
    Point_3 operator()(const Point_3& p, const Point_3& q) const {
      return in_construction_environment([&] {
        return Point_3{FT(FT(p.x + q.x) / FT(2)), FT(FT(p.y + q.y) / FT(2)), FT(FT(p.z + q.z) / FT(2))};
      });
    }
  };

  /// Affine combination sum w_i p_i of points with weights summing to 1 (the
  /// subdivision masks). \pre points.size() == weights.size() > 0.
  struct Construct_barycenter_3 {
    Point_3 operator()(std::span<const Point_3> points, std::span<const FT> weights) const {
      if (points.size() != weights.size() || points.empty())
        throw Precondition_violation("construct_barycenter_3: sizes differ or are zero");
      return in_construction_environment([&] {
        Point_3 r{FT(0), FT(0), FT(0)};
        for (std::size_t i = 0; i < points.size(); ++i) {
          r.x = FT(r.x + FT(weights[i] * points[i].x));
          r.y = FT(r.y + FT(weights[i] * points[i].y));
          r.z = FT(r.z + FT(weights[i] * points[i].z));
        }
        return r;
      });
    }
  };

  /// Squared Euclidean distance, computed in FT.
  struct Compute_squared_distance_2 {
    FT operator()(const Point_2& p, const Point_2& q) const {
      return in_construction_environment([&] {
        const FT dx = p.x - q.x, dy = p.y - q.y;
        return FT(FT(dx * dx) + FT(dy * dy));
      });
    }
  };
  struct Compute_squared_distance_3 {
    FT operator()(const Point_3& p, const Point_3& q) const {
      return in_construction_environment([&] {
        const FT dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
        return FT(FT(FT(dx * dx) + FT(dy * dy)) + FT(dz * dz));
      });
    }
  };

  Construct_point_2 construct_point_2_object() const { return {}; }

  /// f() in the environment FT's constructions need (see the file comment).
  template <class F>
  static auto in_construction_environment(const F& f) {
    if constexpr (is_interval_v<FT>) return in_default_fp_environment(f);
    else return f();
  }

  /// Certified kernels give no definite answer about points with a NaN or
  /// infinite coordinate, even where a projection or the first coordinate of a
  /// lexicographic comparison would not look at it (naive kernels just answer).
  static bool refuses(const Point_2& p) {
    if constexpr (Derived::is_certified) return !(is_finite_number(p.x) && is_finite_number(p.y));
    else return false;
  }
  static bool refuses(const Point_3& p) {
    if constexpr (Derived::is_certified)
      return !(is_finite_number(p.x) && is_finite_number(p.y) && is_finite_number(p.z));
    else return false;
  }
  Construct_point_3 construct_point_3_object() const { return {}; }
  Compare_xy_2 compare_xy_2_object() const { return {}; }
  Coplanar_orientation_3 coplanar_orientation_3_object() const { return {}; }
  Construct_midpoint_2 construct_midpoint_2_object() const { return {}; }
  Construct_midpoint_3 construct_midpoint_3_object() const { return {}; }
  Construct_barycenter_3 construct_barycenter_3_object() const { return {}; }
  Compute_squared_distance_2 compute_squared_distance_2_object() const { return {}; }
  Compute_squared_distance_3 compute_squared_distance_3_object() const { return {}; }
};

/// What a kernel computing its predicates in the floating-point type T states
/// about itself: T's unit roundoff, no exact predicates or constructions, and
/// the forward-error constants of the orientation determinants in T (see
/// semi_static_filter.h: the naive kernel may be wrong within them, the
/// fail-safe kernel answers `uncertain` within them).
template <class T>
struct Floating_point_kernel_constants {
  static constexpr double unit_roundoff = static_cast<double>(unit_roundoff_v<T>);
  static constexpr bool has_exact_predicates = false;
  static constexpr bool has_exact_constructions = false;
  static constexpr std::optional<double> orientation_2_error_bound =
      round_up_to_double(Orientation_filter_constants<T>::eps_2);
  static constexpr std::optional<double> orientation_3_error_bound =
      round_up_to_double(Orientation_filter_constants<T>::eps_3);
};

}  // namespace relgeo::internal
