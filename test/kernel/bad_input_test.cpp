// NaN and infinite coordinates: certified kernels never give a definite sign,
// kernels that cannot hold them refuse them with Non_finite_input, naive
// kernels return something without crashing.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>

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
                     Failsafe_kernel<double>, Failsafe_kernel<float>, Failsafe_kernel<long double>, Interval_kernel,
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
      // The fourth point of the 4-argument form (the first three fixed, not collinear).
      const Certified_sign co4 = k.coplanar_orientation_3_object()(p3(0, 0, 0), p3(1, 0, 0), p3(0, 1, 0),
                                                                   p3(d[9], d[10], d[11]));
      if constexpr (K::is_certified) {
        EXPECT_EQ(o2, Certified_sign::uncertain) << K::name() << " slot " << slot << " value " << bad;
        EXPECT_EQ(o3, Certified_sign::uncertain) << K::name() << " slot " << slot << " value " << bad;
        if (slot < 2) {
          EXPECT_EQ(cmp, Certified_sign::uncertain) << K::name() << " slot " << slot << " value " << bad;
        }
        if (slot * 2 < 9) {
          EXPECT_EQ(co, Certified_sign::uncertain) << K::name() << " slot " << slot << " value " << bad;
        } else {
          EXPECT_EQ(co4, Certified_sign::uncertain) << K::name() << " slot " << slot << " value " << bad;
        }
      } else {
        // Naive kernels answer; the point is that they do not crash.
        EXPECT_TRUE(is_certain(o2));
        EXPECT_TRUE(is_certain(o3));
      }
    }
  }
}

// The same among coordinates of every magnitude: tuples of random finite
// coordinates (from 2^-1074 to the largest double, either sign, some equal)
// with one to three of them NaN or infinite. The Python bindings rely on it:
// under these kernels they check a block of tuples for NaN and infinity only
// when an answer is `uncertain` (python/src/predicates_dispatch.cpp).
TYPED_TEST(NonFiniteInput, CertifiedKernelsAnswerUncertainForAnyNonFiniteTuple) {
  using K = TypeParam;
  if constexpr (K::is_certified) {
    const K k;
    const auto p2 = k.construct_point_2_object();
    const auto p3 = k.construct_point_3_object();
    std::mt19937_64 rng(20261129);
    const auto finite = [&] {
      switch (rng() % 5) {
        case 0: return 0.0;
        case 1: return 1.0;  // equal coordinates: the exact-degeneracy shortcut
        case 2: return std::ldexp(static_cast<double>(rng() >> 11), static_cast<int>(rng() % 2098) - 1127);
        case 3: return std::numeric_limits<double>::max();
        default: return std::uniform_real_distribution<double>(-1, 1)(rng);
      }
    };
    for (int trial = 0; trial < 4000; ++trial) {
      double c[12];
      for (double& v : c) v = (rng() & 1) ? finite() : -finite();
      const int bad_count = 1 + static_cast<int>(rng() % 3);
      for (int b = 0; b < bad_count; ++b) c[rng() % 12] = kBad[rng() % 3];
      // The 2D tuple takes the first six coordinates: give it one bad value too.
      c[rng() % 6] = kBad[rng() % 3];
      const Certified_sign o2 = k.orientation_2_object()(p2(c[0], c[1]), p2(c[2], c[3]), p2(c[4], c[5]));
      const Certified_sign o3 = k.orientation_3_object()(p3(c[0], c[1], c[2]), p3(c[3], c[4], c[5]),
                                                         p3(c[6], c[7], c[8]), p3(c[9], c[10], c[11]));
      ASSERT_EQ(o2, Certified_sign::uncertain) << K::name() << " trial " << trial;
      ASSERT_EQ(o3, Certified_sign::uncertain) << K::name() << " trial " << trial;
    }
  }
}

// Every public predicate on implicit points of the certified kernels that
// can hold a NaN or an infinity: a non-finite coordinate in any argument
// gives `uncertain` (before: Filtered_exact_kernel's exact stage read the
// bits of a NaN as a finite number, and Interval_kernel's arithmetic on
// [inf, inf] gave definite signs), and the number comparison of the kernel
// too. LPI and TPI points with a non-finite defining point are not built.
template <class K>
class NonFiniteImplicitInput : public ::testing::Test {};
using Implicit_kernels_holding_non_finite =
    ::testing::Types<Failsafe_kernel<double>, Failsafe_kernel<float>, Failsafe_kernel<long double>, Interval_kernel,
                     Filtered_exact_kernel>;
TYPED_TEST_SUITE(NonFiniteImplicitInput, Implicit_kernels_holding_non_finite);

TYPED_TEST(NonFiniteImplicitInput, NoPredicateGivesADefiniteSign) {
  using K = TypeParam;
  static_assert(K::is_certified);
  const K k;
  const auto point = k.construct_point_3_object();
  const auto make = k.construct_implicit_point_3_object();
  const auto orient3 = k.implicit_orientation_3_object();
  const auto orient2 = k.implicit_orientation_2_object();
  const auto coplanar = k.implicit_coplanar_orientation_3_object();
  const auto compare = k.compare_xyz_3_object();
  // Four points in general position, and an LPI point built from finite ones.
  const std::array<typename K::Point_3, 4> good{point(0, 0, 0), point(1, 0, 0), point(0, 1, 0), point(0, 0, 1)};
  const auto lpi = make(point(0.25, 0.25, -1), point(0.25, 0.25, 1), good[0], good[1], good[2]);
  ASSERT_TRUE(lpi.has_value());
  std::size_t asked = 0;
  for (double bad : kBad)
    for (int axis = 0; axis < 3; ++axis) {
      double c[3] = {0.5, 0.25, 0.125};
      c[axis] = bad;
      const typename K::Point_3 bad_point = point(c[0], c[1], c[2]);
      const auto b = make(bad_point);
      for (int slot = 0; slot < 4; ++slot) {
        std::array<typename K::Implicit_point_3, 4> p{make(good[0]), make(good[1]), make(good[2]), *lpi};
        p[slot] = b;
        const std::string where = K::name() + ": " + std::to_string(bad) + " in coordinate " + std::to_string(axis) +
                                  " of argument " + std::to_string(slot);
        const auto expect_uncertain = [&](Certified_sign s, const char* predicate) {
          ++asked;
          EXPECT_EQ(s, Certified_sign::uncertain) << predicate << ", " << where;
        };
        expect_uncertain(orient3(p[0], p[1], p[2], p[3]), "implicit_orientation_3");
        if (slot < 3) {
          std::array<typename K::Point_3, 3> e{good[0], good[1], good[2]};
          e[slot] = bad_point;
          expect_uncertain(orient3(e[0], e[1], e[2], *lpi), "implicit_orientation_3 (explicit plane)");
        } else {
          expect_uncertain(orient3(good[0], good[1], good[2], b), "implicit_orientation_3 (explicit plane)");
        }
        for (int dropped = 0; dropped < 3; ++dropped)
          expect_uncertain(orient2(p[(slot + 0) % 4], p[(slot + 1) % 4], p[(slot + 2) % 4], dropped),
                           "implicit_orientation_2");
        expect_uncertain(coplanar(p[(slot + 0) % 4], p[(slot + 1) % 4], p[(slot + 2) % 4]),
                         "implicit_coplanar_orientation_3");
        if (slot == 3) {  // the 4-argument form: p, q, r in general position, s bad
          expect_uncertain(coplanar(make(good[0]), make(good[1]), make(good[2]), b),
                           "implicit_coplanar_orientation_3 (4)");
        }
        expect_uncertain(compare(p[slot], p[(slot + 1) % 4]), "compare_xyz_3");
        expect_uncertain(compare(p[(slot + 1) % 4], p[slot]), "compare_xyz_3");
        // No implicit point from a non-finite defining point.
        std::array<typename K::Point_3, 5> d{point(0.25, 0.25, -1), point(0.25, 0.25, 1), good[0], good[1], good[2]};
        d[slot] = bad_point;
        EXPECT_FALSE(make(d[0], d[1], d[2], d[3], d[4]).has_value()) << "LPI, " << where;
        EXPECT_FALSE(make(bad_point, good[1], good[2], good[0], good[1], good[3], good[0], good[2], good[3])
                         .has_value())
            << "TPI, " << where;
      }
    }
  EXPECT_EQ(asked, 3u * 3u * (4u * 8u + 1u));  // every predicate asked in every position
  // The kernel's own number comparison.
  for (double bad : kBad) {
    EXPECT_EQ(K::compare_ft(typename K::FT(bad), typename K::FT(1)), Certified_sign::uncertain) << bad;
    EXPECT_EQ(K::compare_ft(typename K::FT(1), typename K::FT(bad)), Certified_sign::uncertain) << bad;
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
