// relgeo/core/internal/union_find.h — disjoint sets over the indices
// 0..n-1 (union-find with path halving). The smaller index represents its
// set, so the representatives do not depend on the order of the unions: the
// Boolean relies on it (an input vertex represents the new points equal to
// it), the components and the joining's vertex numbering only need a key.
#pragma once

#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace relgeo::internal {

template <class I>
class Union_find {
 public:
  explicit Union_find(std::size_t n = 0) : parent_(n) { std::iota(parent_.begin(), parent_.end(), I{0}); }

  /// A new singleton set (the next index).
  void add() { parent_.push_back(static_cast<I>(parent_.size())); }
  /// The representative of x's set (the smallest index in it).
  I find(I x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];  // path halving
    return x;
  }
  /// Joins the sets of x and y.
  void unite(I x, I y) {
    x = find(x), y = find(y);
    if (y < x) std::swap(x, y);
    parent_[y] = x;
  }

 private:
  std::vector<I> parent_;
};

}  // namespace relgeo::internal
