// relgeo/hull/internal/hull_frame.h — the frame every relgeo hull algorithm
// runs in: the kernel's double-point hook, the floating-point environment,
// the input check, and the output convention; and the sorted frame of the
// two scans (graham_fortune, monotone_chain).
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/hull/hull_result.h"
#include "relgeo/hull/internal/hull_input.h"
#include "relgeo/hull/internal/interior_prefilter.h"
#include "relgeo/hull/internal/sorted_input.h"
#include "relgeo/kernel/kernel_for_number.h"
#include "relgeo/kernel/point.h"

namespace relgeo::internal {

/// The failure a hull algorithm reports when the kernel cannot order its input.
inline constexpr const char* undecidable_order_failure = "undecidable-order";

/// Fills result.points from result.indices.
template <class Point>
void attach_points(Hull_result<Point>& r, std::span<const Point> points) {
  r.points.clear();
  r.points.reserve(r.indices.size());
  for (std::size_t i : r.indices) r.points.push_back(points[i]);
}

/// The input as points of doubles when every point is exactly one
/// (K::exact_double_point, the kernel hook Has_double_point_kernel), nullopt
/// otherwise.
template <class K>
  requires Has_double_point_kernel<K>
std::optional<std::vector<relgeo::Point_2<double>>> exact_double_points(std::span<const typename K::Point_2> points) {
  std::vector<relgeo::Point_2<double>> doubles(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::optional<relgeo::Point_2<double>> d = K::exact_double_point(points[i]);
    if (!d) return std::nullopt;
    doubles[i] = *d;
  }
  return doubles;
}

/// \brief Runs a hull algorithm: `body(points, kernel, result)` computes the
/// hull as input indices (with its statistics and status) into `result`; the
/// frame
///  1. consults the kernel hook once: when K names a Double_point_kernel
///     (kernel/kernel_for_number.h) and every input point is exactly a point
///     of doubles, the body runs with that kernel on the doubles, whose
///     predicates answer the same exact signs on the same values, so the
///     result (indices, statistics, status) is the one K would produce,
///     without K's arithmetic; it is relabelled with the input's points;
///  2. holds the default floating-point environment for a certified kernel;
///  3. checks that every coordinate is finite (Non_finite_input naming `who`);
///  4. fills result.points from result.indices.
template <class K, class Body>
Hull_result<typename K::Point_2> hull_frame(std::span<const typename K::Point_2> points, const K& k,
                                            const char* who, Body&& body) {
  using Point = typename K::Point_2;
  if constexpr (Has_double_point_kernel<K>) {
    if (const auto doubles = exact_double_points<K>(points)) {
      using D = typename K::Double_point_kernel;
      Hull_result<relgeo::Point_2<double>> h =
          hull_frame(std::span<const relgeo::Point_2<double>>(*doubles), D{}, who, body);
      Hull_result<Point> r;
      r.status = h.status;
      r.failure = std::move(h.failure);
      r.indices = std::move(h.indices);
      r.predicate_calls = h.predicate_calls;
      r.uncertain_answers = h.uncertain_answers;
      attach_points(r, points);
      return r;
    }
  }
  const Default_fp_environment_if<K::is_certified> environment;
  require_finite_points<Point>(points, who);
  Hull_result<Point> r;
  body(points, k, r);
  attach_points(r, points);
  return r;
}

/// The frame shared by the sorting hull algorithms, inside hull_frame: drops
/// certainly interior points (interior_prefilter, if asked), sorts the rest
/// (Sorted_input), answers the 0-2 distinct point cases, and lets
/// `scan(sorted, kernel, chain, result)` build the hull as positions of the
/// sorted input (for 3 or more distinct points); the positions become input
/// indices. An undecidable order is the failure undecidable_order_failure.
template <class K, class Scan>
Hull_result<typename K::Point_2> sorted_hull(std::span<const typename K::Point_2> points, const K& k,
                                             const Hull_options& options, const char* who, Scan&& scan) {
  return hull_frame(points, k, who, [&](auto input, const auto& kernel, auto& r) {
    using Kernel = std::remove_cvref_t<decltype(kernel)>;
    std::optional<Point_bitmap> kept;
    if (options.discard_interior) kept = interior_prefilter(input, kernel, r);
    const Sorted_input<Kernel> sorted(input, kernel, &r.uncertain_answers, kept ? &*kept : nullptr);
    if (sorted.undecidable()) {
      r.status = Hull_status::failed;
      r.failure = undecidable_order_failure;
      return;
    }
    std::vector<std::size_t> chain;  // positions in `sorted`
    if (sorted.size() <= 2) {
      for (std::size_t i = 0; i < sorted.size(); ++i) chain.push_back(i);
    } else {
      scan(sorted, kernel, chain, r);
    }
    r.indices = sorted.indices(chain);
  });
}

/// Rotates a cyclic index sequence to start at its lexicographically smallest
/// point (ties by index), as the output convention asks. Only the start of
/// the cycle depends on it: an `uncertain` comparison keeps the earlier
/// candidate.
template <class K>
void rotate_to_smallest(std::vector<std::size_t>& cycle, std::span<const typename K::Point_2> points,
                        const K& k) {
  if (cycle.size() < 2) return;
  const auto compare = k.compare_xy_2_object();
  std::size_t best = 0;
  for (std::size_t i = 1; i < cycle.size(); ++i) {
    const Certified_sign s = compare(points[cycle[i]], points[cycle[best]]);
    if (certainly(s, Certified_sign::negative) || (certainly(s, Certified_sign::zero) && cycle[i] < cycle[best]))
      best = i;
  }
  std::rotate(cycle.begin(), cycle.begin() + static_cast<std::ptrdiff_t>(best), cycle.end());
}

}  // namespace relgeo::internal
