// relgeo/hull/internal/interior_prefilter.h — the Akl-Toussaint prefilter of
// Hull_options::discard_interior: input points certified to lie strictly
// inside the hull are dropped before sorting.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/hull/hull_result.h"
#include "relgeo/hull/internal/hull_input.h"

namespace relgeo::internal {

/// One bit per input point (n / 8 bytes).
class Point_bitmap {
 public:
  explicit Point_bitmap(std::size_t n) : words_((n + 63) / 64, 0) {}
  void set(std::size_t i) { words_[i / 64] |= std::uint64_t{1} << (i % 64); }
  bool test(std::size_t i) const { return (words_[i / 64] >> (i % 64)) & 1u; }
  std::size_t count() const {
    std::size_t c = 0;
    for (std::uint64_t w : words_) c += static_cast<std::size_t>(std::popcount(w));
    return c;
  }

 private:
  std::vector<std::uint64_t> words_;
};

/// The Akl-Toussaint prefilter of Hull_options::discard_interior: the points
/// NOT certified to lie strictly inside the polygon E of the input's extreme
/// points in the directions 0, 45, ..., 315 degrees (nullopt when it does not
/// apply: see Hull_options). A point strictly left of every directed edge of
/// a closed polygon sees each edge under a positive angle, so E winds around
/// it and it lies strictly inside the hull of E's vertices, which are kept;
/// this holds even if rounding chose the extreme points badly and E is not
/// convex, so the choice needs no exact arithmetic. Skipped (nullopt) when
/// fewer than half of 256 sampled points are dropped. Orientation tests are
/// counted in stats.predicate_calls.
template <class K, class Point>
std::optional<Point_bitmap> interior_prefilter(std::span<const Point> points, const K& k,
                                               Hull_result<Point>& stats) {
  if constexpr (!K::is_certified || !Floating_point_2<Point>) {
    return std::nullopt;
  } else {
    if (points.size() < 1024) return std::nullopt;  // not worth it
    // argmax of d . p for d = (1,0), (1,1), (0,1), (-1,1), (-1,0), (-1,-1), (0,-1), (1,-1).
    std::array<std::size_t, 8> extreme{};
    std::array<decltype(points[0].x), 8> best;
    best.fill(-std::numeric_limits<decltype(points[0].x)>::infinity());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto x = points[i].x, y = points[i].y;
      const decltype(x) value[8] = {x, x + y, y, y - x, -x, -x - y, -y, x - y};
      for (int d = 0; d < 8; ++d)
        if (value[d] > best[d]) best[d] = value[d], extreme[d] = i;
    }
    // Any closed polygon on kept points will do; an edge much shorter than
    // the polygon would make every test against it uncertain, so vertices
    // (nearly) equal to the previous one are skipped.
    using T = std::remove_cvref_t<decltype(points[0].x)>;
    const T size = (best[0] + best[4]) + (best[2] + best[6]);  // width + height (rounded)
    auto apart = [&](const Point& a, const Point& b) {
      return std::abs(a.x - b.x) + std::abs(a.y - b.y) > size * T(0x1p-20);
    };
    std::vector<Point> polygon;
    for (std::size_t e : extreme)
      if (polygon.empty() || apart(polygon.back(), points[e])) polygon.push_back(points[e]);
    while (polygon.size() > 1 && !apart(polygon.back(), polygon.front())) polygon.pop_back();
    if (polygon.size() < 3) return std::nullopt;

    const auto orientation = k.orientation_2_object();
    auto certainly_inside = [&](const Point& p) {
      for (std::size_t e = 0; e < polygon.size(); ++e) {
        ++stats.predicate_calls;
        if (!certainly(orientation(polygon[e], polygon[(e + 1) % polygon.size()], p), Certified_sign::positive))
          return false;
      }
      return true;
    };
    // Worth it only when most points are interior: decide on 256 evenly spaced ones.
    std::size_t sampled_inside = 0;
    for (std::size_t s = 0; s < 256; ++s) sampled_inside += certainly_inside(points[s * (points.size() / 256)]);
    if (sampled_inside < 128) return std::nullopt;

    // An axis-parallel box certified inside E (its corners are, and half-planes
    // are convex) answers most points with four comparisons.
    const auto& v = polygon;
    T lo_x = std::numeric_limits<T>::infinity(), hi_x = -lo_x, lo_y = lo_x, hi_y = -lo_x;
    for (const Point& p : v) lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x), lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
    const T cx = lo_x / 2 + hi_x / 2, cy = lo_y / 2 + hi_y / 2;
    T box[4] = {cx, cx, cy, cy};  // empty unless a shrunk bounding box fits
    for (T shrink : {T(0.9), T(0.7), T(0.5), T(0.3)}) {
      const T x0 = cx - shrink * (cx - lo_x), x1 = cx + shrink * (hi_x - cx);
      const T y0 = cy - shrink * (cy - lo_y), y1 = cy + shrink * (hi_y - cy);
      if (certainly_inside({x0, y0}) && certainly_inside({x1, y0}) && certainly_inside({x1, y1}) &&
          certainly_inside({x0, y1})) {
        box[0] = x0, box[1] = x1, box[2] = y0, box[3] = y1;
        break;
      }
    }
    Point_bitmap kept(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Point& p = points[i];
      const bool in_box = (p.x > box[0]) & (p.x < box[1]) & (p.y > box[2]) & (p.y < box[3]);
      if (!in_box && !certainly_inside(p)) kept.set(i);
    }
    return kept;
  }
}

}  // namespace relgeo::internal
