// The exact error measures: point location, distances, E of eq. (3.2), the
// certificate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "hull_inputs.h"
#include "relgeo/error.h"
#include "relgeo/hull.h"
#include "relgeo/kernel.h"

namespace relgeo::test {
namespace {

const std::vector<P2> kSquare{{0, 0}, {4, 0}, {4, 4}, {0, 4}};

TEST(ConvexPolygon, LocateIsExact) {
  EXPECT_EQ(locate(kSquare, {2, 2}), Polygon_side::inside);
  EXPECT_EQ(locate(kSquare, {0, 2}), Polygon_side::boundary);
  EXPECT_EQ(locate(kSquare, {2, 0}), Polygon_side::boundary);
  EXPECT_EQ(locate(kSquare, {0, 0}), Polygon_side::boundary);
  EXPECT_EQ(locate(kSquare, {4, 4}), Polygon_side::boundary);
  EXPECT_EQ(locate(kSquare, {2, -0x1p-60}), Polygon_side::outside);
  EXPECT_EQ(locate(kSquare, {5, 2}), Polygon_side::outside);
  const std::vector<P2> segment{{0, 0}, {2, 2}};
  EXPECT_EQ(locate(segment, {1, 1}), Polygon_side::boundary);
  EXPECT_EQ(locate(segment, {3, 3}), Polygon_side::outside);
}

TEST(ConvexPolygon, DistancesAreExactAndRoundedUp) {
  EXPECT_EQ(squared_distance(kSquare, {7, 8}), 9 + 16);
  EXPECT_EQ(squared_distance(kSquare, {2, 6}), 4);
  const std::vector<P2> origin{{0, 0}};
  EXPECT_EQ(hausdorff_distance(origin, std::vector<P2>{{3, 4}}), 5.0);
  const double r = hausdorff_distance(origin, std::vector<P2>{{1, 1}});
  EXPECT_GE(mpq_class(r) * mpq_class(r), 2);  // never below the true sqrt(2)
  EXPECT_EQ(hausdorff_distance(origin, std::vector<P2>{{3, 4}}, 2.0), 2.5);  // over the scale
  EXPECT_THROW((void)hausdorff_distance(origin, origin, 0.0), Invalid_input);
  EXPECT_EQ(hausdorff_distance(kSquare, std::vector<P2>{{0, 0}, {4, 0}, {4, 5}, {0, 4}}), 1.0);
}

TEST(HullErrorMeasures, NonConvexOutputHasInfiniteErrorAndCertificate) {
  const std::vector<P2> input{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}};
  const std::vector<std::size_t> reflex{0, 1, 4, 2, 3};  // (2,2) is inside: a reflex vertex
  EXPECT_FALSE(hull_error(input, reflex).convex);
  EXPECT_EQ(hull_error(input, reflex).value, std::numeric_limits<double>::infinity());
  EXPECT_EQ(hull_backward_error(input, reflex).value, std::numeric_limits<double>::infinity());
  const std::vector<std::size_t> right{0, 1, 2, 3};
  EXPECT_EQ(hull_error(input, right).value, 0.0);
  const std::vector<std::size_t> lost{0, 1, 3};  // (4,4) lost: at distance sqrt(8) from the triangle, M = 4
  const auto b = hull_backward_error(input, lost);
  EXPECT_EQ(b.moved_points, (std::vector<std::size_t>{2}));
  EXPECT_GE(b.value, std::sqrt(8.0) / 4);
  EXPECT_LE(b.value, std::nextafter(std::sqrt(8.0) / 4, 1.0));
  EXPECT_THROW(hull_error(input, std::vector<std::size_t>{0, 9}), Invalid_input);
}

TEST(ConvexPolygon, APolygonIsJudgedInTheOrderGiven) {
  EXPECT_TRUE(is_ccw_strictly_convex_polygon(kSquare));
  const std::vector<P2> clockwise{{0, 0}, {0, 4}, {4, 4}, {4, 0}};
  EXPECT_FALSE(is_ccw_strictly_convex_polygon(clockwise));
  const std::vector<P2> bow_tie{{0, 0}, {4, 0}, {0, 4}, {4, 4}};  // the square's vertices, crossed
  EXPECT_FALSE(is_ccw_strictly_convex_polygon(bow_tie));
  // A pentagram turns left at every vertex but winds twice.
  std::vector<P2> pentagon, pentagram;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * 3.141592653589793 * i / 5;
    pentagon.push_back({std::cos(a), std::sin(a)});
  }
  for (int i = 0; i < 5; ++i) pentagram.push_back(pentagon[(2 * i) % 5]);
  EXPECT_TRUE(is_ccw_strictly_convex_polygon(pentagon));
  EXPECT_FALSE(is_ccw_strictly_convex_polygon(pentagram));
  const std::vector<P2> collinear_vertex{{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}};
  EXPECT_FALSE(is_ccw_strictly_convex_polygon(collinear_vertex));
  const std::vector<P2> repeated{{0, 0}, {4, 0}, {4, 0}, {4, 4}};
  EXPECT_FALSE(is_ccw_strictly_convex_polygon(repeated));
  EXPECT_TRUE(is_ccw_strictly_convex_polygon(std::vector<P2>{}));
  EXPECT_TRUE(is_ccw_strictly_convex_polygon(std::vector<P2>{{1, 2}}));
  EXPECT_TRUE(is_ccw_strictly_convex_polygon(std::vector<P2>{{1, 2}, {3, 4}}));
  EXPECT_FALSE(is_ccw_strictly_convex_polygon(std::vector<P2>{{1, 2}, {1, 2}}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)is_ccw_strictly_convex_polygon(std::vector<P2>{{0, 0}, {1, 0}, {nan, 1}}), Non_finite_input);
}

TEST(HullErrorMeasures, TheRightVertexSetInAWrongOrderIsNotAHull) {
  // Built directly: every vertex of the exact hull, listed as a bow tie.
  const std::vector<P2> input{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}};
  const std::vector<std::size_t> crossed{0, 1, 3, 2};
  const Hull_error e = hull_error(input, crossed);
  EXPECT_FALSE(e.convex);
  EXPECT_EQ(e.value, std::numeric_limits<double>::infinity());
  EXPECT_EQ(hull_backward_error(input, crossed).value, std::numeric_limits<double>::infinity());
  const std::vector<std::size_t> clockwise{0, 3, 2, 1};
  EXPECT_EQ(hull_error(input, clockwise).value, std::numeric_limits<double>::infinity());
}

TEST(HullErrorMeasures, NaiveIncrementalWrongOrderIsReportedNotConvex) {
  // The naive scan returns the exact hull's vertex set in another cyclic
  // order: judged as a set that would be "convex, error 0".
  for (const auto& input : wrong_order_inputs()) {
    const auto naive = graham_incremental<Naive_kernel<double>>(input);
    const auto exact = monotone_chain<Filtered_exact_kernel>(input);
    ASSERT_TRUE(naive.ok());
    std::vector<std::size_t> a = naive.indices, b = exact.indices;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    ASSERT_EQ(a, b) << "the case is meant to keep the exact vertex set";
    ASSERT_NE(naive.indices, exact.indices) << "and to return it in a wrong order";
    const Hull_error e = hull_error(input, naive.indices);
    EXPECT_FALSE(e.convex);
    EXPECT_EQ(e.value, std::numeric_limits<double>::infinity());
    EXPECT_EQ(hull_backward_error(input, naive.indices).value, std::numeric_limits<double>::infinity());
    EXPECT_EQ(hull_error(input, exact.indices).value, 0.0);
  }
}

TEST(HullErrorMeasures, NonFiniteInputIsRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<P2> input{{0, 0}, {4, 0}, {nan, 4}, {0, 4}};
  const std::vector<std::size_t> hull{0, 1, 3};
  EXPECT_THROW((void)hull_error(input, hull), Non_finite_input);
  EXPECT_THROW((void)hull_backward_error(input, hull), Non_finite_input);
  EXPECT_THROW((void)locate(kSquare, P2{nan, 1}), Non_finite_input);
  EXPECT_THROW((void)hausdorff_distance(kSquare, input), Non_finite_input);
  // Before, a NaN point "located" inside gave finite figures.
  const std::vector<P2> with_inf{{0, 0}, {4, 0}, {4, 4}, {0, std::numeric_limits<double>::infinity()}};
  EXPECT_THROW((void)hull_backward_error(with_inf, std::vector<std::size_t>{0, 1, 2}), Non_finite_input);
}

TEST(HullErrorMeasures, AprioriBoundNeedsTheFiltersRegime) {
  EXPECT_TRUE(graham_fortune_backward_error_bound<Failsafe_kernel<double>>(classroom_a1()).has_value());
  const std::vector<P2> huge{{0, 0}, {1e300, 0}, {0, 1}};
  EXPECT_FALSE(graham_fortune_backward_error_bound<Failsafe_kernel<double>>(huge).has_value());
  EXPECT_EQ(*graham_fortune_backward_error_bound<Filtered_exact_kernel>(huge), 0.0);
  EXPECT_FALSE(graham_fortune_backward_error_bound<Naive_kernel<double>>(huge).has_value());
  EXPECT_FALSE(graham_fortune_backward_error_bound<Interval_kernel>(huge).has_value());
  // The regime is the type's own: for float, coordinates of order 1 are in it
  // (the check used 2^53 for every type, so float had no bound below 2^19).
  EXPECT_TRUE(graham_fortune_backward_error_bound<Failsafe_kernel<float>>(classroom_a1()).has_value());
  EXPECT_FALSE(graham_fortune_backward_error_bound<Failsafe_kernel<float>>(std::vector<P2>{{0, 0}, {0x1p-10, 1}}).has_value());
  // Linear in n: 4 n eps (1+u)^2.
  const double b9 = *graham_fortune_backward_error_bound<Failsafe_kernel<double>>(classroom_a1());
  EXPECT_GE(b9, 4 * 9 * *Failsafe_kernel<double>::orientation_2_error_bound);
  EXPECT_LE(b9, 4 * 9 * *Failsafe_kernel<double>::orientation_2_error_bound * (1 + 1e-15));
}

}  // namespace
}  // namespace relgeo::test
