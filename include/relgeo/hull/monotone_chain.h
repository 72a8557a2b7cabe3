// relgeo/hull/monotone_chain.h — Andrew's monotone chain algorithm.
#pragma once

#include <span>
#include <vector>

#include "relgeo/hull/hull_result.h"
#include "relgeo/hull/internal/chain_scan.h"
#include "relgeo/hull/internal/hull_frame.h"
#include "relgeo/kernel/concepts.h"

namespace relgeo {

/// \brief Planar convex hull by Andrew's monotone chain (A. M. Andrew,
/// "Another efficient algorithm for convex hulls in two dimensions", 1979):
/// sort lexicographically, then build the lower chain left to right and the
/// upper chain right to left with a stack, keeping a middle point only on a
/// certain left turn (an `uncertain` answer drops it, as in graham_fortune).
///
/// \tparam K an OrientationKernel_2 (orientation_2, compare_xy_2).
/// \param points the input; may be empty, contain duplicates or be collinear.
/// \param options Hull_options: by default certainly interior points are
///   dropped before sorting (Akl-Toussaint), which leaves the exact hull as it is.
/// \return the hull (hull_result.h); 1 index for one distinct point, the two
///   extreme points for collinear input, nothing for empty input.
/// \throws Non_finite_input if a coordinate is NaN or infinite.
/// Complexity: O(n log n) comparisons + O(n) orientation tests.
template <OrientationKernel_2 K>
Hull_result<typename K::Point_2> monotone_chain(std::span<const typename K::Point_2> points,
                                                const K& k = K{},
                                                const Hull_options& options = {}) {
  return internal::sorted_hull(points, k, options, "monotone_chain", [](const auto& sorted, const auto& kernel,
                                                                      auto& chain, auto& r) {
    // Plain index loops rather than std::views: clang 14 (Debian 12's
    // default) cannot compile libstdc++ 12's iota/reverse views.
    const auto orientation = kernel.orientation_2_object();
    const std::size_t m = sorted.size();
    for (std::size_t p = 0; p < m; ++p)  // lower, L..R
      internal::extend_chain(sorted, p, orientation, Certified_sign::positive, chain, 0, r);
    const std::size_t lower_size = chain.size();
    for (std::size_t p = m - 1; p-- > 0;)  // upper, R..L
      internal::extend_chain(sorted, p, orientation, Certified_sign::positive, chain, lower_size - 1, r);
    chain.pop_back();  // L again
  });
}

/// Overload for any contiguous range of K::Point_2 (std::vector, std::array...).
template <OrientationKernel_2 K, class Range>
  requires std::convertible_to<Range&, std::span<const typename K::Point_2>>
Hull_result<typename K::Point_2> monotone_chain(const Range& points, const K& k = K{},
                                                const Hull_options& options = {}) {
  return monotone_chain<K>(std::span<const typename K::Point_2>(points), k, options);
}

}  // namespace relgeo
