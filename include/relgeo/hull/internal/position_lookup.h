// relgeo/hull/internal/position_lookup.h — index recovery of the sorted hull
// input: which input index each hull vertex came from, found by one pass
// over the input through a hash table of the few points asked for.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <type_traits>
#include <vector>

namespace relgeo::internal {

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

}  // namespace relgeo::internal
