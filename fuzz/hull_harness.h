// fuzz/hull_harness.h — the planar-hull contract under one kernel, shared by
// the translation units of the hull fuzzer (relgeo's kernels, CGAL's).
//
// Input layout (hull_fuzzer.cpp decodes it): byte 0 the kernel, byte 1 the
// algorithm and the prefilter option, then point records (an op byte and its
// operands): a new point of two coordinates (fuzz_support.h's mix of raw
// bits, specials and near-grid values), a duplicate of an earlier point, a
// point on the line through two earlier ones, a run of collinear points,
// an earlier point moved by a few ulps, and a cloud of 1100 points around
// the earlier ones (so that the Akl-Toussaint prefilter runs).
//
// Contract, per kernel K and algorithm (doc/reliability.md, harness hull):
//  * NaN or infinite input (after K's own rounding of the coordinates) ends
//    in relgeo::Non_finite_input, finite input never does, and nothing else
//    is thrown;
//  * the result's indices are in range, its points are the input's at them;
//  * graham_incremental may fail (non-termination, undecidable order) but
//    only by saying so;
//  * K with exact predicates: every algorithm returns the exact hull, as an
//    independent oracle computes it in GMP rationals (convention of
//    hull_result.h);
//  * other certified K (failsafe, interval): graham_fortune and
//    monotone_chain return a simple, strictly convex, counterclockwise
//    polygon (checked in rationals), and graham_fortune's backward-error
//    certificate is within its a-priori bound whenever the bound exists.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/error.h"
#include "relgeo/hull.h"

namespace relgeo::fuzz {

enum class Hull_algorithm { incremental, fortune, monotone };

// ---- the independent exact oracle -----------------------------------------------

inline int exact_orientation(const Point_2<double>& p, const Point_2<double>& q, const Point_2<double>& r) {
  const mpq_class px(p.x), py(p.y), qx(q.x), qy(q.y), rx(r.x), ry(r.y);
  const mpq_class d = (qx - px) * (ry - py) - (qy - py) * (rx - px);
  return sgn(d);
}

inline bool lexicographically_less(const Point_2<double>& a, const Point_2<double>& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

/// The exact hull of finite points by the output convention of
/// hull_result.h: counterclockwise vertex indices in strictly convex
/// position from the lexicographically smallest; among equal points the
/// smallest index; collinear input gives its two extremes.
inline std::vector<std::size_t> oracle_hull(std::span<const Point_2<double>> p) {
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return lexicographically_less(p[a], p[b]); });
  std::vector<std::size_t> u;  // distinct points, smallest index of each
  for (std::size_t i : order)
    if (u.empty() || lexicographically_less(p[u.back()], p[i])) u.push_back(i);
  if (u.size() <= 2) return u;
  std::vector<std::size_t> h;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = h.size();
    for (std::size_t k = 0; k < u.size(); ++k) {
      const std::size_t i = pass == 0 ? u[k] : u[u.size() - 1 - k];
      while (h.size() >= base + 2 && exact_orientation(p[h[h.size() - 2]], p[h.back()], p[i]) <= 0) h.pop_back();
      h.push_back(i);
    }
    h.pop_back();  // the last point starts the other chain
  }
  if (h.size() == 2 && h[0] == h[1]) h.pop_back();
  return h;
}

/// Simple, strictly convex, counterclockwise (every turn a strict left turn
/// and exactly one lexicographic local minimum), in rationals.
inline bool is_strictly_convex_ccw(const std::vector<Point_2<double>>& y) {
  const std::size_t h = y.size();
  if (h <= 1) return true;
  if (h == 2) return !(y[0] == y[1]);
  std::size_t minima = 0;
  for (std::size_t i = 0; i < h; ++i) {
    const auto& a = y[(i + h - 1) % h];
    const auto& b = y[i];
    const auto& c = y[(i + 1) % h];
    if (exact_orientation(a, b, c) <= 0) return false;
    minima += lexicographically_less(b, a) && lexicographically_less(b, c);
  }
  return minima == 1;
}

// ---- the contract under one kernel -----------------------------------------------

/// A kernel point's coordinates as the nearest doubles (relgeo points have
/// members, CGAL points accessors).
template <class P>
Point_2<double> to_double_point(const P& p) {
  if constexpr (requires { p.x(); }) return {nearest_double(p.x()), nearest_double(p.y())};
  else return {nearest_double(p.x), nearest_double(p.y)};
}

template <class K>
Hull_result<typename K::Point_2> run_hull(Hull_algorithm a, std::span<const typename K::Point_2> pts, const K& k,
                                          const Hull_options& o) {
  switch (a) {
    case Hull_algorithm::incremental: return graham_incremental<K>(pts, k);
    case Hull_algorithm::fortune: return graham_fortune<K>(pts, k, o);
    default: return monotone_chain<K>(pts, k, o);
  }
}

template <class K>
void check_hull(std::span<const Point_2<double>> input, Hull_algorithm algorithm, const Hull_options& options) {
  using P = typename K::Point_2;
  using FT = typename K::FT;
  const K k{};
  const std::string who = K::name() + " algorithm " + std::to_string(static_cast<int>(algorithm));

  // What the kernel's coordinates are (a float kernel rounds; CGAL's refuse
  // non-finite values when the point is made).
  bool finite = true;
  std::vector<P> pts;
  try {
    const auto make = k.construct_point_2_object();
    for (const auto& p : input) pts.push_back(make(p.x, p.y));
  } catch (const Non_finite_input&) {
    finite = false;
  }
  if (finite) {
    for (const auto& p : input) finite = finite && std::isfinite(p.x) && std::isfinite(p.y);
    if constexpr (std::is_floating_point_v<FT>)
      for (const P& p : pts) {
        const auto d = to_double_point(p);
        finite = finite && std::isfinite(d.x) && std::isfinite(d.y);
      }
  }
  if (!finite) {
    if (pts.size() < input.size()) return;  // refused at construction, typed
    bool refused = false;
    try {
      (void)run_hull<K>(algorithm, pts, k, options);
    } catch (const Non_finite_input&) {
      refused = true;
    } catch (const std::exception& e) {
      require(false, who + ": non-finite input gave " + e.what());
    }
    require(refused, who + ": non-finite input is refused with Non_finite_input");
    return;
  }

  Hull_result<P> r;
  try {
    r = run_hull<K>(algorithm, pts, k, options);
  } catch (const std::exception& e) {
    require(false, who + ": finite input threw " + e.what());
  }
  require(r.indices.size() == r.points.size(), who + ": one point per index");
  for (std::size_t i = 0; i < r.indices.size(); ++i) require(r.indices[i] < input.size(), who + ": index in range");
  if (!r.ok()) {
    require(algorithm == Hull_algorithm::incremental || !K::has_exact_predicates,
            who + ": only graham_incremental or an inexact kernel may fail: " + r.failure);
    require(!r.failure.empty(), who + ": a failure says why");
    return;
  }
  require(r.failure.empty(), who + ": no failure text when ok");

  if constexpr (K::has_exact_predicates) {
    require(r.indices == oracle_hull(input), who + ": the exact hull");
  } else if constexpr (K::is_certified) {
    if (algorithm == Hull_algorithm::incremental) return;  // not stable under any kernel
    // The polygon of the kernel's points (float kernels round the input).
    std::vector<Point_2<double>> y;
    for (const P& p : r.points) y.push_back(to_double_point(p));
    require(is_strictly_convex_ccw(y), who + ": a strictly convex counterclockwise polygon");
    if (algorithm == Hull_algorithm::fortune) {
      if (const auto bound = graham_fortune_backward_error_bound<K>(input)) {
        const auto b = hull_backward_error(input, r.indices);
        require(b.value <= *bound, who + ": backward error " + std::to_string(b.value) + " within the bound " +
                                       std::to_string(*bound));
      }
    }
  }
}

}  // namespace relgeo::fuzz
