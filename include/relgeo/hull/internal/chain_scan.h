// relgeo/hull/internal/chain_scan.h — the stack scan shared by Andrew's
// monotone chain and Fortune's Graham scan: the middle point of the last
// triple is kept only on a *certain* left turn, so an `uncertain` answer drops
// it (Fortune's fail-safe rule).
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "relgeo/hull/hull_result.h"
#include "relgeo/kernel/certified_sign.h"

namespace relgeo::internal {

/// Extends `chain` (positions in the sorted input) through `positions`, in
/// order; the stack never pops below chain[chain_floor].
template <class K, class Sorted, class Positions, class Point>
void scan_chain(const Sorted& input, Positions&& positions, const K& k,
                std::vector<std::size_t>& chain, std::size_t chain_floor, Hull_result<Point>& stats) {
  const auto orientation = k.orientation_2_object();
  for (std::size_t r : positions) {
    while (chain.size() >= chain_floor + 2) {
      const Certified_sign s = orientation(input.point(chain[chain.size() - 2]),
                                           input.point(chain.back()), input.point(r));
      ++stats.predicate_calls;
      stats.uncertain_answers += (s == Certified_sign::uncertain);
      if (s == Certified_sign::positive) break;
      chain.pop_back();
    }
    chain.push_back(r);
  }
}

}  // namespace relgeo::internal
