// relgeo/hull/graham_fortune.h — Fortune's stable Graham scan (thesis Sec. 3.3.3).
#pragma once

#include <ranges>
#include <span>
#include <vector>

#include "relgeo/hull/hull_result.h"
#include "relgeo/hull/internal/chain_scan.h"
#include "relgeo/hull/internal/hull_support.h"
#include "relgeo/kernel/concepts.h"

namespace relgeo {

/// \brief Fortune's stable Graham scan (S. Fortune, "Stable maintenance of
/// point set triangulations in two dimensions", FOCS 1989; thesis Sec. 3.3.3).
///
/// 1. Sort the points lexicographically; L and R are the first and the last.
/// 2. Split the others by the triangle test against the line LR: certainly
///    left of L->R go to the upper candidates, certainly right to the lower
///    candidates; an `uncertain` (or zero) answer drops the point — it lies
///    within the test's uncertainty of segment LR, inside the hull up to that.
/// 3. Scan each candidate chain with a stack, keeping the middle point of a
///    triple only on a *certain* left turn (fail-safe: ambiguous points are
///    dropped).
///
/// With a kernel whose definite answers are exact (Failsafe_kernel and every
/// certified kernel), every kept triple is an exact strict turn, so the output
/// is in strictly convex position, and every input point lies within the
/// bound of graham_fortune_backward_error_bound (relgeo/error/hull_backward_error.h)
/// of the output's hull: the output is the exact hull of an input perturbed by
/// at most that much. With exact predicates it is the exact hull.
///
/// \tparam K an OrientationKernel_2.
/// \return the hull (hull_result.h); special cases as for monotone_chain.
/// \throws Non_finite_input if a coordinate is NaN or infinite.
/// Complexity: O(n log n) comparisons + O(n) orientation tests.
template <OrientationKernel_2 K>
Hull_result<typename K::Point_2> graham_fortune(std::span<const typename K::Point_2> points,
                                                const K& k = K{}) {
  return internal::sorted_hull(points, k, "graham_fortune", [&](const auto& sorted, auto& chain, auto& r) {
    const auto orientation = k.orientation_2_object();
    const std::size_t L = 0, R = sorted.size() - 1;
    // The split by the triangle test against line LR is evaluated on the fly
    // in each scan (no candidate lists: memory stays at the sorted copy).
    auto side_is = [&](Certified_sign wanted) {
      return [&, wanted](std::size_t p) {
        const Certified_sign s = orientation(sorted.point(L), sorted.point(R), sorted.point(p));
        ++r.predicate_calls;
        r.uncertain_answers += (wanted == Certified_sign::negative && s == Certified_sign::uncertain);
        return s == wanted;
      };
    };
    const std::size_t ends[2] = {R, L};
    chain.push_back(L);
    internal::scan_chain(sorted, std::views::iota(L + 1, R) | std::views::filter(side_is(Certified_sign::negative)),
                         k, chain, 0, r);
    internal::scan_chain(sorted, std::span(ends, 1), k, chain, 0, r);  // lower chain L .. R
    const std::size_t lower_size = chain.size();
    internal::scan_chain(sorted,
                         std::views::iota(L + 1, R) | std::views::reverse |
                             std::views::filter(side_is(Certified_sign::positive)),
                         k, chain, lower_size - 1, r);
    internal::scan_chain(sorted, std::span(ends + 1, 1), k, chain, lower_size - 1, r);  // upper R .. L
    chain.pop_back();  // L again
  });
}

template <OrientationKernel_2 K, class Range>
  requires std::convertible_to<Range&, std::span<const typename K::Point_2>>
Hull_result<typename K::Point_2> graham_fortune(const Range& points, const K& k = K{}) {
  return graham_fortune<K>(std::span<const typename K::Point_2>(points), k);
}

}  // namespace relgeo
