// radix_sort_bits: an LSD radix sort of 64-bit words on a range of their
// bits, stable, against std::stable_sort on the same key.
#include "relgeo/core/internal/radix_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace relgeo::internal {
namespace {

std::vector<std::uint64_t> stable_sorted(std::vector<std::uint64_t> words, int low, int bits) {
  const std::uint64_t mask = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
  std::stable_sort(words.begin(), words.end(),
                   [&](std::uint64_t a, std::uint64_t b) { return ((a >> low) & mask) < ((b >> low) & mask); });
  return words;
}

// Key ranges of one digit and less (many equal keys: stability shows), keys
// whose width is no multiple of the digit, keys up to the top bit.
TEST(RadixSortBits, SortsLikeAStableSortOnTheKey) {
  std::mt19937_64 g(7);
  struct Case {
    int low, bits, digit;
    std::uint64_t key_range;
  };
  const Case cases[] = {{0, 64, 11, 0},     {32, 30, 10, 0}, {19, 45, 11, 0}, {7, 23, 11, 5},
                        {40, 24, 16, 3000}, {1, 3, 11, 0},   {20, 44, 8, 0},  {5, 25, 11, 0}};
  for (const Case& c : cases)
    for (std::size_t n : {0u, 1u, 2u, 1000u, 20000u}) {
      std::vector<std::uint64_t> words(n);
      for (std::uint64_t& w : words) {
        w = g();
        if (c.key_range) {  // few distinct keys: the payload below `low` must keep its order
          const std::uint64_t below = c.low == 0 ? 0 : w & ((std::uint64_t{1} << c.low) - 1);
          w = (g() % c.key_range) << c.low | below;
        }
      }
      const std::vector<std::uint64_t> expected = stable_sorted(words, c.low, c.bits);
      std::vector<std::uint64_t> scratch;
      radix_sort_bits(words, scratch, c.low, c.bits, c.digit);
      EXPECT_EQ(words, expected) << "low " << c.low << ", bits " << c.bits << ", digit " << c.digit << ", n " << n;
    }
}

// Bits right above the key are not looked at, even when the last pass's
// digit would reach them: only the key's order and the original order of
// equal keys.
TEST(RadixSortBits, IgnoresTheBitsAboveTheKey) {
  std::vector<std::uint64_t> words{0x13, 0x01, 0x03, 0x12, 0xF0000000000000F0};
  std::vector<std::uint64_t> scratch;
  radix_sort_bits(words, scratch, 0, 4, 3);
  EXPECT_EQ(words, (std::vector<std::uint64_t>{0xF0000000000000F0, 0x01, 0x12, 0x13, 0x03}));
}

}  // namespace
}  // namespace relgeo::internal
