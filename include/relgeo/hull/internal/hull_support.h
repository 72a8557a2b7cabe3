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

/// The input sorted lexicographically (ties by index), equal points reduced to
/// their smallest index; position i has point(i) and input index index(i).
///
/// For relgeo's floating-point points (finite: callers check first) the
/// coordinates are compared directly, which is exact, on a compact copy
/// sorted with std::sort: the sort is most of a hull's running time, and
/// comparing through the kernel's certified functor on scattered indices was
/// 2-3x slower (benchmark/hull). Other point types are sorted through the
/// kernel's compare_xy_2; an `uncertain` comparison counts as `equal` and is
/// reported through *undecided.
template <class K>
class Sorted_input {
  using Point = typename K::Point_2;
  static constexpr bool direct = requires(const Point& p) {
    requires std::is_floating_point_v<std::remove_cvref_t<decltype(p.x)>>;
    requires std::is_same_v<Point, relgeo::Point_2<std::remove_cvref_t<decltype(p.x)>>>;
  };
  struct Record {
    Point p;
    std::size_t index;
  };

 public:
  Sorted_input(std::span<const Point> points, const K& k, std::size_t* undecided) : points_(points) {
    if constexpr (direct) {
      records_.reserve(points.size());
      for (std::size_t i = 0; i < points.size(); ++i) records_.push_back({points[i], i});
      std::sort(records_.begin(), records_.end(), [](const Record& a, const Record& b) {
        if (a.p.x != b.p.x) return a.p.x < b.p.x;
        if (a.p.y != b.p.y) return a.p.y < b.p.y;
        return a.index < b.index;
      });
      records_.erase(std::unique(records_.begin(), records_.end(),
                                 [](const Record& a, const Record& b) { return a.p == b.p; }),
                     records_.end());
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
    if constexpr (direct) return records_.size();
    else return order_.size();
  }
  const Point& point(std::size_t i) const {
    if constexpr (direct) return records_[i].p;
    else return points_[order_[i]];
  }
  std::size_t index(std::size_t i) const {
    if constexpr (direct) return records_[i].index;
    else return order_[i];
  }

 private:
  std::span<const Point> points_;
  std::vector<Record> records_;      // direct comparison
  std::vector<std::size_t> order_;   // through the kernel
};

/// Fills result.points from result.indices.
template <class Point>
void attach_points(Hull_result<Point>& r, std::span<const Point> points) {
  r.points.clear();
  r.points.reserve(r.indices.size());
  for (std::size_t i : r.indices) r.points.push_back(points[i]);
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
