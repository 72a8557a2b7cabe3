// relgeo/hull/internal/hull_support.h — input checks, lexicographic sorting and
// output normalisation shared by the hull algorithms.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include <boost/sort/pdqsort/pdqsort.hpp>

#include "relgeo/core/errors.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/hull/hull_result.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
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
      finite = is_finite_number(x) && is_finite_number(y);
    if (!finite)
      throw Non_finite_input(std::string(who) + ": point " + std::to_string(i) +
                             " has a NaN or infinite coordinate");
  }
}

/// Open-addressing hash map from the points sorted[positions[j]] (distinct,
/// finite, floating-point) to j, at most half full. Index is the slot's
/// integer type (32 bits unless the input has 2^32 points). The index
/// recovery of Sorted_input asks it once per input point; a slot holds the
/// sorted position next to j, so a lookup touches the slot and one point,
/// both of which prefetch() can start loading ahead of time.
template <class Point, class Index>
class Position_lookup {
 public:
  static constexpr std::size_t none = static_cast<std::size_t>(-1);

  Position_lookup(std::span<const Point> sorted, std::span<const std::size_t> positions) : sorted_(sorted) {
    std::size_t size = 16;
    while (size < 2 * positions.size()) size *= 2;
    mask_ = size - 1;
    slots_.assign(size, Slot{empty, empty});
    for (std::size_t j = 0; j < positions.size(); ++j) {
      std::size_t s = hash(sorted[positions[j]]) & mask_;
      while (slots_[s].position != empty && slots_[s].position != positions[j]) s = (s + 1) & mask_;
      if (slots_[s].position == empty)  // a repeated position keeps its first j
        slots_[s] = Slot{static_cast<Index>(positions[j]), static_cast<Index>(j)};
    }
  }
  /// The first j with sorted[positions[j]] == p (== on coordinates, so -0.0
  /// finds 0.0), or none.
  std::size_t find(const Point& p) const {
    for (std::size_t s = hash(p) & mask_;; s = (s + 1) & mask_) {
      const Slot slot = slots_[s];
      if (slot.position == empty) return none;
      if (sorted_[slot.position] == p) return slot.j;
    }
  }
  /// Starts loading p's first slot (stage 1), or the point it names (stage
  /// 2, once the slot is near).
  void prefetch_slot(const Point& p) const { __builtin_prefetch(&slots_[hash(p) & mask_]); }
  void prefetch_point(const Point& p) const {
    const Slot slot = slots_[hash(p) & mask_];
    if (slot.position != empty) __builtin_prefetch(&sorted_[slot.position]);
  }

 private:
  using T = std::remove_cvref_t<decltype(Point{}.x)>;
  static constexpr Index empty = ~Index{0};
  struct Slot {
    Index position, j;
  };
  static std::uint64_t bits(T v) {
    v += T(0);  // -0 becomes +0: equal points must hash alike
    if constexpr (sizeof(T) == 8) return std::bit_cast<std::uint64_t>(v);
    else if constexpr (sizeof(T) == 4) return std::bit_cast<std::uint32_t>(v);
    else return std::hash<T>{}(v);  // long double: padding bits are not the value
  }
  static std::size_t hash(const Point& p) {
    const std::uint64_t h = (bits(p.x) ^ (bits(p.y) * 0x9E3779B97F4A7C15ull)) * 0xBF58476D1CE4E5B9ull;
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
  std::span<const Point> sorted_;
  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
};

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
  if constexpr (!K::is_certified ||
                !requires(const Point& p) {
                  requires std::is_floating_point_v<std::remove_cvref_t<decltype(p.x)>>;
                  requires std::is_same_v<Point, relgeo::Point_2<std::remove_cvref_t<decltype(p.x)>>>;
                }) {
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
        if (orientation(polygon[e], polygon[(e + 1) % polygon.size()], p) != Certified_sign::positive) return false;
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
  static constexpr bool direct = requires(const Point& p) {
    requires std::is_floating_point_v<std::remove_cvref_t<decltype(p.x)>>;
    requires std::is_same_v<Point, relgeo::Point_2<std::remove_cvref_t<decltype(p.x)>>>;
  };

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
      struct Undecidable {};
      auto decided = [&](std::size_t a, std::size_t b) {
        const Certified_sign s = compare(points[a], points[b]);
        if (!is_certain(s)) throw Undecidable{};
        return s;
      };
      for (std::size_t i = 0; i < points.size(); ++i)
        if (!keep || keep->test(i)) order_.push_back(i);
      try {
        std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
          return decided(a, b) == Certified_sign::negative;
        });
        std::size_t kept = 0;
        for (std::size_t i : order_)
          if (kept == 0 || decided(order_[kept - 1], i) != Certified_sign::zero) order_[kept++] = i;
        order_.resize(kept);
      } catch (const Undecidable&) {
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

/// The failure a hull algorithm reports when the kernel cannot order its input.
inline constexpr const char* undecidable_order_failure = "undecidable-order";

/// Fills result.points from result.indices.
template <class Point>
void attach_points(Hull_result<Point>& r, std::span<const Point> points) {
  r.points.clear();
  r.points.reserve(r.indices.size());
  for (std::size_t i : r.indices) r.points.push_back(points[i]);
}

/// A kernel with exact predicates that can give its points' exact double
/// values (Exact_kernel::exact_double_point).
template <class K>
concept Exact_on_doubles = K::has_exact_predicates && requires(const typename K::Point_2& p) {
  { K::exact_double_point(p) } -> std::same_as<std::optional<relgeo::Point_2<double>>>;
};

/// When every input point of an Exact_on_doubles kernel is exactly a point of
/// doubles, `hull(doubles, Filtered_exact_kernel{})`, relabelled with the
/// input's points: every predicate there answers the same exact sign on the
/// same values, so the hull and its statistics are the ones K would produce,
/// without rational arithmetic. nullopt (nothing computed) otherwise.
template <class K, class Hull>
  requires Exact_on_doubles<K>
std::optional<Hull_result<typename K::Point_2>> hull_on_exact_doubles(
    std::span<const typename K::Point_2> points, Hull&& hull) {
  std::vector<relgeo::Point_2<double>> doubles(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::optional<relgeo::Point_2<double>> d = K::exact_double_point(points[i]);
    if (!d) return std::nullopt;
    doubles[i] = *d;
  }
  Hull_result<relgeo::Point_2<double>> h = hull(std::span<const relgeo::Point_2<double>>(doubles),
                                                Filtered_exact_kernel{});
  Hull_result<typename K::Point_2> r;
  r.status = h.status;
  r.failure = std::move(h.failure);
  r.indices = std::move(h.indices);
  r.predicate_calls = h.predicate_calls;
  r.uncertain_answers = h.uncertain_answers;
  attach_points(r, points);
  return r;
}

/// The frame shared by the sorting hull algorithms: checks the input, drops
/// certainly interior points (interior_prefilter, if asked), sorts the rest
/// (Sorted_input), answers the 0-2 distinct point cases, lets `scan(sorted,
/// chain, result)` build the hull as positions of the sorted input (for 3 or
/// more distinct points), and returns the result with input indices and points.
template <class K, class Scan>
Hull_result<typename K::Point_2> sorted_hull(std::span<const typename K::Point_2> points, const K& k,
                                             const Hull_options& options, const char* who, Scan&& scan) {
  using Point = typename K::Point_2;
  const Default_fp_environment_if<K::is_certified> environment;
  require_finite_points<Point>(points, who);
  Hull_result<Point> r;
  std::optional<Point_bitmap> kept;
  if (options.discard_interior) kept = interior_prefilter(points, k, r);
  const Sorted_input<K> sorted(points, k, &r.uncertain_answers, kept ? &*kept : nullptr);
  if (sorted.undecidable()) {
    r.status = Hull_status::failed;
    r.failure = undecidable_order_failure;
    return r;
  }
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
/// point (ties by index), as the output convention asks. Only the start of
/// the cycle depends on it: an `uncertain` comparison keeps the earlier
/// candidate.
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
