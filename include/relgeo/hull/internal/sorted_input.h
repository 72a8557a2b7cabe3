// relgeo/hull/internal/sorted_input.h — the distinct hull input points in
// lexicographic order, and the input index of each sorted position.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <boost/sort/pdqsort/pdqsort.hpp>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/certified_sort.h"
#include "relgeo/hull/internal/hull_input.h"
#include "relgeo/hull/internal/interior_prefilter.h"
#include "relgeo/hull/internal/position_lookup.h"

namespace relgeo::internal {

/// The distinct input points in lexicographic order: position i holds
/// point(i); indices(positions) gives, for positions of this order, the
/// smallest input index of each point.
///
/// Points of doubles (finite: callers check first) are compared directly,
/// which is exact, on a plain sorted copy of the points (Boost's branchless
/// pattern-defeating quicksort, faster than std::sort on random input: the
/// sort/ rows of relgeo_hull_benchmark);
/// the input indices are recovered afterwards for the few positions asked
/// for, by one pass over the input through a hash set of their points. The
/// sort is most of a hull's time and the copy its memory: comparing through
/// the kernel's certified functor on scattered indices was 2-3x slower, and
/// (point, index) records took 1.5x the input (benchmark/hull). Other point
/// types are sorted as indices through the kernel's compare_xy_2. An
/// `uncertain` comparison (points of wide intervals, say) leaves the order
/// undecided: the sort stops at once (a comparator that guesses would not be
/// a strict weak ordering, and Fortune's argument needs sorted input),
/// undecidable() is set and the sequence is empty; it is counted in
/// *undecided.
template <class K>
class Sorted_input {
  using Point = typename K::Point_2;
  static constexpr bool direct = Floating_point_2<Point>;

 public:
  /// `keep` (one bit per input point, nullptr: all) selects the points sorted.
  Sorted_input(std::span<const Point> points, const K& k, std::size_t* undecided,
               const Point_bitmap* keep = nullptr)
      : input_(points) {
    if constexpr (direct) {
      if (keep) {
        sorted_.reserve(keep->count());
        for (std::size_t i = 0; i < points.size(); ++i)
          if (keep->test(i)) sorted_.push_back(points[i]);
      } else {
        sorted_.assign(points.begin(), points.end());
      }
      // Branch-free "less" (| and & instead of || and &&): the partitions of
      // pdqsort_branchless then run without mispredictions.
      boost::sort::pdqsort_branchless(sorted_.begin(), sorted_.end(), [](const Point& a, const Point& b) {
        return (a.x < b.x) | ((a.x == b.x) & (a.y < b.y));
      });
      sorted_.erase(std::unique(sorted_.begin(), sorted_.end()), sorted_.end());
    } else {
      const auto compare = k.compare_xy_2_object();
      const auto by_point = [&](std::size_t a, std::size_t b) { return compare(points[a], points[b]); };
      for (std::size_t i = 0; i < points.size(); ++i)
        if (!keep || keep->test(i)) order_.push_back(i);
      bool decided = certified_sort(order_.begin(), order_.end(), by_point, /*stable=*/true);
      std::size_t kept = 0;
      for (std::size_t j = 0; decided && j < order_.size(); ++j) {
        const Certified_sign s = kept == 0 ? Certified_sign::positive : by_point(order_[kept - 1], order_[j]);
        decided = is_certain(s);
        if (!certainly(s, Certified_sign::zero)) order_[kept++] = order_[j];
      }
      order_.resize(kept);
      if (!decided) {
        undecidable_ = true;
        order_.clear();
        if (undecided) ++*undecided;
      }
    }
  }

  /// The kernel could not order two of the points (nothing is sorted then).
  bool undecidable() const { return undecidable_; }

  std::size_t size() const {
    if constexpr (direct) return sorted_.size();
    else return order_.size();
  }
  const Point& point(std::size_t i) const {
    if constexpr (direct) return sorted_[i];
    else return input_[order_[i]];
  }
  /// The smallest input index of the point at each position.
  std::vector<std::size_t> indices(std::span<const std::size_t> positions) const {
    std::vector<std::size_t> out(positions.size());
    if constexpr (direct) {
      // One pass over the input in index order: the first hit of a point is
      // its smallest index.
      if (sorted_.size() < (std::size_t{1} << 32) - 1) recover<std::uint32_t>(positions, out);
      else recover<std::size_t>(positions, out);
    } else {
      for (std::size_t j = 0; j < positions.size(); ++j) out[j] = order_[positions[j]];
    }
    return out;
  }

 private:
  template <class Index>
  void recover(std::span<const std::size_t> positions, std::vector<std::size_t>& out) const {
    using Lookup = Position_lookup<Point, Index>;
    const Lookup lookup(sorted_, positions);
    std::fill(out.begin(), out.end(), Lookup::none);
    // When the hull is large its table is too: prefetching the slot 16 points
    // ahead and its point 8 ahead hides some of the cache misses (a fifth of
    // the recovery time for 10^6 points on a circle, timed on its own).
    constexpr std::size_t slot_ahead = 16, point_ahead = 8;
    const std::size_t n = input_.size();
    std::size_t found = 0;
    for (std::size_t i = 0; i < n && found < out.size(); ++i) {
      if (i + slot_ahead < n) lookup.prefetch_slot(input_[i + slot_ahead]);
      if (i + point_ahead < n) lookup.prefetch_point(input_[i + point_ahead]);
      const std::size_t j = lookup.find(input_[i]);
      if (j != Lookup::none && out[j] == Lookup::none) out[j] = i, ++found;
    }
    // A chain computed with wrong (naive) answers can repeat a position:
    // the repeats take the index found for its first occurrence.
    for (std::size_t j = 0; j < out.size(); ++j)
      if (out[j] == Lookup::none) out[j] = out[lookup.find(sorted_[positions[j]])];
  }

  std::span<const Point> input_;
  std::vector<Point> sorted_;        // direct comparison
  std::vector<std::size_t> order_;   // through the kernel
  bool undecidable_ = false;
};

}  // namespace relgeo::internal
