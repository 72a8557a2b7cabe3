// relgeo/core/internal/radix_sort.h — LSD radix sort of 64-bit words on a
// range of their bits: a key above, a payload below. The half-edge matchings
// (Mesh_topology, the Boolean's piece adjacency) and Face_bvh's Morton order
// sort this way in O(n).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace relgeo::internal {

/// Sorts `words` by their bits [low, low + bits), `digit` bits a pass
/// (stable: equal keys keep their order, so the payload below `low` is not
/// looked at). The counts of every pass come from one read of the words.
/// `scratch` is working memory (resized). \pre 0 < digit <= 16,
/// low + bits <= 64.
inline void radix_sort_bits(std::vector<std::uint64_t>& words, std::vector<std::uint64_t>& scratch, int low, int bits,
                            int digit = 11) {
  const int passes = (bits + digit - 1) / digit;
  if (passes <= 0 || words.size() < 2) return;
  const std::size_t buckets = std::size_t{1} << digit;
  // Pass p reads bits [low + p digit, ...): `digit` of them, the last pass
  // only those up to the key's end.
  const std::uint64_t full = (std::uint64_t{1} << digit) - 1;
  const std::uint64_t last = (std::uint64_t{1} << (bits - (passes - 1) * digit)) - 1;
  const auto mask = [&](int p) { return p + 1 < passes ? full : last; };
  // start[p * (buckets + 1) + d + 1]: how many words have digit d in pass p.
  std::vector<std::size_t> start(static_cast<std::size_t>(passes) * (buckets + 1), 0);
  for (std::uint64_t w : words) {
    for (int p = 0; p + 1 < passes; ++p) ++start[p * (buckets + 1) + ((w >> (low + p * digit)) & full) + 1];
    ++start[(passes - 1) * (buckets + 1) + ((w >> (low + (passes - 1) * digit)) & last) + 1];
  }
  scratch.resize(words.size());
  for (int p = 0; p < passes; ++p) {
    std::size_t* next = start.data() + p * (buckets + 1);
    for (std::size_t d = 1; d <= buckets; ++d) next[d] += next[d - 1];
    const int shift = low + p * digit;
    const std::uint64_t m = mask(p);
    for (std::uint64_t w : words) scratch[next[(w >> shift) & m]++] = w;
    words.swap(scratch);
  }
}

}  // namespace relgeo::internal
