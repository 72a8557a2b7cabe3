// relgeo/kernel/internal/implicit_staged.h — exact predicates on implicit
// points of double inputs at floating-point speed (Filtered_exact_kernel).
//
// A point keeps its defining doubles and, computed once when it is built,
// its homogeneous coordinates with a bound on their rounding error
// (filtered_value.h). Each predicate tries those error-bounded coordinates
// first (no recomputation: a few dozen flops), then the generic stages of
// filtered_predicate.h on the defining doubles: intervals, floating-point
// expansions, GMP integers. The formulas (implicit_coordinates.h) are
// homogeneous polynomials with integer coefficients, as those stages
// require. The later stages run in the default floating-point environment
// whatever the caller set.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>

#include "relgeo/core/dyadic.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/interval.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/kernel/implicit_point.h"
#include "relgeo/kernel/internal/exact_implicit_coordinates.h"
#include "relgeo/kernel/internal/expansion_orientation_3.h"
#include "relgeo/kernel/internal/filtered_predicate.h"
#include "relgeo/kernel/internal/implicit_enclosed.h"
#include "relgeo/kernel/internal/implicit_predicates.h"
#include "relgeo/kernel/internal/lpi_filter.h"

namespace relgeo::internal {

/// An Interval containing an expansion's value (for approximate_from_enclosure).
inline Interval enclosure_interval(const Dynamic_expansion& e) {
  Interval sum(0.0);
  for (const double c : e) sum = sum + Interval(c);
  return sum;
}

/// Number of defining points of each kind.
constexpr int defining_point_count(Implicit_point_kind kind) {
  return kind == Implicit_point_kind::explicit_point ? 1 : (kind == Implicit_point_kind::lpi ? 5 : 9);
}

/// An implicit point of double inputs with its first-stage coordinates.
/// 128 bytes: an explicit point (most points of a mesh) is its filter, whose
/// values are its coordinates exactly; the 5 or 9 defining points of an LPI
/// or TPI point are stored once, shared by the copies.
struct Staged_implicit_point {
  Homogeneous_3<Filtered_value<double>> filter;
  Implicit_point_kind kind = Implicit_point_kind::explicit_point;
  /// No NaN or infinity among its defining doubles (LPI and TPI points are
  /// built from finite ones only); predicates on a point that is not answer
  /// `uncertain`, even where they would not read the bad coordinate.
  bool finite = true;
  std::shared_ptr<const std::array<Point_3<double>, 9>> defining;  ///< null for an explicit point

  /// The i-th defining point, i < defining_point_count(kind) (the point
  /// itself when explicit).
  Point_3<double> primitive(int i) const {
    if (kind == Implicit_point_kind::explicit_point) return {filter.x.value, filter.y.value, filter.z.value};
    return (*defining)[i];
  }
};

/// A coordinate of p that its construction makes exactly one of its
/// defining doubles: every coordinate of an explicit point; coordinate
/// `axis` of an LPI point when the line's two points share it (so does the
/// whole line) or the plane's three do (the plane is axis = c); of a TPI
/// point when one plane's three points share it. A built LPI or TPI point
/// has W != 0, so its line and planes are proper ones. These coordinates are
/// where the filters fail most: on parts with axis-aligned faces and edges
/// (CAD models), the points of one face or edge agree in them, and proving
/// two coordinates equal takes the exact stages. Call it in the default
/// floating-point environment (under DAZ, distinct subnormals compare equal).
inline std::optional<double> exact_coordinate(const Staged_implicit_point& p, int axis) {
  const auto shared = [axis](const Point_3<double>* v, int count) -> std::optional<double> {
    for (int i = 1; i < count; ++i)
      if (!(coordinate(v[i], axis) == coordinate(v[0], axis))) return std::nullopt;
    return coordinate(v[0], axis);
  };
  switch (p.kind) {
    case Implicit_point_kind::explicit_point:
      return p.filter[axis].value;
    case Implicit_point_kind::lpi: {
      const Point_3<double>* v = p.defining->data();
      if (const auto on_line = shared(v, 2)) return on_line;
      return shared(v + 2, 3);
    }
    default: {
      const Point_3<double>* v = p.defining->data();
      for (int plane = 0; plane < 3; ++plane)
        if (const auto on_plane = shared(v + 3 * plane, 3)) return on_plane;
      return std::nullopt;
    }
  }
}

/// Whether the points' coordinates `axis` are all known exactly
/// (exact_coordinate) and equal: the points lie on one plane axis = c. In
/// the default floating-point environment.
template <std::size_t N>
bool share_exact_coordinate(const std::array<const Staged_implicit_point*, N>& points, int axis) {
  const std::optional<double> first = exact_coordinate(*points[0], axis);
  if (!first) return false;
  for (std::size_t i = 1; i < N; ++i) {
    const std::optional<double> c = exact_coordinate(*points[i], axis);
    if (!c || !(*c == *first)) return false;
  }
  return true;
}

/// Degree in the input coordinates of a point's homogeneous coordinates
/// (X, Y, Z; W has one less).
constexpr int homogeneous_degree(Implicit_point_kind kind) {
  return kind == Implicit_point_kind::explicit_point ? 1 : (kind == Implicit_point_kind::lpi ? 4 : 7);
}

/// Homogeneous coordinates of a point in NT, from its defining doubles
/// converted by `to_nt`.
template <class NT, class Convert>
Homogeneous_3<NT> homogeneous_coordinates(const Staged_implicit_point& p, const Convert& to_nt) {
  const auto point = [&](int i) {
    const Point_3<double> v = p.primitive(i);
    return Point_3<NT>{to_nt(v.x), to_nt(v.y), to_nt(v.z)};
  };
  switch (p.kind) {
    case Implicit_point_kind::explicit_point: return explicit_coordinates(point(0));
    case Implicit_point_kind::lpi: return lpi_coordinates(point(0), point(1), point(2), point(3), point(4));
    default: {
      std::array<Point_3<NT>, 9> v;
      for (int i = 0; i < 9; ++i) v[i] = point(i);
      return tpi_coordinates(v);
    }
  }
}

/// The defining doubles of several points (the inputs of the generic
/// stages) and the degree of the predicates on them: every value the
/// formulas form is a polynomial of degree at most the sum of the points'
/// homogeneous degrees.
template <std::size_t N>
class Defining_doubles {
 public:
  explicit Defining_doubles(const std::array<const Staged_implicit_point*, N>& points) {
    for (const auto* p : points) {
      degree_ += homogeneous_degree(p->kind);
      has_tpi_ = has_tpi_ || p->kind == Implicit_point_kind::tpi;
      for (int i = 0; i < defining_point_count(p->kind); ++i) {
        const Point_3<double> d = p->primitive(i);
        for (double v : {d.x, d.y, d.z}) values_[count_++] = v;
      }
    }
  }
  std::span<const double> values() const { return {values_.data(), count_}; }
  int degree() const { return degree_; }
  /// Whether expansions are worth trying before GMP. Measured on the
  /// soundness families (`relgeo_intersection_benchmark
  /// --benchmark_filter=exact_stage`, each exact stage alone): on LPI points
  /// of degree 7 expansions take 0.46-1.05 of GMP's time; at degrees 10-13
  /// 1.4x, with TPI points 1.9x, on the random mix (degrees to 28) 4x.
  bool expansions_worthwhile() const { return degree_ <= 9 && !has_tpi_; }

 private:
  std::array<double, 27 * N> values_{};
  std::size_t count_ = 0;
  int degree_ = 0;
  bool has_tpi_ = false;
};

/// The formula `sign` on the points' homogeneous coordinates, as the
/// generic stages evaluate it (`to_nt` converts one defining double).
template <std::size_t N, class Sign>
auto implicit_formula(const std::array<const Staged_implicit_point*, N>& points, const Sign& sign) {
  return [&points, &sign](const auto& to_nt) {
    using NT = std::decay_t<decltype(to_nt(0.0))>;
    std::array<Homogeneous_3<NT>, N> coordinates;
    std::array<const Homogeneous_3<NT>*, N> pointers;
    for (std::size_t i = 0; i < N; ++i) {
      coordinates[i] = homogeneous_coordinates<NT>(*points[i], to_nt);
      pointers[i] = &coordinates[i];
    }
    return sign(pointers);
  };
}

/// Runs a predicate `sign(array of homogeneous pointers)` through the
/// stages on the points given. When the first stage cannot decide,
/// `known_zero()` (in the default environment) may prove the sign zero from
/// how the points were built, before the exact stages.
///
/// A point with a NaN or an infinity among its defining doubles (only an
/// explicit point can hold one) gives `uncertain`, before any stage: the
/// later stages would decode the bits of a NaN or an infinity as a finite
/// number, and the first would answer where the bad coordinate is not read
/// (a projection dropping it, a comparison decided before it).
template <std::size_t N, class Sign, class Known_zero = bool (*)()>
Certified_sign staged_sign(
    const std::array<const Staged_implicit_point*, N>& points, const Sign& sign,
    const Known_zero& known_zero = [] { return false; }) {
  std::array<const Homogeneous_3<Filtered_value<double>>*, N> filters;
  bool finite = true;
  for (std::size_t i = 0; i < N; ++i) filters[i] = &points[i]->filter, finite = finite & points[i]->finite;
  if (!finite) [[unlikely]]
    return Certified_sign::uncertain;
  const Certified_sign first = in_default_fp_environment([&] { return sign(filters); });
  if (is_certain(first)) [[likely]]
    return first;
  return call_in_default_fp_environment([&] {
    if (known_zero()) return Certified_sign::zero;
    const Defining_doubles<N> inputs(points);
    return filtered_exact_sign(inputs.values(), inputs.degree(), inputs.expansions_worthwhile(),
                               implicit_formula(points, sign))
        .first;
  });
}

/// Policy of Implicit_kernel_base for Filtered_exact_kernel.
struct Staged_implicit_policy {
  using Explicit = Point_3<double>;
  using Point = Staged_implicit_point;

  static Point make(const Explicit& p) {
    Point r;
    r.filter = explicit_coordinates(Point_3<Filtered_value<double>>{p.x, p.y, p.z});
    r.finite = all_finite(p.x, p.y, p.z);  // the same in every environment (DAZ reads a subnormal as 0: finite)
    return r;
  }
  static std::optional<Point> lpi(const Explicit& p, const Explicit& q, const Explicit& r, const Explicit& s,
                                  const Explicit& t) {
    return built(Implicit_point_kind::lpi, std::array<Explicit, 5>{p, q, r, s, t});
  }
  static std::optional<Point> tpi(const std::array<Explicit, 9>& v) { return built(Implicit_point_kind::tpi, v); }

  /// Zero without the exact stages when the four points share an exactly
  /// known coordinate (one plane axis = c: a face of an axis-aligned part).
  static Certified_sign orientation_3(const Point& a, const Point& b, const Point& c, const Point& d) {
    const std::array<const Point*, 4> points{&a, &b, &c, &d};
    return staged_sign(
        points, [](const auto& h) { return orientation_3_sign(h); },
        [&points] {
          return share_exact_coordinate(points, 0) || share_exact_coordinate(points, 1) ||
                 share_exact_coordinate(points, 2);
        });
  }
  /// orientation_3 of explicit a, b, c and any d (the common query: a point
  /// against an input triangle's plane) without building a, b, c first.
  static Certified_sign orientation_3(const Explicit& a, const Explicit& b, const Explicit& c, const Point& d) {
    if (!(all_finite(a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z) & d.finite)) [[unlikely]]
      return Certified_sign::uncertain;
    const Certified_sign first = in_default_fp_environment([&] {
      return orientation_3_filter(a, b, c, d.filter).sign() * sign_of_w(d.filter);
    });
    if (is_certain(first)) [[likely]]
      return first;
    return orientation_3(make(a), make(b), make(c), d);
  }
  /// Zero without the exact stages when the three points share an exactly
  /// known coordinate that the projection keeps (one line in it).
  static Certified_sign orientation_2(const Point& a, const Point& b, const Point& c, int axis) {
    const std::array<const Point*, 3> points{&a, &b, &c};
    return staged_sign(
        points, [axis](const auto& h) { return orientation_2_sign(h, axis); },
        [&points, axis] {
          return share_exact_coordinate(points, (axis + 1) % 3) || share_exact_coordinate(points, (axis + 2) % 3);
        });
  }
  /// The filter on all three coordinates; when it cannot decide, one
  /// coordinate at a time (compare_coordinate).
  static Certified_sign compare_xyz(const Point& a, const Point& b) {
    if (!(a.finite & b.finite)) [[unlikely]]
      return Certified_sign::uncertain;
    const Certified_sign first = in_default_fp_environment([&] { return compare_xyz_sign(a.filter, b.filter); });
    if (is_certain(first)) [[likely]]
      return first;
    return call_in_default_fp_environment([&] {
      for (int axis = 0; axis < 3; ++axis) {
        const Certified_sign s = compare_coordinate(a, b, axis);
        if (!certainly(s, Certified_sign::zero)) return s;
      }
      return Certified_sign::zero;
    });
  }
  /// The exact rational coordinates (GMP; the filters are not used).
  static std::array<mpq_class, 3> exact_coordinates(const Point& a) {
    switch (a.kind) {
      case Implicit_point_kind::explicit_point:
        return {exact_rational(a.filter.x.value), exact_rational(a.filter.y.value), exact_rational(a.filter.z.value)};
      case Implicit_point_kind::lpi:
        return Exact_implicit_coordinates::lpi(std::span<const Point_3<double>, 5>(a.defining->data(), 5));
      default:
        return Exact_implicit_coordinates::tpi(*a.defining);
    }
  }

  /// Doubles within a few ulps: from the filter when its enclosure is within
  /// 4 ulps of its midpoint, else from intervals recomputed from the defining
  /// doubles (an LPI point also from its two orientations), else from exact
  /// expansions of the homogeneous coordinates (when the generic predicates
  /// would use them), else the exact coordinates rounded once (at most half
  /// an ulp).
  static Approximate_point_3 approximate(const Point& a) {
    return in_default_fp_environment([&] {
      if (a.kind == Implicit_point_kind::explicit_point) return Approximate_point_3{a.primitive(0), 0.0};
      const auto close = [](const Approximate_point_3& x) {
        const double scale = std::max({std::abs(x.point.x), std::abs(x.point.y), std::abs(x.point.z)});
        return x.error <= 0x1p-50 * scale;
      };
      const Approximate_point_3 fast = approximate_from_enclosure(a.filter);
      if (close(fast)) return fast;
      if (a.kind == Implicit_point_kind::lpi) {
        if (const Approximate_point_3 on_line = approximate_lpi_on_its_line(a); close(on_line)) return on_line;
        if (const Approximate_point_3 on_line = approximate_lpi_by_orientations(a); close(on_line)) return on_line;
      }
      const Approximate_point_3 interval = approximate_from_enclosure(
          homogeneous_coordinates<Interval>(a, [](double v) { return Interval(v); }));
      if (close(interval)) return interval;
      if (const Approximate_point_3 e = approximate_by_expansions(a); close(e)) return e;
      const std::array<mpq_class, 3> c = exact_coordinates(a);
      Approximate_point_3 r;
      double error = 0;
      double* out[3] = {&r.point.x, &r.point.y, &r.point.z};
      for (int axis = 0; axis < 3; ++axis) {
        *out[axis] = round_rational<double>(c[axis], Rounding::to_nearest);
        error = std::max({error, sub_up(upper_double(c[axis]), *out[axis]), sub_up(*out[axis], lower_double(c[axis]))});
      }
      r.error = error;
      return r;
    });
  }

 private:
  // One coordinate of a and b (finite points; in the default environment).
  // Two coordinates known exactly (exact_coordinate) compare as doubles; a
  // coordinate known on one side enters the stages as that of an explicit
  // point, so their formula is of the other point's degree alone.
  static Certified_sign compare_coordinate(const Point& a, const Point& b, int axis) {
    const std::optional<double> known_a = exact_coordinate(a, axis), known_b = exact_coordinate(b, axis);
    if (known_a && known_b)
      return *known_a < *known_b   ? Certified_sign::negative
             : *known_b < *known_a ? Certified_sign::positive
                                   : Certified_sign::zero;
    const auto stand_in = [axis](double c) {
      return make({axis == 0 ? c : 0.0, axis == 1 ? c : 0.0, axis == 2 ? c : 0.0});
    };
    const Point ea = known_a ? stand_in(*known_a) : Point{}, eb = known_b ? stand_in(*known_b) : Point{};
    return staged_sign(std::array<const Point*, 2>{known_a ? &ea : &a, known_b ? &eb : &b},
                       [axis](const auto& h) { return compare_coordinate_sign(*h[0], *h[1], axis); });
  }
  // An LPI point as p + (lambda / W) (q - p) in intervals. Its enclosure is
  // an ulp or two of the point wide when the step from p is short against
  // the coordinates (an edge of a mesh against its position), where the
  // quotients X / W of the homogeneous form carry the relative error of a
  // degree-4 polynomial and are rarely close enough.
  static Approximate_point_3 approximate_lpi_on_its_line(const Point& a) {
    std::array<Point_3<Interval>, 5> v;
    for (int i = 0; i < 5; ++i) {
      const Point_3<double> d = a.primitive(i);
      v[i] = {Interval(d.x), Interval(d.y), Interval(d.z)};
    }
    const auto [direction, w, lambda] = lpi_parts(v[0], v[1], v[2], v[3], v[4]);
    if (!(w.inf() > 0 || w.sup() < 0)) return {};
    const Interval step = lambda / w;
    return approximate_from_enclosure(Homogeneous_3<Interval>{v[0].x + step * direction.x,
                                                              v[0].y + step * direction.y,
                                                              v[0].z + step * direction.z, Interval(1.0), true});
  }
  // The LPI point of the line through p, q and the plane through r, s, t as
  // p + (O(p) / (O(p) - O(q))) (q - p) (or the same from q), with O(x) the orientation_3
  // determinant of (r, s, t, x), each enclosed a few ulps wide by the
  // compensated step of its expansion stage (expansion_orientation_3.h).
  // p and q lie on either side of the plane, so O(p) - O(q) does not
  // cancel and the step is within a few ulps, where lambda and W in
  // intervals lose bits to cancellation (on the benchmark's gear against its
  // moved copy, 1,192 of the 1,780 new points: within 2^-46 to 2^-49 of
  // their size, not the 2^-50 asked for, and GMP-free expansions of X, Y,
  // Z, W cost microseconds each).
  static Approximate_point_3 approximate_lpi_by_orientations(const Point& a) {
    const Point_3<double> p = a.primitive(0), q = a.primitive(1), r = a.primitive(2), s = a.primitive(3),
                          t = a.primitive(4);
    const auto against_plane = [&](const Point_3<double>& x) {
      return orientation_3_enclosure({r.x, r.y, r.z, s.x, s.y, s.z, t.x, t.y, t.z, x.x, x.y, x.z});
    };
    const std::optional<Interval> at_p = against_plane(p), at_q = against_plane(q);
    if (!at_p || !at_q) return {};
    // From the end nearer the plane: the step is at most about 1/2, and so
    // is its error's share of the point's.
    const bool from_p = std::abs(at_p->inf() + at_p->sup()) <= std::abs(at_q->inf() + at_q->sup());
    const Point_3<double>& from = from_p ? p : q;
    const Point_3<double>& to = from_p ? q : p;
    const Interval w = from_p ? *at_p - *at_q : *at_q - *at_p;
    if (!(w.inf() > 0 || w.sup() < 0)) return {};
    const Interval step = (from_p ? *at_p : *at_q) / w;
    const auto along = [&step](double a, double b) { return Interval(a) + step * (Interval(b) - Interval(a)); };
    return approximate_from_enclosure(
        Homogeneous_3<Interval>{along(from.x, to.x), along(from.y, to.y), along(from.z, to.z), Interval(1.0), true});
  }
  // X, Y, Z, W exact in expansions, each enclosed by the outward-rounded sum
  // of its components (a few ulps wide), divided in intervals. The inputs
  // were scaled by 2^shift, and so was X / W: the scaling is undone when
  // that is exact, else the answer is "not close" (GMP decides).
  static Approximate_point_3 approximate_by_expansions(const Point& a) {
    const Defining_doubles<1> inputs(std::array<const Point*, 1>{&a});
    if (!inputs.expansions_worthwhile()) return {};
    const Expansion_scaling scaled(inputs.values(), inputs.degree());
    if (!scaled.exact()) return {};
    Approximate_point_3 r = approximate_from_enclosure(homogeneous_coordinates<Dynamic_expansion>(a, scaled));
    double* coordinate[4] = {&r.point.x, &r.point.y, &r.point.z, &r.error};
    for (double* c : coordinate) {
      const double unscaled = std::ldexp(*c, -scaled.shift());
      if (std::ldexp(unscaled, scaled.shift()) != *c) return {};
      *c = unscaled;
    }
    return r;
  }
  template <std::size_t N>
  static std::optional<Point> built(Implicit_point_kind kind, const std::array<Explicit, N>& v) {
    for (std::size_t i = 0; i < N; ++i)
      if (!all_finite(v[i].x, v[i].y, v[i].z)) return std::nullopt;
    Point r;
    r.kind = kind;
    auto defining = std::make_shared<std::array<Point_3<double>, 9>>();
    std::copy(v.begin(), v.end(), defining->begin());
    r.defining = std::move(defining);
    // W must be nonzero: decided on the error-bounded W when it can be,
    // through the later stages otherwise.
    const Certified_sign w = in_default_fp_environment([&] {
      if constexpr (N == 5) r.filter = lpi_filter(v[0], v[1], v[2], v[3], v[4]);
      else r.filter = homogeneous_coordinates<Filtered_value<double>>(r, [](double x) { return Filtered_value<double>(x); });
      return certified_sign_of(r.filter.w);
    });
    if (certainly(w, Certified_sign::positive) || certainly(w, Certified_sign::negative)) [[likely]]
      return r;
    if (certainly(w, Certified_sign::zero)) return std::nullopt;
    const Certified_sign exact = staged_sign(std::array<const Point*, 1>{&r}, [](const auto& h) {
      return certified_sign_of(h[0]->w);
    });
    if (certainly(exact, Certified_sign::zero)) return std::nullopt;
    return r;
  }
};

}  // namespace relgeo::internal
