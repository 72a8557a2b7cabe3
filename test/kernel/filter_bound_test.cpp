// The epsilon constants of the semi-static filter (Failsafe_kernel, first stage
// of Filtered_exact_kernel) satisfy the inequalities of their derivation
// (internal/semi_static_filter.h), checked in exact rational arithmetic.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cfenv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/analysis/sign_tally.h"
#include "relgeo/kernel/failsafe_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "support/fp_environments.h"

namespace relgeo {
namespace {

// Exact value of a finite float, double or x87 long double.
template <class T>
mpq_class exact(T v) {
  if (v == 0) return 0;
  int e = 0;
  const T f = std::frexp(v, &e);  // v = f 2^e, 0.5 <= |f| < 1
  const T m = std::ldexp(f, std::numeric_limits<T>::digits);  // an integer, exact in T
  // m splits exactly into two doubles (at most 64 significant bits).
  const double hi = static_cast<double>(m);
  const double lo = static_cast<double>(m - static_cast<T>(hi));
  mpq_class r = mpq_class(hi) + mpq_class(lo);
  const int scale = e - std::numeric_limits<T>::digits;
  mpz_class two_power = 1;
  two_power <<= std::abs(scale);
  if (scale >= 0) r *= two_power;
  else r /= two_power;
  return r;
}

// The inequalities of the derivation in semi_static_filter.h, in exact
// rational arithmetic: v = 2u bounds the relative error of one operation in
// every rounding mode, lambda the absolute error of a flushed result or a
// subnormal input read as zero.
template <class T>
void check_constants() {
  using C = internal::Orientation_filter_constants<T>;
  const mpq_class u = exact(C::u), v = 2 * u;
  const mpq_class lambda = exact(std::numeric_limits<T>::min());
  auto gamma = [&](int n) { return mpq_class(n * v / (1 - n * v)); };
  const mpq_class w = 1 - v;

  const mpq_class eps2 = exact(C::eps_2);
  EXPECT_EQ(eps2, 16 * u * (1 + 16 * u)) << "eps_2 is not exactly 16u(1+16u) in T";
  const mpq_class l2 = exact(C::low_2), h2 = exact(C::high_2);
  EXPECT_GE(eps2 * w * w - 4 * gamma(2), mpq_class(122, 10) * lambda / l2 + mpq_class(32, 10) * lambda / (l2 * l2));
  // No underflow in the computed bound fl(fl(eps Mx) My), nor overflow of a
  // sum of two products of maxima.
  EXPECT_GE(eps2 * l2 * l2 * w * w, lambda / v);
  EXPECT_LT(4 * h2 * h2, exact(std::numeric_limits<T>::max()));

  const mpq_class eps3 = exact(C::eps_3);
  EXPECT_EQ(eps3, 97 * u);
  const mpq_class l3 = exact(C::low_3), h3 = exact(C::high_3);
  EXPECT_GE(eps3 * w * w * w - 6 * (gamma(5) + gamma(3)),
            60 * lambda / l3 + 30 * lambda / (l3 * l3) + 6 * lambda / (l3 * l3 * l3));
  EXPECT_GE(eps3 * l3 * l3 * l3 * w * w * w, lambda / v);
  EXPECT_LT(8 * h3 * h3 * h3, exact(std::numeric_limits<T>::max()));

  // The published double of a kernel never rounds the constant down.
  EXPECT_GE(mpq_class(*Failsafe_kernel<T>::orientation_2_error_bound), eps2);
  EXPECT_GE(mpq_class(*Failsafe_kernel<T>::orientation_3_error_bound), eps3);
}

TEST(FilterBound, DoubleConstantsFollowTheDerivation) { check_constants<double>(); }
TEST(FilterBound, FloatConstantsFollowTheDerivation) { check_constants<float>(); }
TEST(FilterBound, LongDoubleConstantsFollowTheDerivation) { check_constants<long double>(); }

TEST(FilterBound, DirectedRoundingNeedsTwiceCgalsConstant) {
  // CGAL's Static_filters/Orientation_2.h derives 8.8872057372592798e-16 for
  // round to nearest. Under a directed rounding mode one operation errs by up
  // to 2u, so to first order the test needs 16u (2D) and 96u (3D); ours are
  // those plus a margin of a few u^2 (2D) and u (3D).
  const double u = 0x1p-53;
  EXPECT_GE(*Failsafe_kernel<double>::orientation_2_error_bound, 2 * 8.8872057372592798e-16 * (1 - 1e-3));
  EXPECT_LE(*Failsafe_kernel<double>::orientation_2_error_bound, 16 * u * (1 + 1e-12));
  EXPECT_GE(*Failsafe_kernel<double>::orientation_3_error_bound, 96 * u);
  EXPECT_LE(*Failsafe_kernel<double>::orientation_3_error_bound, 97 * u);
}

// The determinant of a case and its maxima, computed in the caller's
// environment (out of line: after the switch).
[[gnu::noinline]] std::array<double, 3> determinant_and_maxima(const analysis::Orientation_2_case& c) {
  const double det = internal::orientation_2_determinant<double>(c.px, c.py, c.qx, c.qy, c.rx, c.ry);
  return {det, std::max(std::abs(c.qx - c.px), std::abs(c.rx - c.px)),
          std::max(std::abs(c.qy - c.py), std::abs(c.ry - c.py))};
}

TEST(FilterBound, UpwardRoundingErrsBeyondTheRoundToNearestConstant) {
  // Found by search: under upward rounding both differences of the first
  // product round up by almost an ulp and the second product's factors shrink,
  // so the computed determinant is off by 10u Mx My, more than the constant
  // 8u(1+8u) that suffices in round to nearest (CGAL's, and relgeo's before):
  // a filter built on it has no proof outside round to nearest. 16u(1+16u)
  // covers it.
  const analysis::Orientation_2_case c{-0x1.92p-66, -0x1.0cp-80, 0x1.0000000000002p+3,
                                       -0x1.0000000000001p+1, -0x1.0000000000005p+3, 0x1.0000000000004p+1};
  std::array<double, 3> r;
  {
    const test::Scoped_fp_environment upward({"upward", false, false, FE_UPWARD});
    r = determinant_and_maxima(c);
  }
  const mpq_class exact_det = (mpq_class(c.qx) - c.px) * (mpq_class(c.ry) - c.py) -
                              (mpq_class(c.qy) - c.py) * (mpq_class(c.rx) - c.px);
  const mpq_class error = abs(mpq_class(r[0]) - exact_det);
  const mpq_class mxmy = mpq_class(r[1]) * r[2];
  const mpq_class u(0x1p-53);
  EXPECT_GT(error, 8 * u * (1 + 8 * u) * mxmy);
  EXPECT_GE(error, mpq_class(99, 10) * u * mxmy);
  EXPECT_LE(error, exact(internal::Orientation_filter_constants<double>::eps_2) * mxmy);
}

TEST(FilterBound, FailsafeDecidesEveryRandomCase) {
  // The bound is not needlessly pessimistic: random (non-degenerate) input is
  // always decided.
  const auto w = analysis::uniform_2(100000, 5);
  const auto exact = analysis::exact_signs<analysis::Orientation_2_case>(w.cases);
  const auto t = analysis::tally(std::span<const analysis::Orientation_2_case>(w.cases),
                                 std::span<const Certified_sign>(exact), Failsafe_kernel<double>{});
  EXPECT_EQ(t.uncertain, 0u);
  EXPECT_EQ(t.wrong(), 0u);
}

TEST(FilterBound, FilteredKernelUsesEveryStage) {
  // Uniform input is decided by the first stage; near-degenerate input in
  // moderate range by the specialised expansion; beyond it, intervals decide
  // what they can, generic expansions on scaled input what spans few enough
  // bits, and GMP the rest.
  using K = Filtered_exact_kernel;
  EXPECT_EQ(K::orientation_2_with_stage({0, 0}, {1, 0.1}, {0.3, 1}).second, Filter_stage::semi_static);
  const auto exact_zero = K::orientation_2_with_stage({0.5, 0.5}, {12, 12}, {24, 24});
  EXPECT_EQ(exact_zero.first, Certified_sign::zero);
  EXPECT_EQ(exact_zero.second, Filter_stage::expansion);
  const auto tiny = K::orientation_2_with_stage({0.5 + 0x1p-53, 0.5}, {12, 12}, {24, 24});
  EXPECT_EQ(tiny.second, Filter_stage::expansion);
  EXPECT_EQ(tiny.first, Certified_sign::negative);  // p moved right of the diagonal: pqr clockwise
  const double big = 0x1p600;  // beyond the specialised expansion's range, a 60-bit span: generic expansions
  const auto huge = K::orientation_2_with_stage({big * (0.5 + 0x1p-53), big * 0.5}, {big * 12, big * 12}, {big * 24, big * 24});
  EXPECT_EQ(huge.second, Filter_stage::expansion);
  EXPECT_EQ(huge.first, Certified_sign::negative);
  // Bits from 2^-600 to 2^502: beyond what exact expansions of degree 2 span
  // (1032 bits), so GMP; the determinant is -2^-100 against products of 2^1001.
  const auto wide = K::orientation_2_with_stage({0x1p-600, 0}, {0x1p500, 0x1p500}, {0x1p501, 0x1p501});
  EXPECT_EQ(wide.second, Filter_stage::exact);
  EXPECT_EQ(wide.first, Certified_sign::negative);
  const double small = 0x1p-420;  // below the expansion's range; no interval overflows
  const auto small_zero =
      K::orientation_2_with_stage({small * 0.5, small * 0.5}, {small * 12, small * 12}, {small * 24, small * 24});
  EXPECT_EQ(small_zero.second, Filter_stage::interval);  // exact differences and products: a zero interval
  EXPECT_EQ(small_zero.first, Certified_sign::zero);
}

// One plane (p, q, r) against several points: Orientation_3_plane_epsilon_test
// decides only exact signs, in every environment, and Filtered_exact_kernel's
// Orientation_3_against_plane answers every finite case exactly. The
// points: each workload case's s, and points on the plane far beyond the
// triangle, rounded to doubles (nearly coplanar; there |s - p| dominates the
// filter's bound, which a bound of q - p and r - p alone would get wrong).
TEST(FilterBound, OnePlaneAgainstSeveralPointsIsExact) {
  using K = Filtered_exact_kernel;
  std::vector<std::array<double, 12>> cases;
  for (const auto& w : analysis::standard_workloads_3(3000, 37))
    for (const auto& c : w.cases) cases.push_back(c.c);
  std::vector<test::Fp_environment_setting> settings = test::non_default_fp_environments();
  settings.insert(settings.begin(), test::Fp_environment_setting{.name = "default"});
  std::size_t decided = 0, left = 0;
  for (const auto& v : cases) {
    const K::Point_3 p{v[0], v[1], v[2]}, q{v[3], v[4], v[5]}, r{v[6], v[7], v[8]};
    std::vector<K::Point_3> points{{v[9], v[10], v[11]}};
    for (double t : {1e3, -3e4, 7e5})
      points.push_back({p.x + t * (q.x - p.x) - 0.7 * t * (r.x - p.x), p.y + t * (q.y - p.y) - 0.7 * t * (r.y - p.y),
                        p.z + t * (q.z - p.z) - 0.7 * t * (r.z - p.z)});
    for (const K::Point_3& s : points) {
      if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z)) continue;  // a far point overflowed
      const mpq_class d = internal::orientation_3_determinant<mpq_class>(
          exact(p.x), exact(p.y), exact(p.z), exact(q.x), exact(q.y), exact(q.z), exact(r.x), exact(r.y), exact(r.z),
          exact(s.x), exact(s.y), exact(s.z));
      const Certified_sign truth = sgn(d) > 0   ? Certified_sign::positive
                                   : sgn(d) < 0 ? Certified_sign::negative
                                                : Certified_sign::zero;
      for (const test::Fp_environment_setting& setting : settings) {
        const test::Scoped_fp_environment environment(setting);
        const internal::Orientation_3_plane_epsilon_test<double> plane(p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z);
        const internal::Epsilon_test t = plane(s.x, s.y, s.z);
        if (t.decided) {
          ASSERT_EQ(t.sign, truth) << setting.name;
        }
        (t.decided ? decided : left) += 1;
        ASSERT_EQ(K::Orientation_3_against_plane(p, q, r)(s), truth) << setting.name;
      }
    }
  }
  EXPECT_GT(decided, 10000u);
  EXPECT_GT(left, 10000u);  // the later stages answered too
}

TEST(FilterBound, FilteredOrientation3UsesGmpOnlyOutsideTheExpansionRange) {
  // Every case whose coordinates lie in the expansion range is decided by the
  // epsilon test or the expansion stage; intervals and GMP see only the rest.
  using K = Filtered_exact_kernel;
  std::size_t by_stage[5] = {0, 0, 0, 0, 0}, in_range = 0, outside = 0;
  for (const auto& w : analysis::standard_workloads_3(20000, 31)) {
    for (const auto& c : w.cases) {
      const auto& v = c.c;
      const auto [sign, stage] = K::orientation_3_with_stage({v[0], v[1], v[2]}, {v[3], v[4], v[5]},
                                                             {v[6], v[7], v[8]}, {v[9], v[10], v[11]});
      ASSERT_TRUE(is_certain(sign));
      ++by_stage[static_cast<int>(stage)];
      bool range = true;
      for (double x : v) range &= internal::Expansion_orientation_3_range::contains(x);
      (range ? in_range : outside) += 1;
      if (range) {
        ASSERT_TRUE(stage == Filter_stage::semi_static || stage == Filter_stage::expansion) << w.name;
      }
    }
  }
  std::printf("[ stages   ] semi-static %zu, interval %zu, expansion %zu, exact %zu (in range %zu, outside %zu)\n",
              by_stage[0], by_stage[1], by_stage[2], by_stage[3], in_range, outside);
  EXPECT_GT(by_stage[static_cast<int>(Filter_stage::expansion)], 20000u);  // near-coplanar, degenerate
  EXPECT_GT(outside, 0u);  // extreme magnitudes reach the interval and GMP stages
  EXPECT_GT(by_stage[static_cast<int>(Filter_stage::interval)] + by_stage[static_cast<int>(Filter_stage::exact)], 0u);
  const auto beyond = K::orientation_3_with_stage({0, 0, 0}, {0x1p400, 0, 0}, {0, 0x1p400, 0}, {0x1p399, 0x1p399, 0});
  EXPECT_EQ(beyond.first, Certified_sign::zero);  // on the plane z = 0: exactly degenerate
  EXPECT_EQ(beyond.second, Filter_stage::semi_static);
}

}  // namespace
}  // namespace relgeo
