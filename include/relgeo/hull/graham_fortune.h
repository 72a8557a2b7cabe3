// relgeo/hull/graham_fortune.h — Fortune's stable Graham scan (thesis Sec. 3.3.3).
#pragma once

#include <span>
#include <vector>

#include "relgeo/hull/hull_result.h"
#include "relgeo/hull/internal/chain_scan.h"
#include "relgeo/hull/internal/hull_frame.h"
#include "relgeo/kernel/concepts.h"

namespace relgeo {

/// \brief Fortune's stable Graham scan (S. Fortune, "Stable maintenance of
/// point set triangulations in two dimensions", FOCS 1989; thesis Sec. 3.3.3).
///
/// 0. Unless options.discard_interior is false, drop the points certified to
///    lie strictly inside the polygon of 8 extreme points (Akl-Toussaint,
///    Hull_options): the same exact hull, the same backward-error bound.
/// 1. Sort the points lexicographically; L and R are the first and the last.
/// 2. Split the others by the triangle test against the line LR: certainly
///    left of L->R go to the upper chain, certainly right to the lower chain;
///    an `uncertain` (or zero) answer drops the point — it lies within the
///    test's uncertainty of segment LR, inside the hull up to that.
/// 3. Scan each chain with a stack from L to R, keeping the middle point of a
///    triple only on a *certain* turn outwards (left on the lower chain, right
///    on the upper one; fail-safe: ambiguous points are dropped).
///
/// With a kernel whose definite answers are exact (Failsafe_kernel and every
/// certified kernel), every kept triple is an exact strict turn, so the output
/// is in strictly convex position, and every input point lies within the
/// bound of graham_fortune_backward_error_bound (relgeo/error/hull_backward_error.h)
/// of the output's hull: the output is the exact hull of an input perturbed by
/// at most that much. With exact predicates it is the exact hull.
///
/// \tparam K an OrientationKernel_2.
/// \param options Hull_options (the prefilter of step 0).
/// \return the hull (hull_result.h); special cases as for monotone_chain.
/// \throws Non_finite_input if a coordinate is NaN or infinite.
/// Complexity: O(n log n) comparisons + O(n) orientation tests.
template <OrientationKernel_2 K>
Hull_result<typename K::Point_2> graham_fortune(std::span<const typename K::Point_2> points,
                                                const K& k = K{},
                                                const Hull_options& options = {}) {
  return internal::sorted_hull(points, k, options, "graham_fortune", [](const auto& sorted, const auto& kernel,
                                                                      auto& chain, auto& r) {
    const auto orientation = kernel.orientation_2_object();
    const std::size_t L = 0, R = sorted.size() - 1;
    // One pass from L to R: each point is tested once against line LR and
    // extends the chain on its side. The upper chain is scanned left to right
    // too, keeping a middle point only on a certain *right* turn: that is the
    // lower-chain rule on the input mirrored in the x axis, which negates
    // every determinant exactly and leaves every error bound unchanged, so
    // Fortune's guarantee carries over. (One test per point instead of one
    // per chain, and no candidate lists: memory stays at the sorted copy.)
    std::vector<std::size_t> upper{L};
    chain.push_back(L);
    for (std::size_t p = L + 1; p < R; ++p) {
      const Certified_sign side = orientation(sorted.point(L), sorted.point(R), sorted.point(p));
      ++r.predicate_calls;
      r.uncertain_answers += (!is_certain(side));
      if (certainly(side, Certified_sign::negative))
        internal::extend_chain(sorted, p, orientation, Certified_sign::positive, chain, 0, r);
      else if (certainly(side, Certified_sign::positive))
        internal::extend_chain(sorted, p, orientation, Certified_sign::negative, upper, 0, r);
    }
    internal::extend_chain(sorted, R, orientation, Certified_sign::positive, chain, 0, r);
    internal::extend_chain(sorted, R, orientation, Certified_sign::negative, upper, 0, r);
    // chain = lower L .. R, then the upper chain back from R to L (both ends shared).
    chain.insert(chain.end(), upper.rbegin() + 1, upper.rend() - 1);
  });
}

template <OrientationKernel_2 K, class Range>
  requires std::convertible_to<Range&, std::span<const typename K::Point_2>>
Hull_result<typename K::Point_2> graham_fortune(const Range& points, const K& k = K{},
                                                const Hull_options& options = {}) {
  return graham_fortune<K>(std::span<const typename K::Point_2>(points), k, options);
}

}  // namespace relgeo
