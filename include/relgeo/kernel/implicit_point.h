// relgeo/kernel/implicit_point.h — implicit (indirect) points and the
// predicates on them: what a kernel adds to model IntersectionKernel_3.
//
// A Boolean creates vertices where an edge of one mesh crosses a triangle of
// the other (LPI: the line through two points and the plane through three)
// and, in coplanar and three-surface configurations, where three planes meet
// (TPI). Rounding such a point to doubles and testing the rounded point
// breaks exactness. Following Attene ("Indirect predicates for geometric
// constructions", CAD 126, 2020), a kernel instead keeps an implicit point
// by what defines it and evaluates predicates on the exact homogeneous
// coordinates (kernel/internal/implicit_coordinates.h), each kernel in its own
// arithmetic:
//
//  | kernel                 | implicit point holds        | predicates                                  |
//  |------------------------|-----------------------------|---------------------------------------------|
//  | Naive_kernel<T>        | the point rounded to T      | the naive predicates on it (may be wrong)   |
//  | Mpfr_kernel<B>         | the point rounded to B bits | the MPFR predicates on it (may be wrong)    |
//  | Failsafe_kernel<T>     | homogeneous coordinates with | a rounding-error bound in T (filtered_value |
//  |                        | their rounding-error bound  | .h); uncertain when it does not exclude 0   |
//  | Interval_kernel        | interval homogeneous coords | interval arithmetic; uncertain when 0 is in |
//  | Filtered_exact_kernel  | its defining doubles and    | error bound -> intervals -> expansions ->   |
//  |                        | error-bounded coordinates   | GMP integers: always exact                  |
//  | Exact_kernel           | the exact rational point    | exact                                       |
//
// The functors every model provides (fetched through the kernel object):
//  * construct_implicit_point_3_object(): (p) an explicit point; (p, q, r, s, t)
//    the LPI point, (a0, b0, c0, a1, b1, c1, a2, b2, c2) the TPI point, as a
//    std::optional that is empty when the kernel cannot certify that the point
//    exists (line parallel to the plane, dependent planes; exact kernels: only
//    then; naive kernels: when their computed denominator is 0);
//  * implicit_orientation_3_object(): orientation of four points, any mix;
//  * implicit_orientation_2_object(): orientation of three points projected
//    by dropping one axis (kept axes (axis+1) % 3, (axis+2) % 3: the
//    projection whose orientation agrees with a normal of positive component
//    along the dropped axis);
//  * implicit_coplanar_orientation_3_object(): CGAL's coplanar_orientation on
//    implicit points (3 and 4 arguments, the semantics of the explicit one);
//  * compare_xyz_3_object(): lexicographic comparison; `zero` means the same
//    point (two crossings at one geometric point are recognised as one);
//  * approximate_point_3_object(): the nearest doubles it can give, with a
//    bound on the error of each coordinate (infinite for naive kernels,
//    which do not know theirs).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/errors.h"
#include "relgeo/kernel/point.h"

namespace relgeo {

/// What defines a point of an IntersectionKernel_3.
enum class Implicit_point_kind : std::uint8_t {
  explicit_point,  ///< an input point
  lpi,             ///< line through two points x plane through three
  tpi              ///< three planes, each through three points
};

/// A point in doubles with a bound on the error of each coordinate
/// (|exact - point| <= error per coordinate; infinity when unknown).
struct Approximate_point_3 {
  Point_3<double> point;
  double error = std::numeric_limits<double>::infinity();
};

namespace internal {

/// The functors of IntersectionKernel_3, built on a policy that supplies
/// (static): Point, Explicit (the kernel's Point_3), make(Explicit),
/// lpi(5 x Explicit) and tpi(array of 9) as optionals, orientation_3,
/// orientation_2(a, b, c, axis), compare_xyz, approximate, kind.
template <class Policy>
class Implicit_kernel_base {
 public:
  using Implicit_point_3 = typename Policy::Point;
  using Explicit_point_3 = typename Policy::Explicit;

  struct Construct_implicit_point_3 {
    Implicit_point_3 operator()(const Explicit_point_3& p) const { return Policy::make(p); }
    /// The LPI point of the line through p, q and the plane through r, s, t.
    std::optional<Implicit_point_3> operator()(const Explicit_point_3& p, const Explicit_point_3& q,
                                               const Explicit_point_3& r, const Explicit_point_3& s,
                                               const Explicit_point_3& t) const {
      return Policy::lpi(p, q, r, s, t);
    }
    /// The TPI point of the planes (a0, b0, c0), (a1, b1, c1), (a2, b2, c2).
    std::optional<Implicit_point_3> operator()(const Explicit_point_3& a0, const Explicit_point_3& b0,
                                               const Explicit_point_3& c0, const Explicit_point_3& a1,
                                               const Explicit_point_3& b1, const Explicit_point_3& c1,
                                               const Explicit_point_3& a2, const Explicit_point_3& b2,
                                               const Explicit_point_3& c2) const {
      return Policy::tpi(std::array<Explicit_point_3, 9>{a0, b0, c0, a1, b1, c1, a2, b2, c2});
    }
  };

  struct Implicit_orientation_3 {
    Certified_sign operator()(const Implicit_point_3& a, const Implicit_point_3& b, const Implicit_point_3& c,
                              const Implicit_point_3& d) const {
      return Policy::orientation_3(a, b, c, d);
    }
    /// d against the plane of three input points (the common query).
    Certified_sign operator()(const Explicit_point_3& a, const Explicit_point_3& b, const Explicit_point_3& c,
                              const Implicit_point_3& d) const {
      if constexpr (requires { Policy::orientation_3(a, b, c, d); }) return Policy::orientation_3(a, b, c, d);
      else return Policy::orientation_3(Policy::make(a), Policy::make(b), Policy::make(c), d);
    }
  };

  /// \pre 0 <= dropped_axis <= 2 (throws Precondition_violation).
  struct Implicit_orientation_2 {
    Certified_sign operator()(const Implicit_point_3& a, const Implicit_point_3& b, const Implicit_point_3& c,
                              int dropped_axis) const {
      if (dropped_axis < 0 || dropped_axis > 2)
        throw Precondition_violation("implicit_orientation_2: the dropped axis must be 0, 1 or 2");
      return Policy::orientation_2(a, b, c, dropped_axis);
    }
  };

  /// CGAL's Coplanar_orientation_3 on implicit points, projecting onto the
  /// first of the xy, yz, xz planes in which p, q, r are not collinear (as
  /// the explicit one of Kernel_base).
  struct Implicit_coplanar_orientation_3 {
    Certified_sign operator()(const Implicit_point_3& p, const Implicit_point_3& q,
                              const Implicit_point_3& r) const {
      for (int plane = 0; plane < 3; ++plane) {
        const Certified_sign o = in_plane(plane, p, q, r);
        if (!certainly(o, Certified_sign::zero) || plane == 2) return o;
      }
      return Certified_sign::zero;  // unreachable
    }
    /// \pre p, q, r are not collinear (throws Precondition_violation).
    Certified_sign operator()(const Implicit_point_3& p, const Implicit_point_3& q, const Implicit_point_3& r,
                              const Implicit_point_3& s) const {
      for (int plane = 0; plane < 3; ++plane) {
        const Certified_sign o = in_plane(plane, p, q, r);
        if (!is_certain(o)) return o;
        if (!certainly(o, Certified_sign::zero)) return o * in_plane(plane, p, q, s);
      }
      throw Precondition_violation("implicit coplanar_orientation(p,q,r,s): p, q, r are collinear");
    }

   private:
    // xy drops z; yz drops x; xz drops y, whose cyclic projection (z, x) is
    // the mirror of (x, z).
    static Certified_sign in_plane(int plane, const Implicit_point_3& p, const Implicit_point_3& q,
                                   const Implicit_point_3& r) {
      switch (plane) {
        case 0: return Policy::orientation_2(p, q, r, 2);
        case 1: return Policy::orientation_2(p, q, r, 0);
        default: return -Policy::orientation_2(p, q, r, 1);
      }
    }
  };

  struct Compare_xyz_3 {
    Certified_sign operator()(const Implicit_point_3& a, const Implicit_point_3& b) const {
      return Policy::compare_xyz(a, b);
    }
  };

  struct Approximate_implicit_point_3 {
    Approximate_point_3 operator()(const Implicit_point_3& a) const { return Policy::approximate(a); }
  };

  static Implicit_point_kind implicit_kind(const Implicit_point_3& a) { return a.kind; }

  Construct_implicit_point_3 construct_implicit_point_3_object() const { return {}; }
  Implicit_orientation_3 implicit_orientation_3_object() const { return {}; }
  Implicit_orientation_2 implicit_orientation_2_object() const { return {}; }
  Implicit_coplanar_orientation_3 implicit_coplanar_orientation_3_object() const { return {}; }
  Compare_xyz_3 compare_xyz_3_object() const { return {}; }
  Approximate_implicit_point_3 approximate_point_3_object() const { return {}; }
};

/// The orientation predicates of a policy whose implicit points are
/// constructed points (`Point::point`, a point of the predicate kernel PK):
/// PK's own tests on them, in-plane after Policy::project drops `axis`
/// (CRTP base of the policies in internal/implicit_rounded.h and
/// internal/implicit_cgal.h). Member templates: PK and Policy may be
/// incomplete where the base is named.
template <class Policy, class PK>
struct Constructed_point_orientations {
  template <class Point>
  static Certified_sign orientation_3(const Point& a, const Point& b, const Point& c, const Point& d) {
    return typename PK::Orientation_3{}(a.point, b.point, c.point, d.point);
  }
  template <class Point>
  static Certified_sign orientation_2(const Point& a, const Point& b, const Point& c, int axis) {
    return typename PK::Orientation_2{}(Policy::project(a.point, axis), Policy::project(b.point, axis),
                                        Policy::project(c.point, axis));
  }
};

}  // namespace internal
}  // namespace relgeo
