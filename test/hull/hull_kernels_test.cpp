// Planar hulls typed across kernels: the classroom example A1, the output
// convention, degenerate and bad input (SPEC Sec. 3.1, issue "planar convex hulls").
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

#include "hull_inputs.h"
#include "relgeo/error.h"
#include "relgeo/hull.h"
#include "relgeo/kernel.h"
#include "relgeo/kernel/cgal_kernel.h"

namespace relgeo::test {
namespace {

enum class Algorithm { incremental, fortune, monotone };

template <class K>
Hull_result<typename K::Point_2> run(Algorithm a, const std::vector<typename K::Point_2>& pts) {
  switch (a) {
    case Algorithm::incremental: return graham_incremental<K>(pts);
    case Algorithm::fortune: return graham_fortune<K>(pts);
    default: return monotone_chain<K>(pts);
  }
}
constexpr Algorithm kAlgorithms[] = {Algorithm::incremental, Algorithm::fortune, Algorithm::monotone};

template <class K>
class HullKernels : public ::testing::Test {};
using Hull_kernels =
    ::testing::Types<Naive_kernel<double>, Naive_kernel<float>, Failsafe_kernel<double>,
                     Interval_kernel, Filtered_exact_kernel, Exact_kernel, Mpfr_kernel<53>,
                     Cgal_kernel<CGAL::Epick>>;
TYPED_TEST_SUITE(HullKernels, Hull_kernels);

TYPED_TEST(HullKernels, ClassroomExampleA1) {
  using K = TypeParam;
  const auto input = classroom_a1();
  const auto pts = to_kernel<K>(input);
  for (Algorithm a : kAlgorithms) {
    const auto r = run<K>(a, pts);
    const auto e = hull_error(input, r.indices);
    const auto b = hull_backward_error(input, r.indices);
    if constexpr (K::has_exact_predicates) {
      EXPECT_EQ(r.indices, classroom_a1_hull()) << K::name();
      EXPECT_EQ(e.value, 0.0);
      EXPECT_EQ(b.value, 0.0);
    }
    if constexpr (K::is_certified) {
      // Stable algorithms under certified kernels: convex, within their bound.
      if (a != Algorithm::incremental) {
        EXPECT_TRUE(e.convex) << K::name();
        const auto bound = graham_fortune_backward_error_bound<K>(input);
        if (bound) {
          EXPECT_LE(b.value, *bound) << K::name();
        }
        EXPECT_EQ(r.indices, classroom_a1_hull()) << K::name();
      }
    }
    ASSERT_TRUE(r.ok()) << K::name() << " " << r.failure;
  }
}

TEST(HullClassroomExample, NaiveIncrementalLosesTheExtremePointP4) {
  // The published failure (Kettner et al., Sec. 4.1; thesis Fig. 1.1).
  const auto input = classroom_a1();
  const auto r = graham_incremental<Naive_kernel<double>>(input);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(std::count(r.indices.begin(), r.indices.end(), 3u), 0) << "p4 should be lost";
  const auto b = hull_backward_error(input, r.indices);
  EXPECT_GT(b.value, 0.0);
  ASSERT_TRUE(b.worst_point.has_value());
  EXPECT_EQ(*b.worst_point, 3u);
  EXPECT_GT(hull_error(input, r.indices).value, 0.29);  // p4 is 8.04 from the computed hull, M = 27
  // The stable scan in plain double keeps it.
  EXPECT_EQ(graham_fortune<Naive_kernel<double>>(input).indices, classroom_a1_hull());
  EXPECT_EQ(graham_fortune<Failsafe_kernel<double>>(input).indices, classroom_a1_hull());
}

TYPED_TEST(HullKernels, OutputConventionOnRandomInput) {
  using K = TypeParam;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto input = uniform_points(seed, 200);
    const auto exact = exact_hull(input);
    for (Algorithm a : kAlgorithms) {
      const auto r = run<K>(a, to_kernel<K>(input));
      ASSERT_TRUE(r.ok());
      ASSERT_EQ(r.points.size(), r.indices.size());
      // Random input is far from degenerate: every kernel finds the exact hull.
      const auto got = points_at(input, r.indices);
      if constexpr (!std::is_same_v<typename K::FT, float>) {
        EXPECT_EQ(got, exact) << K::name() << " seed " << seed;
      }
    }
  }
}

TYPED_TEST(HullKernels, DegenerateInputHasDocumentedResults) {
  using K = TypeParam;
  const K k;
  for (Algorithm a : kAlgorithms) {
    EXPECT_TRUE(run<K>(a, {}).indices.empty());
    EXPECT_EQ(run<K>(a, to_kernel<K>({{2, 3}})).indices, (std::vector<std::size_t>{0}));
    // All equal: the smallest index.
    EXPECT_EQ(run<K>(a, to_kernel<K>({{1, 1}, {1, 1}, {1, 1}})).indices, (std::vector<std::size_t>{0}));
    // Collinear: the two extreme points, lexicographically smallest first.
    EXPECT_EQ(run<K>(a, to_kernel<K>({{1, 1}, {3, 3}, {0, 0}, {2, 2}, {3, 3}})).indices,
              (std::vector<std::size_t>{2, 1}));
    // Duplicated hull vertices and a point on an edge: smallest indices, no edge point.
    EXPECT_EQ(run<K>(a, to_kernel<K>({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {4, 0}, {2, 0}, {0, 0}, {1, 1}})).indices,
              (std::vector<std::size_t>{0, 1, 2, 3}));
  }
  (void)k;
}

TYPED_TEST(HullKernels, SignedZerosAreOnePointReportedByItsSmallestIndex) {
  using K = TypeParam;
  // -0.0 == 0.0: (0, -0) at index 1 and (-0, 0) at index 3 are one hull vertex.
  const auto pts = to_kernel<K>({{4, 0}, {0, -0.0}, {2, 3}, {-0.0, 0}, {1, 1}});
  for (Algorithm a : kAlgorithms)
    EXPECT_EQ(run<K>(a, pts).indices, (std::vector<std::size_t>{1, 0, 2})) << K::name();
}

TYPED_TEST(HullKernels, NonFiniteInputIsRejectedWithATypedError) {
  using K = TypeParam;
  if constexpr (!K::has_exact_constructions && !std::is_same_v<K, Mpfr_kernel<53>>) {
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
      const auto pts = to_kernel<K>({{0, 0}, {1, bad}, {2, 0}});
      for (Algorithm a : kAlgorithms) EXPECT_THROW(run<K>(a, pts), Non_finite_input) << K::name();
    }
  }
}

// Exact_kernel runs on the points' doubles (Filtered_exact_kernel) when every
// coordinate is one exactly, and in rationals otherwise: both paths must give
// the same hull. x / 3 + 1 / 7 is never a double, and scaling and translating
// keep every orientation sign.
TEST(HullExactKernel, RationalAndDoublePathsAgree) {
  const Exact_kernel k;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    // 60 points of a 9 x 9 integer grid: duplicates and collinear triples abound.
    std::mt19937_64 random(seed);
    std::vector<P2> grid(60);
    for (auto& p : grid) p = {double(random() % 9), double(random() % 9)};
    std::vector<Exact_kernel::Point_2> thirds, integers;
    for (const auto& p : grid) {
      integers.push_back(k.construct_point_2_object()(p.x, p.y));
      const mpq_class shift(1, 7);
      thirds.push_back({mpq_class(integers.back().x / 3 + shift), mpq_class(integers.back().y / 3 + shift)});
      ASSERT_FALSE(Exact_kernel::exact_double_point(thirds.back()).has_value());
    }
    for (Algorithm a : kAlgorithms) {
      const auto on_doubles = run<Exact_kernel>(a, integers);
      const auto in_rationals = run<Exact_kernel>(a, thirds);
      EXPECT_EQ(in_rationals.indices, on_doubles.indices) << seed;
      EXPECT_EQ(in_rationals.predicate_calls, on_doubles.predicate_calls) << seed;
      EXPECT_EQ(on_doubles.indices, run<Filtered_exact_kernel>(a, grid).indices) << seed;
    }
  }
}

// The double-point hook (kernel/kernel_for_number.h) is what sends
// Exact_kernel to doubles: a kernel naming another Double_point_kernel gets
// that one, once per run, for every algorithm, and only when every point is a
// double exactly.
static_assert(Has_double_point_kernel<Exact_kernel>);
static_assert(!Has_double_point_kernel<Filtered_exact_kernel>);
static_assert(!Has_double_point_kernel<Interval_kernel>);
static_assert(!Has_double_point_kernel<Failsafe_kernel<double>>);
struct Counted_double_kernel : Filtered_exact_kernel {
  static inline int runs = 0;
  Counted_double_kernel() { ++runs; }
};
struct Exact_kernel_with_counted_hook : Exact_kernel {
  using Double_point_kernel = Counted_double_kernel;
};
TEST(HullExactKernel, TheFrameConsultsTheDoublePointHookOnce) {
  static_assert(Has_double_point_kernel<Exact_kernel_with_counted_hook>);
  const Exact_kernel k;
  const std::vector<Exact_kernel::Point_2> doubles{k.construct_point_2_object()(0, 0), k.construct_point_2_object()(4, 0),
                                                   k.construct_point_2_object()(1, 3), k.construct_point_2_object()(1, 1)};
  std::vector<Exact_kernel::Point_2> not_doubles = doubles;
  not_doubles[3].x = mpq_class(1, 3);
  for (Algorithm a : kAlgorithms) {
    Counted_double_kernel::runs = 0;
    const auto on_doubles = run<Exact_kernel_with_counted_hook>(a, doubles);
    EXPECT_EQ(Counted_double_kernel::runs, 1);
    EXPECT_EQ(on_doubles.indices, (std::vector<std::size_t>{0, 1, 2}));
    EXPECT_EQ(on_doubles.points, (std::vector<Exact_kernel::Point_2>{doubles[0], doubles[1], doubles[2]}));
    Counted_double_kernel::runs = 0;
    EXPECT_EQ(run<Exact_kernel_with_counted_hook>(a, not_doubles).indices, (std::vector<std::size_t>{0, 1, 2}));
    EXPECT_EQ(Counted_double_kernel::runs, 0);
  }
}

// Large inputs (where the interior prefilter runs) reject NaN and infinity
// before anything else, wherever the bad point sits.
TEST(HullBadInput, NonFiniteCoordinatesInLargeInputs) {
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()})
    for (std::size_t at : {std::size_t{0}, std::size_t{1234}, std::size_t{4999}}) {
      auto input = uniform_points(5, 5000);
      input[at].y = bad;
      EXPECT_THROW(graham_fortune<Failsafe_kernel<double>>(input), Non_finite_input) << at;
      EXPECT_THROW(monotone_chain<Filtered_exact_kernel>(input), Non_finite_input) << at;
      EXPECT_THROW(graham_fortune<Filtered_exact_kernel>(input, {}, Hull_options{.discard_interior = false}),
                   Non_finite_input)
          << at;
    }
}

// Degenerate large inputs keep their documented results with the prefilter on.
TEST(HullDegenerateInput, LargeEqualAndCollinearInputs) {
  const std::vector<P2> equal(3000, P2{0.25, -7});
  std::vector<P2> collinear;
  for (int i = 0; i < 3000; ++i) collinear.push_back({double((i * 7919) % 3000), 2.0 * ((i * 7919) % 3000) + 1});
  const std::size_t first = 0, last = static_cast<std::size_t>(std::find(collinear.begin(), collinear.end(), P2{2999, 5999}) - collinear.begin());
  const std::size_t lowest = static_cast<std::size_t>(std::find(collinear.begin(), collinear.end(), P2{0, 1}) - collinear.begin());
  EXPECT_EQ(graham_fortune<Failsafe_kernel<double>>(equal).indices, (std::vector<std::size_t>{first}));
  EXPECT_EQ(monotone_chain<Filtered_exact_kernel>(equal).indices, (std::vector<std::size_t>{first}));
  EXPECT_EQ(graham_fortune<Failsafe_kernel<double>>(collinear).indices, (std::vector<std::size_t>{lowest, last}));
  EXPECT_EQ(monotone_chain<Filtered_exact_kernel>(collinear).indices, (std::vector<std::size_t>{lowest, last}));
}

// Chains computed with wrong naive answers can name a sorted position twice;
// each occurrence must get the point's smallest input index (a regression:
// naive float monotone_chain on a large-range input reported index -1).
TEST(HullSortedInput, RepeatedPositionsShareTheSmallestIndex) {
  const std::vector<P2> input{{3, 3}, {1, 1}, {2, 2}, {1, 1}, {0, 5}};
  const internal::Sorted_input<Filtered_exact_kernel> sorted(input, Filtered_exact_kernel{}, nullptr);
  ASSERT_EQ(sorted.size(), 4u);  // (0,5) (1,1) (2,2) (3,3)
  const std::vector<std::size_t> positions{1, 3, 1, 0, 3};
  EXPECT_EQ(sorted.indices(positions), (std::vector<std::size_t>{1, 0, 1, 4, 0}));
}

TEST(HullIncremental, NeverHangsOrCrashesOnAdversarialInput) {
  // Naive double on thousands of near-degenerate sets: every run returns, and
  // its indices are valid input indices; failures are reported, not hidden.
  std::size_t failed = 0, lost = 0;
  for (std::uint64_t seed = 0; seed < 4000; ++seed) {
    const auto input = near_degenerate_points(seed, static_cast<int>(seed % 4));
    const auto r = graham_incremental<Naive_kernel<double>>(input);
    for (std::size_t i : r.indices) ASSERT_LT(i, input.size());
    failed += !r.ok();
    lost += hull_backward_error(input, r.indices).value > 0;
  }
  std::printf("[ incremental/double ] 4000 near-degenerate sets: %zu non-terminations, %zu with lost points\n", failed, lost);
  EXPECT_GT(lost + failed, 0u) << "the naive incremental algorithm is expected to fail somewhere";
}

}  // namespace
}  // namespace relgeo::test
