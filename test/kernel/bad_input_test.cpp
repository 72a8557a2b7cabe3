// NaN and infinite coordinates: certified kernels never give a definite sign,
// kernels that cannot hold them refuse them with Non_finite_input, naive
// kernels return something without crashing.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <gtest/gtest.h>

#include <limits>

#include "relgeo/kernel.h"
#include "relgeo/kernel/cgal_kernel.h"

namespace relgeo {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
const double kBad[] = {kNan, kInf, -kInf};

template <class K>
class NonFiniteInput : public ::testing::Test {};

using Kernels_holding_non_finite =
    ::testing::Types<Naive_kernel<float>, Naive_kernel<double>, Naive_kernel<long double>,
                     Failsafe_kernel<double>, Failsafe_kernel<float>, Interval_kernel,
                     Filtered_exact_kernel, Cgal_kernel<CGAL::Simple_cartesian<double>>,
                     Cgal_kernel<CGAL::Epick>>;
TYPED_TEST_SUITE(NonFiniteInput, Kernels_holding_non_finite);

TYPED_TEST(NonFiniteInput, CertifiedKernelsNeverGiveADefiniteSign) {
  using K = TypeParam;
  const K k;
  const auto p2 = k.construct_point_2_object();
  const auto p3 = k.construct_point_3_object();
  for (double bad : kBad) {
    for (int slot = 0; slot < 6; ++slot) {
      double c[6] = {0, 0, 1, 0, 0, 1};
      c[slot] = bad;
      const Certified_sign o2 = k.orientation_2_object()(p2(c[0], c[1]), p2(c[2], c[3]), p2(c[4], c[5]));
      const Certified_sign cmp = k.compare_xy_2_object()(p2(c[0], c[1]), p2(1, 1));
      double d[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
      d[slot * 2] = bad;
      const Certified_sign o3 = k.orientation_3_object()(p3(d[0], d[1], d[2]), p3(d[3], d[4], d[5]),
                                                         p3(d[6], d[7], d[8]), p3(d[9], d[10], d[11]));
      const Certified_sign co = k.coplanar_orientation_3_object()(p3(d[0], d[1], d[2]),
                                                                  p3(d[3], d[4], d[5]),
                                                                  p3(d[6], d[7], d[8]));
      if constexpr (K::is_certified) {
        EXPECT_EQ(o2, Certified_sign::uncertain) << K::name() << " slot " << slot << " value " << bad;
        EXPECT_EQ(o3, Certified_sign::uncertain) << K::name() << " slot " << slot << " value " << bad;
        if (slot < 2) {
          EXPECT_EQ(cmp, Certified_sign::uncertain) << K::name() << " slot " << slot << " value " << bad;
        }
        if (slot * 2 < 9) {
          EXPECT_EQ(co, Certified_sign::uncertain) << K::name() << " slot " << slot << " value " << bad;
        }
      } else {
        // Naive kernels answer; the point is that they do not crash.
        EXPECT_TRUE(is_certain(o2));
        EXPECT_TRUE(is_certain(o3));
      }
    }
  }
}

template <class K>
class NonFiniteRefused : public ::testing::Test {};
using Kernels_refusing_non_finite =
    ::testing::Types<Exact_kernel, Mpfr_kernel<53>, Mpfr_kernel<200>, Cgal_kernel<CGAL::Epeck>>;
TYPED_TEST_SUITE(NonFiniteRefused, Kernels_refusing_non_finite);

TYPED_TEST(NonFiniteRefused, ConstructionThrowsATypedError) {
  const TypeParam k;
  for (double bad : kBad) {
    EXPECT_THROW(k.construct_point_2_object()(bad, 0), Non_finite_input);
    EXPECT_THROW(k.construct_point_2_object()(0, bad), Non_finite_input);
    EXPECT_THROW(k.construct_point_3_object()(0, 0, bad), Non_finite_input);
    try {
      k.construct_point_2_object()(bad, 1);
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Error_code::non_finite_coordinate);
      EXPECT_NE(std::string(e.what()).find("NaN or infinite"), std::string::npos);
    }
  }
}

TEST(HugeFiniteInput, FilteredKernelFallsBackToExact) {
  // Products overflow double: the filter refuses, the exact stage decides.
  const Filtered_exact_kernel k;
  const double b = 1e300;
  EXPECT_EQ(k.orientation_2_object()({0, 0}, {b, 0}, {0, b}), Certified_sign::positive);
  EXPECT_EQ(k.orientation_2_object()({0, 0}, {b, b}, {-b, -b}), Certified_sign::zero);
  EXPECT_EQ(Failsafe_kernel<double>{}.orientation_2_object()({0, 0}, {b, 0}, {0, b}),
            Certified_sign::uncertain);
  const double t = 1e-300;  // products underflow
  EXPECT_EQ(k.orientation_2_object()({0, 0}, {t, 0}, {0, t}), Certified_sign::positive);
  EXPECT_EQ(k.orientation_3_object()({0, 0, 0}, {t, 0, 0}, {0, t, 0}, {0, 0, t}), Certified_sign::positive);
  EXPECT_EQ(k.orientation_3_object()({0, 0, 0}, {b, 0, 0}, {0, b, 0}, {0, 0, -b}), Certified_sign::negative);
}

TEST(CoplanarOrientation, CollinearReferenceTripleIsAPreconditionViolation) {
  const Filtered_exact_kernel k;
  const auto co = k.coplanar_orientation_3_object();
  EXPECT_EQ(co({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), Certified_sign::zero);
  EXPECT_THROW(co({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 1, 0}), Precondition_violation);
  EXPECT_EQ(co({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 3, 0}), Certified_sign::positive);
  EXPECT_EQ(co({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, -3, 0}), Certified_sign::negative);
  EXPECT_EQ(co({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}), Certified_sign::zero);
  const Cgal_kernel<CGAL::Epick> c;
  EXPECT_THROW(c.coplanar_orientation_3_object()({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 1, 0}),
               Precondition_violation);
}

}  // namespace
}  // namespace relgeo
