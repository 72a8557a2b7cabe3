// relgeo/kernel/internal/implicit_staged.h — exact predicates on implicit
// points of double inputs at floating-point speed (Filtered_exact_kernel).
//
// A point keeps its defining doubles and, computed once when it is built,
// its homogeneous coordinates with a bound on their rounding error
// (filtered_value.h).
// Each predicate tries
//  1. the error-bounded coordinates (no recomputation: a few dozen flops),
//  2. intervals recomputed from the defining doubles (tighter),
//  3. GMP integers: every defining double scaled by one power of two to an
//     integer (the formulas are homogeneous, so signs are unchanged), then
//     the same formulas exactly,
// and returns the first definite answer, which is the exact sign. The later
// stages run in the default floating-point environment whatever the caller set.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <optional>
#include <span>

#include "relgeo/core/dyadic.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/interval.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/kernel/implicit_point.h"
#include "relgeo/kernel/internal/implicit_enclosed.h"
#include "relgeo/kernel/internal/implicit_predicates.h"
#include "relgeo/kernel/internal/lpi_filter.h"

namespace relgeo::internal {

/// Number of defining points of each kind.
constexpr int defining_point_count(Implicit_point_kind kind) {
  return kind == Implicit_point_kind::explicit_point ? 1 : (kind == Implicit_point_kind::lpi ? 5 : 9);
}

/// An implicit point of double inputs with its first-stage coordinates.
struct Staged_implicit_point {
  Homogeneous_3<Filtered_value<double>> filter;
  Implicit_point_kind kind = Implicit_point_kind::explicit_point;
  std::array<Point_3<double>, 9> primitives;  ///< the first defining_point_count(kind) are set
};

/// Homogeneous coordinates of a point in NT, from its defining doubles
/// converted by `to_nt`.
template <class NT, class Convert>
Homogeneous_3<NT> homogeneous_coordinates(const Staged_implicit_point& p, const Convert& to_nt) {
  const auto point = [&](int i) {
    const Point_3<double>& v = p.primitives[i];
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

/// The defining doubles of several points as integers scaled by one common
/// power of two (2^-emin, emin the smallest exponent of their binary parts).
class Scaled_integers {
 public:
  template <std::size_t N>
  explicit Scaled_integers(const std::array<const Staged_implicit_point*, N>& points) {
    for (const auto* p : points)
      for (int i = 0; i < defining_point_count(p->kind); ++i)
        for (double v : {p->primitives[i].x, p->primitives[i].y, p->primitives[i].z}) {
          const Binary_parts b = binary_parts(v);
          if (b.mantissa != 0) emin_ = std::min(emin_, b.exponent);
        }
  }
  mpz_class operator()(double v) const {
    const Binary_parts b = binary_parts(v);
    mpz_class z;
    set_mpz(z.get_mpz_t(), b.mantissa);
    if (b.mantissa != 0) mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), static_cast<mp_bitcnt_t>(b.exponent - emin_));
    return z;
  }

 private:
  int emin_ = INT_MAX;
};

/// Runs a predicate `sign(array of homogeneous pointers)` through the
/// stages on the points given.
template <std::size_t N, class Sign>
Certified_sign staged_sign(const std::array<const Staged_implicit_point*, N>& points, const Sign& sign) {
  std::array<const Homogeneous_3<Filtered_value<double>>*, N> filters;
  for (std::size_t i = 0; i < N; ++i) filters[i] = &points[i]->filter;
  const Certified_sign first = in_default_fp_environment([&] { return sign(filters); });
  if (is_certain(first)) [[likely]]
    return first;
  return call_in_default_fp_environment([&] {
    std::array<Homogeneous_3<Interval>, N> intervals;
    std::array<const Homogeneous_3<Interval>*, N> interval_pointers;
    for (std::size_t i = 0; i < N; ++i) {
      intervals[i] = homogeneous_coordinates<Interval>(*points[i], [](double v) { return Interval(v); });
      interval_pointers[i] = &intervals[i];
    }
    const Certified_sign second = sign(interval_pointers);
    if (is_certain(second)) return second;
    const Scaled_integers to_integer(points);
    std::array<Homogeneous_3<mpz_class>, N> exact;
    std::array<const Homogeneous_3<mpz_class>*, N> exact_pointers;
    for (std::size_t i = 0; i < N; ++i) {
      exact[i] = homogeneous_coordinates<mpz_class>(*points[i], to_integer);
      exact_pointers[i] = &exact[i];
    }
    return sign(exact_pointers);
  });
}

/// Policy of Implicit_kernel_base for Filtered_exact_kernel.
struct Staged_implicit_policy {
  using Explicit = Point_3<double>;
  using Point = Staged_implicit_point;

  static Point make(const Explicit& p) {
    Point r;
    r.primitives[0] = p;
    r.filter = explicit_coordinates(Point_3<Filtered_value<double>>{p.x, p.y, p.z});
    return r;
  }
  static std::optional<Point> lpi(const Explicit& p, const Explicit& q, const Explicit& r, const Explicit& s,
                                  const Explicit& t) {
    return built(Implicit_point_kind::lpi, std::array<Explicit, 5>{p, q, r, s, t});
  }
  static std::optional<Point> tpi(const std::array<Explicit, 9>& v) { return built(Implicit_point_kind::tpi, v); }

  static Certified_sign orientation_3(const Point& a, const Point& b, const Point& c, const Point& d) {
    return staged_sign(std::array<const Point*, 4>{&a, &b, &c, &d}, [](const auto& h) {
      return orientation_3_sign(h);
    });
  }
  /// orientation_3 of explicit a, b, c and any d (the common query: a point
  /// against an input triangle's plane) without building a, b, c first.
  static Certified_sign orientation_3(const Explicit& a, const Explicit& b, const Explicit& c, const Point& d) {
    const Certified_sign first = in_default_fp_environment([&] {
      return orientation_3_filter(a, b, c, d.filter).sign() * sign_of_w(d.filter);
    });
    if (is_certain(first)) [[likely]]
      return first;
    return orientation_3(make(a), make(b), make(c), d);
  }
  static Certified_sign orientation_2(const Point& a, const Point& b, const Point& c, int axis) {
    return staged_sign(std::array<const Point*, 3>{&a, &b, &c}, [axis](const auto& h) {
      return orientation_2_sign(h, axis);
    });
  }
  static Certified_sign compare_xyz(const Point& a, const Point& b) {
    return staged_sign(std::array<const Point*, 2>{&a, &b}, [](const auto& h) {
      return compare_xyz_sign(*h[0], *h[1]);
    });
  }
  /// From the error-bounded coordinates; when their W is not certainly
  /// nonzero, the exact rational point rounded to nearest.
  static Approximate_point_3 approximate(const Point& a) {
    return in_default_fp_environment([&] {
      const Approximate_point_3 fast = approximate_from_enclosure(a.filter);
      if (std::isfinite(fast.error)) return fast;
      const std::array<const Point*, 1> one{&a};
      const Scaled_integers to_integer(one);  // the common scale cancels in X / W
      const Homogeneous_3<mpz_class> h = homogeneous_coordinates<mpz_class>(a, to_integer);
      Approximate_point_3 r;
      double error = 0;
      double* out[3] = {&r.point.x, &r.point.y, &r.point.z};
      for (int axis = 0; axis < 3; ++axis) {
        mpq_class c = h.unit ? mpq_class(h[axis]) : mpq_class(h[axis], h.w);
        c.canonicalize();
        *out[axis] = round_rational<double>(c, Rounding::to_nearest);
        error = std::max({error, sub_up(upper_double(c), *out[axis]), sub_up(*out[axis], lower_double(c))});
      }
      r.error = error;
      return r;
    });
  }

 private:
  template <std::size_t N>
  static std::optional<Point> built(Implicit_point_kind kind, const std::array<Explicit, N>& v) {
    Point r;
    r.kind = kind;
    for (std::size_t i = 0; i < N; ++i) {
      if (!all_finite(v[i].x, v[i].y, v[i].z)) return std::nullopt;
      r.primitives[i] = v[i];
    }
    // W must be nonzero: decided on the error-bounded W when it can be,
    // through the later stages otherwise.
    const Certified_sign w = in_default_fp_environment([&] {
      if constexpr (N == 5) r.filter = lpi_filter(v[0], v[1], v[2], v[3], v[4]);
      else r.filter = homogeneous_coordinates<Filtered_value<double>>(r, [](double x) { return Filtered_value<double>(x); });
      return certified_sign_of(r.filter.w);
    });
    if (w == Certified_sign::positive || w == Certified_sign::negative) [[likely]]
      return r;
    if (w == Certified_sign::zero) return std::nullopt;
    const Certified_sign exact = staged_sign(std::array<const Point*, 1>{&r}, [](const auto& h) {
      return certified_sign_of(h[0]->w);
    });
    if (exact == Certified_sign::zero) return std::nullopt;
    return r;
  }
};

}  // namespace relgeo::internal
