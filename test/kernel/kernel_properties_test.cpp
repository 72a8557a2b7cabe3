// Every model satisfies the Kernel concept and states what it guarantees.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <gtest/gtest.h>

#include <cmath>

#include "relgeo/kernel.h"
#include "relgeo/kernel/cgal_kernel.h"

namespace relgeo {
namespace {

static_assert(Kernel<Naive_kernel<float>> && Kernel<Naive_kernel<double>> &&
              Kernel<Naive_kernel<long double>>);
static_assert(Kernel<Failsafe_kernel<double>> && Kernel<Failsafe_kernel<float>>);
static_assert(Kernel<Interval_kernel> && Kernel<Filtered_exact_kernel> && Kernel<Exact_kernel>);
// Default kernels by coordinate type (kernel_for_number.h).
static_assert(std::is_same_v<Kernel_for_number<double>::type, Naive_kernel<double>>);
static_assert(std::is_same_v<Kernel_for_number<float>::type, Naive_kernel<float>>);
static_assert(std::is_same_v<Kernel_for_number<mpq_class>::type, Exact_kernel>);
static_assert(std::is_same_v<Kernel_for_number<Interval>::type, Interval_kernel>);
static_assert(std::is_same_v<Kernel_for_number<Mpfr_number<80>>::type, Mpfr_kernel<80>>);
static_assert(std::is_same_v<Predicate_kernel_for_number<double>::type, Filtered_exact_kernel>);
static_assert(std::is_same_v<Predicate_kernel_for_number<long double>::type, Naive_kernel<long double>>);
static_assert(std::is_same_v<Predicate_kernel_for_number<mpq_class>::type, Exact_kernel>);
static_assert(Kernel<Mpfr_kernel<53>> && Kernel<Mpfr_kernel<300>>);
static_assert(Kernel<Cgal_kernel<CGAL::Simple_cartesian<double>>>);
static_assert(Kernel<Cgal_kernel<CGAL::Epick>> && Kernel<Cgal_kernel<CGAL::Epeck>>);
static_assert(!OrientationKernel_2<int>);

TEST(KernelProperties, NamesAreShortAndDistinct) {
  EXPECT_EQ(Naive_kernel<double>::name(), "double");
  EXPECT_EQ(Naive_kernel<long double>::name(), "long-double");
  EXPECT_EQ(Failsafe_kernel<double>::name(), "failsafe<double>");
  EXPECT_EQ(Mpfr_kernel<53>::name(), "mpfr-53");
  EXPECT_EQ(Cgal_kernel<CGAL::Epick>::name(), "cgal-epick");
  EXPECT_EQ(Cgal_kernel<CGAL::Epeck>::name(), "cgal-epeck");
  EXPECT_EQ(Cgal_kernel<CGAL::Simple_cartesian<double>>::name(), "cgal-sc-double");
}

// The concepts each kernel models (kernel/concepts.h): every certified kernel
// with implicit points is an IntersectionKernel_3, Cgal_kernel<Epeck> included.
static_assert(IntersectionKernel_3<Filtered_exact_kernel> && IntersectionKernel_3<Exact_kernel>);
static_assert(IntersectionKernel_3<Cgal_kernel<CGAL::Epeck>>);
static_assert(ConstructionKernel_3<Interval_kernel> && ConstructionKernel_3<Exact_kernel>);
static_assert(!Kernel<int> && !KernelOrDefault<int> && KernelOrDefault<void>);

TEST(KernelProperties, CgalKernelsCompareTheirNumbersExactly) {
  // NumberComparisonKernel_3: the sign of a - b, uncertain only for a NaN.
  using Epick = Cgal_kernel<CGAL::Epick>;
  EXPECT_EQ(Epick::compare_ft(1.0, 2.0), Certified_sign::negative);
  EXPECT_EQ(Epick::compare_ft(0x1p53 + 2, 0x1p53), Certified_sign::positive);
  EXPECT_EQ(Epick::compare_ft(-0.0, 0.0), Certified_sign::zero);
  EXPECT_EQ(Epick::compare_ft(std::nan(""), 1.0), Certified_sign::uncertain);
  // Epeck's lazy numbers: 1/3 + 1/3 + 1/3 is exactly 1, which no double sum is.
  using Epeck = Cgal_kernel<CGAL::Epeck>;
  const Epeck::FT third = Epeck::FT(1) / Epeck::FT(3);
  EXPECT_EQ(Epeck::compare_ft(third + third + third, Epeck::FT(1)), Certified_sign::zero);
  EXPECT_EQ(Epeck::compare_ft(third, Epeck::FT(0.3333333333333333)), Certified_sign::positive);
}

TEST(KernelProperties, GuaranteesAreStated) {
  EXPECT_EQ(Naive_kernel<double>::unit_roundoff, 0x1p-53);
  EXPECT_EQ(Naive_kernel<float>::unit_roundoff, 0x1p-24);
  EXPECT_EQ(Naive_kernel<long double>::unit_roundoff, 0x1p-64);
  EXPECT_EQ(Mpfr_kernel<100>::unit_roundoff, 0x1p-100);
  EXPECT_EQ(Exact_kernel::unit_roundoff, 0.0);
  EXPECT_FALSE(Naive_kernel<double>::is_certified);
  EXPECT_TRUE(Failsafe_kernel<double>::is_certified);
  EXPECT_FALSE(Failsafe_kernel<double>::has_exact_predicates);
  EXPECT_TRUE(Filtered_exact_kernel::has_exact_predicates);
  EXPECT_FALSE(Filtered_exact_kernel::has_exact_constructions);
  EXPECT_TRUE(Exact_kernel::has_exact_constructions);
  EXPECT_FALSE(Interval_kernel::orientation_2_error_bound.has_value());
  EXPECT_EQ(*Exact_kernel::orientation_3_error_bound, 0.0);
  EXPECT_FALSE(Cgal_kernel<CGAL::Simple_cartesian<double>>::is_certified);
  EXPECT_TRUE(Cgal_kernel<CGAL::Epick>::has_exact_predicates);
  EXPECT_FALSE(Cgal_kernel<CGAL::Epick>::has_exact_constructions);
  EXPECT_TRUE(Cgal_kernel<CGAL::Epeck>::has_exact_constructions);
  EXPECT_EQ(*Cgal_kernel<CGAL::Simple_cartesian<double>>::orientation_2_error_bound,
            *Naive_kernel<double>::orientation_2_error_bound);
}

TEST(KernelConstructions, MidpointsBarycentersDistancesInTheKernelsNumberType) {
  const Exact_kernel k;
  const auto p = k.construct_point_3_object()(0, 0, 0), q = k.construct_point_3_object()(1, 3, 0.1);
  const auto m = k.construct_midpoint_3_object()(p, q);
  EXPECT_EQ(m.z, mpq_class(0.1) / 2);  // exact, not a rounded 0.05
  const std::vector<Exact_kernel::Point_3> pts{p, q};
  const std::vector<mpq_class> w{mpq_class(1, 3), mpq_class(2, 3)};
  const auto b = k.construct_barycenter_3_object()(pts, w);
  EXPECT_EQ(b.y, 2);
  EXPECT_EQ(k.compute_squared_distance_3_object()(p, q), 1 + 9 + mpq_class(0.1) * mpq_class(0.1));
  EXPECT_THROW(k.construct_barycenter_3_object()(pts, std::vector<mpq_class>{1}), Precondition_violation);
  const Naive_kernel<double> n;
  EXPECT_EQ(n.construct_midpoint_2_object()({0, 0}, {1, 3}).y, 1.5);
}

}  // namespace
}  // namespace relgeo
