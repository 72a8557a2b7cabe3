// relgeo/hull/internal/chain_scan.h — the stack step shared by Andrew's
// monotone chain and Fortune's Graham scan: the middle point of the last
// triple is kept only on a *certain* turn the right way, so an `uncertain`
// answer drops it (Fortune's fail-safe rule).
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "relgeo/hull/hull_result.h"
#include "relgeo/core/certified_sign.h"

namespace relgeo::internal {

/// Pushes position `r` onto `chain` (positions in the sorted input), first
/// popping every middle point whose turn to r is not certainly `keep`; the
/// stack never pops below chain[chain_floor].
template <class Sorted, class Orientation, class Point>
void extend_chain(const Sorted& input, std::size_t r, const Orientation& orientation, Certified_sign keep,
                  std::vector<std::size_t>& chain, std::size_t chain_floor, Hull_result<Point>& stats) {
  while (chain.size() >= chain_floor + 2) {
    const Certified_sign s =
        orientation(input.point(chain[chain.size() - 2]), input.point(chain.back()), input.point(r));
    ++stats.predicate_calls;
    stats.uncertain_answers += (!is_certain(s));
    if (s == keep) break;
    chain.pop_back();
  }
  chain.push_back(r);
}

}  // namespace relgeo::internal
