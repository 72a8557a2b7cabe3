// relgeo/core/certified_sort.h — sorting by a certified comparison, which
// may answer `uncertain`.
//
// std::sort and std::stable_sort need a strict weak ordering; a comparator
// that reads `uncertain` as one of the definite answers is none (two points
// of wide intervals can each look smaller than the other), and the standard
// leaves the result undefined — in practice reads outside the range. A
// kernel's definite answers are exact, so they are consistent; the sort
// below stops at the first `uncertain` instead, and the caller reports that
// the order is undecided (a failure with a reason, never a guess).
#pragma once

#include <algorithm>

#include "relgeo/core/certified_sign.h"

namespace relgeo {

/// \brief Sorts [first, last) by `compare(a, b)`, a three-way comparison
/// answering a Certified_sign (negative: a comes first), stably when
/// `stable`. Returns false as soon as a comparison is `uncertain`: the
/// range's contents are then unspecified (the sort failed).
template <class It, class Compare>
bool certified_sort(It first, It last, Compare compare, bool stable = false) {
  struct Undecided {};
  const auto less = [&compare](const auto& a, const auto& b) {
    const Certified_sign s = compare(a, b);
    if (!is_certain(s)) throw Undecided{};
    return certainly(s, Certified_sign::negative);
  };
  try {
    if (stable) std::stable_sort(first, last, less);
    else std::sort(first, last, less);
  } catch (const Undecided&) {
    return false;
  }
  return true;
}

}  // namespace relgeo
