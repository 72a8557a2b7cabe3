// relgeo/hull/internal/hull_support.h — input checks, lexicographic sorting and
// output normalisation shared by the hull algorithms.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/hull/hull_result.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/internal/kernel_base.h"
#include "relgeo/kernel/point.h"

namespace relgeo::internal {

/// x and y of a relgeo point (members) or a CGAL point (methods).
template <class P>
auto coordinate_x(const P& p) {
  if constexpr (requires { p.x(); }) return p.x();
  else return p.x;
}
template <class P>
auto coordinate_y(const P& p) {
  if constexpr (requires { p.y(); }) return p.y();
  else return p.y;
}

/// Throws Non_finite_input naming the first point with a NaN or infinite coordinate.
template <class Point>
void require_finite_points(std::span<const Point> points, const char* who) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto x = coordinate_x(points[i]);
    const auto y = coordinate_y(points[i]);
    bool finite = true;
    if constexpr (std::is_floating_point_v<decltype(x)> ||
                  requires { x.inf(); x.sup(); })
      finite = is_finite_value(x) && is_finite_value(y);
    if (!finite)
      throw Non_finite_input(std::string(who) + ": point " + std::to_string(i) +
                             " has a NaN or infinite coordinate");
  }
}

/// The distinct input points in lexicographic order: position i holds
/// point(i); indices(positions) gives, for positions of this order, the
/// smallest input index of each point.
///
/// relgeo's floating-point points (finite: callers check first) are compared
/// directly, which is exact, on a plain sorted copy of the points; the input
/// indices are recovered afterwards for the few positions asked for, by one
/// pass over the input with a binary search among them. The sort is most of a
/// hull's time and the copy its memory: comparing through the kernel's
/// certified functor on scattered indices was 2-3x slower, and (point, index)
/// records took 1.5x the input (benchmark/hull). Other point types are sorted
/// as indices through the kernel's compare_xy_2; an `uncertain` comparison
/// counts as `equal` and is reported through *undecided.
template <class K>
class Sorted_input {
  using Point = typename K::Point_2;
  static constexpr bool direct = requires(const Point& p) {
    requires std::is_floating_point_v<std::remove_cvref_t<decltype(p.x)>>;
    requires std::is_same_v<Point, relgeo::Point_2<std::remove_cvref_t<decltype(p.x)>>>;
  };
  static bool less_xy(const Point& a, const Point& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  }

 public:
  Sorted_input(std::span<const Point> points, const K& k, std::size_t* undecided) : input_(points) {
    if constexpr (direct) {
      sorted_.assign(points.begin(), points.end());
      std::sort(sorted_.begin(), sorted_.end(), less_xy);
      sorted_.erase(std::unique(sorted_.begin(), sorted_.end()), sorted_.end());
    } else {
      const auto compare = k.compare_xy_2_object();
      order_.resize(points.size());
      std::iota(order_.begin(), order_.end(), std::size_t{0});
      std::size_t unsure = 0;
      std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
        const Certified_sign s = compare(points[a], points[b]);
        unsure += (s == Certified_sign::uncertain);
        return s == Certified_sign::negative;
      });
      std::size_t kept = 0;
      for (std::size_t i : order_) {
        if (kept > 0) {
          const Certified_sign s = compare(points[order_[kept - 1]], points[i]);
          unsure += (s == Certified_sign::uncertain);
          if (s == Certified_sign::zero || s == Certified_sign::uncertain) continue;
        }
        order_[kept++] = i;
      }
      order_.resize(kept);
      if (undecided) *undecided += unsure;
    }
  }

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
      // Positions sorted (= points in lexicographic order), then one pass over
      // the input in index order: the first hit of a point is its smallest index.
      std::vector<std::size_t> by_position(positions.size());
      std::iota(by_position.begin(), by_position.end(), std::size_t{0});
      std::sort(by_position.begin(), by_position.end(),
                [&](std::size_t a, std::size_t b) { return positions[a] < positions[b]; });
      constexpr std::size_t unset = static_cast<std::size_t>(-1);
      std::fill(out.begin(), out.end(), unset);
      std::size_t found = 0;
      for (std::size_t i = 0; i < input_.size() && found < out.size(); ++i) {
        const auto it = std::lower_bound(by_position.begin(), by_position.end(), input_[i],
                                         [&](std::size_t slot, const Point& q) {
                                           return less_xy(sorted_[positions[slot]], q);
                                         });
        if (it == by_position.end() || !(sorted_[positions[*it]] == input_[i])) continue;
        // Equal positions (a closed chain repeats none, but be safe) share the index.
        for (auto j = it; j != by_position.end() && positions[*j] == positions[*it]; ++j)
          if (out[*j] == unset) out[*j] = i, ++found;
      }
    } else {
      for (std::size_t j = 0; j < positions.size(); ++j) out[j] = order_[positions[j]];
    }
    return out;
  }

 private:
  std::span<const Point> input_;
  std::vector<Point> sorted_;        // direct comparison
  std::vector<std::size_t> order_;   // through the kernel
};

/// Fills result.points from result.indices.
template <class Point>
void attach_points(Hull_result<Point>& r, std::span<const Point> points) {
  r.points.clear();
  r.points.reserve(r.indices.size());
  for (std::size_t i : r.indices) r.points.push_back(points[i]);
}

/// The frame shared by the sorting hull algorithms: checks the input, sorts it
/// (Sorted_input), answers the 0-2 distinct point cases, lets `scan(sorted,
/// chain, result)` build the hull as positions of the sorted input (for 3 or
/// more distinct points), and returns the result with input indices and points.
template <class K, class Scan>
Hull_result<typename K::Point_2> sorted_hull(std::span<const typename K::Point_2> points, const K& k,
                                             const char* who, Scan&& scan) {
  using Point = typename K::Point_2;
  require_finite_points<Point>(points, who);
  Hull_result<Point> r;
  const Sorted_input<K> sorted(points, k, &r.uncertain_answers);
  std::vector<std::size_t> chain;  // positions in `sorted`
  if (sorted.size() <= 2) {
    for (std::size_t i = 0; i < sorted.size(); ++i) chain.push_back(i);
  } else {
    scan(sorted, chain, r);
  }
  r.indices = sorted.indices(chain);
  attach_points(r, points);
  return r;
}

/// Rotates a cyclic index sequence to start at its lexicographically smallest
/// point (ties by index), as the output convention asks.
template <class K>
void rotate_to_smallest(std::vector<std::size_t>& cycle, std::span<const typename K::Point_2> points,
                        const K& k) {
  if (cycle.size() < 2) return;
  const auto compare = k.compare_xy_2_object();
  std::size_t best = 0;
  for (std::size_t i = 1; i < cycle.size(); ++i) {
    const Certified_sign s = compare(points[cycle[i]], points[cycle[best]]);
    if (s == Certified_sign::negative || (s == Certified_sign::zero && cycle[i] < cycle[best])) best = i;
  }
  std::rotate(cycle.begin(), cycle.begin() + static_cast<std::ptrdiff_t>(best), cycle.end());
}

}  // namespace relgeo::internal
