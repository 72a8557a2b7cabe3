// The epsilon constants of the semi-static filter (Failsafe_kernel, first stage
// of Filtered_exact_kernel) satisfy the inequalities of their derivation
// (internal/semi_static_filter.h), checked in exact rational arithmetic.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/analysis/sign_tally.h"
#include "relgeo/kernel/failsafe_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"

namespace relgeo {
namespace {

// Exact value of a float, double or x87 long double (whose 64-bit significand
// splits exactly into two doubles).
template <class T>
mpq_class exact(T v) {
  const double hi = static_cast<double>(v);
  const double lo = static_cast<double>(v - static_cast<T>(hi));
  return mpq_class(hi) + mpq_class(lo);
}

template <class T>
mpq_class gamma(int n) {
  const mpq_class u = exact(unit_roundoff_v<T>);
  return n * u / (1 - n * u);
}

template <class T>
void check_constants() {
  using C = internal::Orientation_filter_constants<T>;
  const mpq_class u = exact(C::u);
  const mpq_class one_minus_u = 1 - u;
  // eps_2 >= 4 gamma_2 / (1-u)^2
  const mpq_class eps2 = 8 * u * (1 + 8 * u);
  EXPECT_EQ(exact(C::eps_2), eps2) << "eps_2 is not exactly 8u(1+8u) in T";
  EXPECT_GE(eps2, 4 * gamma<T>(2) / (one_minus_u * one_minus_u));
  // eps_3 >= 6 (gamma_5 + gamma_3) / (1-u)^3
  const mpq_class eps3 = exact(C::eps_3);
  EXPECT_EQ(eps3, 49 * u);
  EXPECT_GE(eps3, 6 * (gamma<T>(5) + gamma<T>(3)) / (one_minus_u * one_minus_u * one_minus_u));
  // The published double of a kernel never rounds the constant down.
  EXPECT_GE(mpq_class(*Failsafe_kernel<T>::orientation_2_error_bound), eps2);
  EXPECT_GE(mpq_class(*Failsafe_kernel<T>::orientation_3_error_bound), eps3);
  // Range guards: products stay finite, underflow stays negligible.
  EXPECT_LT(C::low_2, 1);
  EXPECT_GT(C::high_2, 1);
  EXPECT_LT(C::low_3, 1);
  EXPECT_GT(C::high_3, 1);
}

TEST(FilterBound, DoubleConstantsFollowTheDerivation) { check_constants<double>(); }
TEST(FilterBound, FloatConstantsFollowTheDerivation) { check_constants<float>(); }
TEST(FilterBound, LongDoubleConstantsFollowTheDerivation) { check_constants<long double>(); }

TEST(FilterBound, DoubleEpsilonMatchesCgalsStaticFilter) {
  // CGAL's Static_filters/Orientation_2.h derives 8.8872057372592798e-16 for
  // the same test; ours is tighter by its more careful accounting, never looser
  // than 8u.
  EXPECT_LE(*Failsafe_kernel<double>::orientation_2_error_bound, 8.8872057372592798e-16);
  EXPECT_GE(*Failsafe_kernel<double>::orientation_2_error_bound, 8 * 0x1p-53);
  EXPECT_LE(*Failsafe_kernel<double>::orientation_3_error_bound, 5.4400928206632e-15 * (1 + 1e-12));
}

TEST(FilterBound, FailsafeDecidesEveryRandomCase) {
  // The bound is not needlessly pessimistic: random (non-degenerate) input is
  // always decided.
  const auto w = analysis::uniform_2(100000, 5);
  const auto exact = analysis::exact_signs<analysis::Orientation_2_case>(w.cases);
  const auto t = analysis::tally(Failsafe_kernel<double>{}, std::span<const analysis::Orientation_2_case>(w.cases),
                                 std::span<const Certified_sign>(exact));
  EXPECT_EQ(t.uncertain, 0u);
  EXPECT_EQ(t.wrong(), 0u);
}

TEST(FilterBound, FilteredKernelUsesEveryStage) {
  // Uniform input is decided by the first stage; near-degenerate input in
  // moderate range by the expansion; beyond it, intervals decide what they
  // can and GMP the rest.
  using K = Filtered_exact_kernel;
  EXPECT_EQ(K::orientation_2_with_stage({0, 0}, {1, 0.1}, {0.3, 1}).second, Filter_stage::semi_static);
  const auto exact_zero = K::orientation_2_with_stage({0.5, 0.5}, {12, 12}, {24, 24});
  EXPECT_EQ(exact_zero.first, Certified_sign::zero);
  EXPECT_EQ(exact_zero.second, Filter_stage::expansion);
  const auto tiny = K::orientation_2_with_stage({0.5 + 0x1p-53, 0.5}, {12, 12}, {24, 24});
  EXPECT_EQ(tiny.second, Filter_stage::expansion);
  EXPECT_EQ(tiny.first, Certified_sign::negative);  // p moved right of the diagonal: pqr clockwise
  const double big = 0x1p600;  // beyond the expansion's range
  const auto huge = K::orientation_2_with_stage({big * (0.5 + 0x1p-53), big * 0.5}, {big * 12, big * 12}, {big * 24, big * 24});
  EXPECT_EQ(huge.second, Filter_stage::exact);
  EXPECT_EQ(huge.first, Certified_sign::negative);
  const double small = 0x1p-420;  // below the expansion's range; no interval overflows
  const auto small_zero =
      K::orientation_2_with_stage({small * 0.5, small * 0.5}, {small * 12, small * 12}, {small * 24, small * 24});
  EXPECT_EQ(small_zero.second, Filter_stage::interval);  // exact differences and products: a zero interval
  EXPECT_EQ(small_zero.first, Certified_sign::zero);
}

}  // namespace
}  // namespace relgeo
