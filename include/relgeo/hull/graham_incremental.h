// relgeo/hull/graham_incremental.h — the incremental hull of Kettner et al.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "relgeo/hull/hull_result.h"
#include "relgeo/hull/internal/hull_frame.h"
#include "relgeo/hull/internal/sorted_input.h"
#include "relgeo/kernel/concepts.h"

namespace relgeo {

namespace internal {

/// The body of graham_incremental (inside hull_frame): the hull of `points`
/// as input indices into r.
template <OrientationKernel_2 K>
void incremental_hull(std::span<const typename K::Point_2> points, const K& k, Hull_result<typename K::Point_2>& r) {
  const auto orientation = k.orientation_2_object();
  const auto compare = k.compare_xy_2_object();
  auto orient = [&](std::size_t a, std::size_t b, std::size_t c) {
    const Certified_sign s = orientation(points[a], points[b], points[c]);
    ++r.predicate_calls;
    r.uncertain_answers += (!is_certain(s));
    return s;
  };
  const std::size_t n = points.size();
  if (n == 0) return;

  // Seed triangle.
  std::size_t second = n, third = n;
  for (std::size_t i = 1; i < n && second == n; ++i)
    if (!certainly(compare(points[0], points[i]), Certified_sign::zero)) second = i;
  for (std::size_t i = second + 1; second < n && i < n && third == n; ++i) {
    const Certified_sign s = orient(0, second, i);
    if (certainly(s, Certified_sign::positive) || certainly(s, Certified_sign::negative)) third = i;
  }
  if (third == n) {  // one distinct point, or (as far as K can tell) collinear
    const Sorted_input<K> sorted(points, k, &r.uncertain_answers);
    if (sorted.undecidable()) {
      r.status = Hull_status::failed;
      r.failure = undecidable_order_failure;
      return;
    }
    std::vector<std::size_t> ends;
    if (sorted.size() >= 1) ends.push_back(0);
    if (sorted.size() >= 2) ends.push_back(sorted.size() - 1);
    r.indices = sorted.indices(ends);
    return;
  }

  // Circular doubly linked list over input indices.
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> next(n, none), prev(n, none);
  std::size_t start = 0, hull_size = 3;
  auto link = [&](std::size_t a, std::size_t b) { next[a] = b, prev[b] = a; };
  if (certainly(orient(0, second, third), Certified_sign::positive)) {
    link(0, second), link(second, third), link(third, 0);
  } else {
    link(0, third), link(third, second), link(second, 0);
  }

  auto insert = [&](std::size_t p) -> bool {  // false: non-termination detected
    // Locate: first edge (s, next s) that p sees.
    std::size_t s = start, scanned = 0;
    while (!certainly(orient(s, next[s], p), Certified_sign::negative)) {
      s = next[s];
      if (++scanned >= hull_size) return true;  // inside (or on the boundary): discard
    }
    std::size_t t = next[s];
    // Walk forward while p sees (t, next t).
    for (std::size_t steps = 0; !certainly(orient(t, next[t], p), Certified_sign::positive);) {
      t = next[t];
      if (++steps > hull_size || t == s) return false;
    }
    // Walk backward while p sees (prev s, s).
    for (std::size_t steps = 0; !certainly(orient(prev[s], s, p), Certified_sign::positive);) {
      s = prev[s];
      if (++steps > hull_size || s == t) return false;
    }
    // Remove the vertices strictly between s and t, insert p.
    for (std::size_t v = next[s]; v != t;) {
      const std::size_t after = next[v];
      if (v == start) start = s;
      next[v] = prev[v] = none;
      --hull_size;
      v = after;
    }
    link(s, p), link(p, t);
    ++hull_size;
    return true;
  };

  for (std::size_t i = 1; i < n; ++i) {
    if (i == second || i == third) continue;
    if (!insert(i)) {
      r.status = Hull_status::failed;
      r.failure = "non-termination";
      break;
    }
  }

  // Read the cycle (bounded: a corrupted list cannot loop forever).
  std::size_t v = start;
  do {
    r.indices.push_back(v);
    v = next[v];
  } while (v != start && r.indices.size() <= n);
  rotate_to_smallest(r.indices, points, k);
}


}  // namespace internal

/// \brief The incremental planar convex hull of L. Kettner, K. Mehlhorn,
/// S. Pion, S. Schirra, C. Yap, "Classroom examples of robustness problems in
/// geometric computations" (CGTA 40, 2008) — the thesis' unstable algorithm.
///
/// The hull is a counterclockwise circular list seeded with a triangle of
/// input points; each further point p (in input order) is located by scanning
/// the edges from the start for the first edge (s, t) with
/// orientation(s, t, p) < 0 (p sees it). If there is none, p is discarded.
/// Otherwise the algorithm walks forward while orientation(t, succ t, p) <= 0
/// and backward while orientation(pred s, s, p) <= 0, removes the vertices
/// strictly between s and t, and inserts p.
///
/// With a naive kernel this fails in the published ways (points lost, non-convex
/// output, walks that never stop). It never hangs or crashes: a walk longer
/// than the current hull, or one that meets the other end, ends the run with
/// status `failed` and failure "non-termination"; the hull so far is returned.
///
/// Seeding, generalised from the paper (which assumes it): the triangle is the
/// first point, the first point different from it and the first point
/// certainly not collinear with those two (made counterclockwise); the points
/// skipped meanwhile are processed afterwards in input order. When no such
/// triangle exists the input is collinear and the result is its two extreme
/// points (or one point). An `uncertain` answer counts as "not < 0" in the
/// location scan and as "<= 0" in the walks.
///
/// \throws Non_finite_input if a coordinate is NaN or infinite.
/// Complexity: O(n h) orientation tests, h the hull size.
template <OrientationKernel_2 K>
Hull_result<typename K::Point_2> graham_incremental(std::span<const typename K::Point_2> points,
                                                    const K& k = K{}) {
  return internal::hull_frame(points, k, "graham_incremental", [](auto input, const auto& kernel, auto& r) {
    internal::incremental_hull(input, kernel, r);
  });
}

template <OrientationKernel_2 K, class Range>
  requires std::convertible_to<Range&, std::span<const typename K::Point_2>>
Hull_result<typename K::Point_2> graham_incremental(const Range& points, const K& k = K{}) {
  return graham_incremental<K>(std::span<const typename K::Point_2>(points), k);
}

}  // namespace relgeo
