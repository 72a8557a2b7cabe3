// certified_sort: a sort by a three-way Certified_sign comparison that stops
// at the first `uncertain` instead of handing std::sort something that is no
// strict weak ordering.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "relgeo/core/certified_sort.h"

namespace relgeo {
namespace {

Certified_sign three_way(int a, int b) {
  return a < b ? Certified_sign::negative : (b < a ? Certified_sign::positive : Certified_sign::zero);
}

TEST(CertifiedSort, SortsByDefiniteAnswers) {
  std::mt19937 g(3);
  std::vector<int> v(1000);
  for (int& x : v) x = static_cast<int>(g() % 100);
  std::vector<int> expected = v;
  std::sort(expected.begin(), expected.end());
  EXPECT_TRUE(certified_sort(v.begin(), v.end(), three_way));
  EXPECT_EQ(v, expected);
}

TEST(CertifiedSort, StableKeepsTheOrderOfEqualElements) {
  std::vector<std::pair<int, int>> v;
  for (int i = 0; i < 200; ++i) v.push_back({i % 7, i});
  EXPECT_TRUE(certified_sort(
      v.begin(), v.end(), [](const auto& a, const auto& b) { return three_way(a.first, b.first); }, /*stable=*/true));
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (v[i - 1].first == v[i].first) {
      EXPECT_LT(v[i - 1].second, v[i].second);
    }
  }
}

TEST(CertifiedSort, AnUncertainAnswerFailsTheSort) {
  // Values closer than 3 cannot be ordered (as intervals of width 3 would
  // be): no strict weak ordering, which certified_sort must not pass on.
  const auto doubtful = [](int a, int b) {
    if (a != b && (a - b < 3 && b - a < 3)) return Certified_sign::uncertain;
    return three_way(a, b);
  };
  std::vector<int> spread{40, 10, 30, 0, 20};
  EXPECT_TRUE(certified_sort(spread.begin(), spread.end(), doubtful));
  EXPECT_EQ(spread, (std::vector<int>{0, 10, 20, 30, 40}));
  for (bool stable : {false, true}) {
    std::mt19937 g(5);
    std::vector<int> v(500);
    for (int& x : v) x = static_cast<int>(g() % 1000);
    EXPECT_FALSE(certified_sort(v.begin(), v.end(), doubtful, stable));
    EXPECT_EQ(v.size(), 500u);
  }
}

}  // namespace
}  // namespace relgeo
