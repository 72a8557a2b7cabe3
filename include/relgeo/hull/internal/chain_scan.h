// relgeo/hull/internal/chain_scan.h — the stack scan shared by Andrew's
// monotone chain and Fortune's Graham scan: the middle point of the last
// triple is kept only on a *certain* left turn, so an `uncertain` answer drops
// it (Fortune's fail-safe rule).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "relgeo/hull/hull_result.h"
#include "relgeo/kernel/certified_sign.h"

namespace relgeo::internal {

/// Appends the convex chain through `sequence` (in order) to `chain`, whose
/// last element must be sequence's predecessor (or which is empty).
template <class K, class Point>
void scan_chain(std::span<const std::size_t> sequence, std::span<const Point> points, const K& k,
                std::vector<std::size_t>& chain, std::size_t chain_floor,
                Hull_result<Point>& stats) {
  const auto orientation = k.orientation_2_object();
  for (std::size_t r : sequence) {
    while (chain.size() >= chain_floor + 2) {
      const Certified_sign s =
          orientation(points[chain[chain.size() - 2]], points[chain.back()], points[r]);
      ++stats.predicate_calls;
      stats.uncertain_answers += (s == Certified_sign::uncertain);
      if (s == Certified_sign::positive) break;
      chain.pop_back();
    }
    chain.push_back(r);
  }
}

}  // namespace relgeo::internal
