// relgeo/joining/internal/point_tree.h — a static kd-tree over points of
// dimension D (doubles): nearest neighbours and radius queries. Built once in
// O(n log n) (median splits), leaves of up to 8 points; the points are stored
// in tree order with their original indices.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace relgeo::internal {

template <int D>
class Point_tree {
 public:
  using Point = std::array<double, D>;

  Point_tree() = default;
  explicit Point_tree(std::vector<Point> points) : points_(std::move(points)) {
    index_.resize(points_.size());
    std::iota(index_.begin(), index_.end(), std::uint32_t{0});
    if (!points_.empty()) build(0, static_cast<std::uint32_t>(points_.size()));
    std::vector<Point> ordered(points_.size());
    for (std::size_t i = 0; i < index_.size(); ++i) ordered[i] = points_[index_[i]];
    points_ = std::move(ordered);
  }

  std::size_t size() const { return points_.size(); }

  /// The k nearest points to q as (squared distance, original index), nearest first.
  std::vector<std::pair<double, std::uint32_t>> nearest(const Point& q, std::size_t k) const {
    std::vector<std::pair<double, std::uint32_t>> best;
    if (nodes_.empty() || k == 0) return best;
    search_nearest(0, q, k, best);
    return best;
  }

  /// Every point within distance r of q (original indices, any order).
  template <class F>
  void for_each_within(const Point& q, double r, F&& f) const {
    if (!nodes_.empty()) search_radius(0, q, r * r, f);
  }

 private:
  struct Node {
    std::uint32_t begin, end;  // points in [begin, end)
    std::uint32_t left = 0, right = 0;  // children (0: leaf)
    Point lo, hi;  // bounding box
  };

  std::uint32_t build(std::uint32_t begin, std::uint32_t end) {
    const auto id = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({begin, end, 0, 0, {}, {}});
    Point lo, hi;
    lo.fill(std::numeric_limits<double>::infinity()), hi.fill(-std::numeric_limits<double>::infinity());
    for (std::uint32_t i = begin; i < end; ++i)
      for (int d = 0; d < D; ++d) lo[d] = std::min(lo[d], points_[index_[i]][d]), hi[d] = std::max(hi[d], points_[index_[i]][d]);
    nodes_[id].lo = lo, nodes_[id].hi = hi;
    if (end - begin <= 8) return id;
    int axis = 0;
    for (int d = 1; d < D; ++d)
      if (hi[d] - lo[d] > hi[axis] - lo[axis]) axis = d;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(index_.begin() + begin, index_.begin() + mid, index_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) { return points_[a][axis] < points_[b][axis]; });
    const std::uint32_t l = build(begin, mid);
    const std::uint32_t r = build(mid, end);
    nodes_[id].left = l, nodes_[id].right = r;
    return id;
  }

  static double box_distance2(const Node& n, const Point& q) {
    double s = 0;
    for (int d = 0; d < D; ++d) {
      const double e = q[d] < n.lo[d] ? n.lo[d] - q[d] : (q[d] > n.hi[d] ? q[d] - n.hi[d] : 0.0);
      s += e * e;
    }
    return s;
  }
  static double distance2(const Point& a, const Point& b) {
    double s = 0;
    for (int d = 0; d < D; ++d) s += (a[d] - b[d]) * (a[d] - b[d]);
    return s;
  }

  void search_nearest(std::uint32_t id, const Point& q, std::size_t k,
                      std::vector<std::pair<double, std::uint32_t>>& best) const {
    const Node& n = nodes_[id];
    if (best.size() == k && box_distance2(n, q) > best.back().first) return;
    if (n.left == 0) {
      for (std::uint32_t i = n.begin; i < n.end; ++i) {
        const std::pair<double, std::uint32_t> c{distance2(points_[i], q), index_[i]};
        if (best.size() < k) best.insert(std::upper_bound(best.begin(), best.end(), c), c);
        else if (c < best.back()) best.pop_back(), best.insert(std::upper_bound(best.begin(), best.end(), c), c);
      }
      return;
    }
    const bool left_first = box_distance2(nodes_[n.left], q) <= box_distance2(nodes_[n.right], q);
    search_nearest(left_first ? n.left : n.right, q, k, best);
    search_nearest(left_first ? n.right : n.left, q, k, best);
  }

  template <class F>
  void search_radius(std::uint32_t id, const Point& q, double r2, F& f) const {
    const Node& n = nodes_[id];
    if (box_distance2(n, q) > r2) return;
    if (n.left == 0) {
      for (std::uint32_t i = n.begin; i < n.end; ++i)
        if (distance2(points_[i], q) <= r2) f(index_[i]);
      return;
    }
    search_radius(n.left, q, r2, f);
    search_radius(n.right, q, r2, f);
  }

  std::vector<Point> points_;
  std::vector<std::uint32_t> index_;
  std::vector<Node> nodes_;
};

}  // namespace relgeo::internal
