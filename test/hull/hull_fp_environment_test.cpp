// The hulls and their error measures in every floating-point environment a
// caller can set: a certified kernel gives the same hull as in the default
// environment (the algorithms establish it), on near-degenerate sets and on
// sets whose coordinates are subnormal (which denormals-are-zero reads as 0:
// sorted naively, distinct points would merge).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hull_inputs.h"
#include "relgeo/error.h"
#include "relgeo/hull.h"
#include "relgeo/kernel.h"
#include "support/fp_environments.h"

namespace relgeo::test {
namespace {

std::vector<std::vector<P2>> environment_inputs() {
  std::vector<std::vector<P2>> sets;
  for (std::uint64_t seed = 0; seed < 40; ++seed) sets.push_back(near_degenerate_points(seed, static_cast<int>(seed % 4)));
  std::mt19937_64 g(5);
  for (int s = 0; s < 20; ++s) {  // subnormal coordinates
    std::vector<P2> pts;
    for (int i = 0; i < 30; ++i)
      pts.push_back({std::ldexp(static_cast<double>(g() % 64) - 32, -1070), std::ldexp(static_cast<double>(g() % 64) - 32, -1068)});
    sets.push_back(pts);
  }
  sets.push_back(classroom_a1());
  return sets;
}

template <class K, class Hull>
void expect_same_hull_in_every_environment(Hull hull) {
  const K k;
  for (const auto& input : environment_inputs()) {
    const auto points = to_kernel<K>(input);
    const auto reference = hull(points, k);
    const auto error = hull_error(input, reference.indices);
    const auto backward = hull_backward_error(input, reference.indices);
    for (const auto& s : non_default_fp_environments()) {
      Hull_result<typename K::Point_2> r;
      Hull_error e;
      Hull_backward_error b;
      {
        const Scoped_fp_environment environment(s);
        r = hull(points, k);
        e = hull_error(input, r.indices);
        b = hull_backward_error(input, r.indices);
      }
      ASSERT_EQ(r.indices, reference.indices) << K::name() << " under " << s.name;
      EXPECT_EQ(e.value, error.value) << s.name;
      EXPECT_EQ(b.value, backward.value) << s.name;
    }
  }
}

auto fortune = [](const auto& points, const auto& k) { return graham_fortune(points, k); };
auto chain = [](const auto& points, const auto& k) { return monotone_chain(points, k); };

TEST(HullFpEnvironment, FortuneFailsafe) { expect_same_hull_in_every_environment<Failsafe_kernel<double>>(fortune); }
TEST(HullFpEnvironment, FortuneFiltered) { expect_same_hull_in_every_environment<Filtered_exact_kernel>(fortune); }
TEST(HullFpEnvironment, ChainFiltered) { expect_same_hull_in_every_environment<Filtered_exact_kernel>(chain); }
TEST(HullFpEnvironment, ChainExact) { expect_same_hull_in_every_environment<Exact_kernel>(chain); }
TEST(HullFpEnvironment, FortuneInterval) { expect_same_hull_in_every_environment<Interval_kernel>(fortune); }

TEST(HullFpEnvironment, SubnormalPointsAreHardUnderDenormalsAreZero) {
  // Why the hull needs the default environment: the naive kernel, which
  // computes in the caller's, merges distinct subnormal points there.
#if defined(__x86_64__) || defined(__i386__)
  std::size_t differ = 0;
  for (const auto& input : environment_inputs()) {
    const auto reference = monotone_chain<Naive_kernel<double>>(input);
    const Scoped_fp_environment daz({"denormals-are-zero", false, true, 0});
    differ += monotone_chain<Naive_kernel<double>>(input).indices != reference.indices;
  }
  EXPECT_GT(differ, 0u);
#else
  GTEST_SKIP() << "denormals-are-zero is set on x86 only";
#endif
}

}  // namespace
}  // namespace relgeo::test
