// The exact error measures: point location, distances, E of eq. (3.2), the
// certificate.
#include <gtest/gtest.h>

#include <limits>

#include "hull_inputs.h"
#include "relgeo/error.h"
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
  EXPECT_EQ(sqrt_ratio_up(25, 1), 5.0);
  const double r = sqrt_ratio_up(2, 1);
  EXPECT_GE(mpq_class(r) * mpq_class(r), 2);  // never below the true sqrt(2)
  EXPECT_EQ(hausdorff_distance(kSquare, std::vector<P2>{{0, 0}, {4, 0}, {4, 5}, {0, 4}}), 1.0);
}

TEST(HullErrorMeasures, NonConvexOutputHasInfiniteErrorAndCertificate) {
  const std::vector<P2> input{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}};
  const std::vector<std::size_t> reflex{0, 1, 4, 2, 3};  // (2,2) is inside: not convex position
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

TEST(HullErrorMeasures, AprioriBoundNeedsTheFiltersRegime) {
  EXPECT_TRUE(graham_fortune_backward_error_bound<Failsafe_kernel<double>>(classroom_a1()).has_value());
  const std::vector<P2> huge{{0, 0}, {1e300, 0}, {0, 1}};
  EXPECT_FALSE(graham_fortune_backward_error_bound<Failsafe_kernel<double>>(huge).has_value());
  EXPECT_EQ(*graham_fortune_backward_error_bound<Filtered_exact_kernel>(huge), 0.0);
  EXPECT_FALSE(graham_fortune_backward_error_bound<Naive_kernel<double>>(huge).has_value());
  EXPECT_FALSE(graham_fortune_backward_error_bound<Interval_kernel>(huge).has_value());
  // Linear in n: 4 n eps (1+u)^2.
  const double b9 = *graham_fortune_backward_error_bound<Failsafe_kernel<double>>(classroom_a1());
  EXPECT_GE(b9, 4 * 9 * *Failsafe_kernel<double>::orientation_2_error_bound);
  EXPECT_LE(b9, 4 * 9 * *Failsafe_kernel<double>::orientation_2_error_bound * (1 + 1e-15));
}

}  // namespace
}  // namespace relgeo::test
