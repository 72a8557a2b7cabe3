// The extruded-object checker (thesis Sec. 3.4.1) under every relgeo kernel
// and hull algorithm: well-formed contours certified, the three classic
// failures refused with margins <= 0 where they should be, a margin below the
// stated uncertainty reported as not certified, the prune agreeing with the
// full quadratic check, 3D input, the derivation of condition 2, bad input.
#include <gtest/gtest.h>

#include <random>

#include "relgeo/curves.h"
#include "relgeo/kernel.h"
#include "relgeo_fixtures/curves/test_contours.h"
#include "support/fp_environments.h"

namespace relgeo::test {
namespace {

template <class K, class A>
struct Setup {
  using Kernel = K;
  using Algorithm = A;
};

template <class T>
class ExtrusionKernels : public ::testing::Test {};
using Setups = ::testing::Types<
    Setup<Naive_kernel<double>, Graham_fortune_hull>, Setup<Naive_kernel<double>, Graham_incremental_hull>,
    Setup<Naive_kernel<float>, Monotone_chain_hull>, Setup<Failsafe_kernel<double>, Graham_fortune_hull>,
    Setup<Interval_kernel, Graham_fortune_hull>, Setup<Filtered_exact_kernel, Graham_incremental_hull>,
    Setup<Filtered_exact_kernel, Monotone_chain_hull>, Setup<Exact_kernel, Graham_fortune_hull>,
    Setup<Mpfr_kernel<53>, Monotone_chain_hull>>;
TYPED_TEST_SUITE(ExtrusionKernels, Setups);

template <class T>
Extrusion_report check(const Bezier_contour& c, const Extrusion_options& o = {}) {
  return check_extrusion<typename T::Kernel>(c, o, typename T::Kernel{}, typename T::Algorithm{});
}

TYPED_TEST(ExtrusionKernels, CircleLikeCubicChainsAreCertified) {
  for (std::size_t M : {4, 5, 8, 16, 32, 64}) {
    const Extrusion_report r = check<TypeParam>(circle_contour(M, 3.0, {1.5, -2.0}));
    EXPECT_EQ(r.verdict, Extrusion_verdict::certified) << "M=" << M;
    EXPECT_EQ(r.offending_total, 0u);
    EXPECT_EQ(r.conditions[0].problems, M);
    EXPECT_EQ(r.conditions[1].problems, 2 * M);
    EXPECT_EQ(r.non_adjacent_pairs, M * (M - 3) / 2);
    EXPECT_EQ(r.conditions[2].problems + r.conditions[2].pruned, r.non_adjacent_pairs);
    for (const auto& s : r.conditions) {
      EXPECT_GT(s.min_margin, 0);
      ASSERT_TRUE(s.worst || s.pruned);
      if (s.worst) {
        EXPECT_GT(s.worst->slack(), 0);
      }
    }
    // every margin is larger than the uncertainty it has to cover
    EXPECT_GT(r.conditions[0].min_margin, 2e-3 * 3.0);
    EXPECT_EQ(r.hull_failures, 0u);
  }
}

TYPED_TEST(ExtrusionKernels, SelfIntersectingCurveIsRefused) {
  const Extrusion_report r = check<TypeParam>(looped_circle_contour(8));
  EXPECT_EQ(r.verdict, Extrusion_verdict::refused);
  const auto& c1 = r.conditions[0];
  EXPECT_EQ(c1.verdict, Extrusion_verdict::refused);
  EXPECT_EQ(c1.refused, 1u);
  EXPECT_LE(c1.min_margin, 0);
  ASSERT_FALSE(r.offending.empty());
  const Extrusion_problem& worst = r.offending.front();
  EXPECT_EQ(worst.condition, Extrusion_condition::no_self_intersection);
  EXPECT_EQ(worst.curve_a, 0u);
  EXPECT_LT(worst.margin, 0);  // 0 strictly inside conv(q)
}

TYPED_TEST(ExtrusionKernels, AdjacentCurvesFoldingBackAreRefused) {
  const Extrusion_report r = check<TypeParam>(folded_contour());
  EXPECT_EQ(r.verdict, Extrusion_verdict::refused);
  EXPECT_EQ(r.conditions[0].verdict, Extrusion_verdict::certified);
  EXPECT_EQ(r.conditions[2].verdict, Extrusion_verdict::certified);
  const auto& c2 = r.conditions[1];
  EXPECT_EQ(c2.verdict, Extrusion_verdict::refused);
  EXPECT_LE(c2.min_margin, 0);
  for (const auto& p : r.offending) {
    EXPECT_EQ(p.condition, Extrusion_condition::adjacent_curves);
    EXPECT_EQ(p.curve_a, 1u);
    EXPECT_EQ(p.curve_b, 2u);
    EXPECT_LE(p.margin, 0);
  }
}

TYPED_TEST(ExtrusionKernels, CrossingNonAdjacentCurvesAreRefused) {
  using K = typename TypeParam::Kernel;
  const Extrusion_report r = check<TypeParam>(bow_tie_contour());
  EXPECT_EQ(r.verdict, Extrusion_verdict::refused);
  // Conditions 1 and 2 hold. Their sets have collinear points (straight
  // edges): a naive kernel may return a hull that is not the exact one, whose
  // certificate then says "not certified" — never "refused".
  for (int c = 0; c < 2; ++c) {
    if constexpr (K::is_certified) {
      EXPECT_EQ(r.conditions[c].verdict, Extrusion_verdict::certified) << c;
    } else {
      EXPECT_NE(r.conditions[c].verdict, Extrusion_verdict::refused) << c;
    }
  }
  EXPECT_EQ(r.conditions[2].refused, 1u);
  const Extrusion_problem* found = nullptr;
  for (const auto& p : r.offending)
    if (p.condition == Extrusion_condition::disjoint_curves) found = &p;
  ASSERT_NE(found, nullptr);
  const Extrusion_problem& worst = *found;
  EXPECT_EQ(worst.verdict, Extrusion_verdict::refused);
  EXPECT_EQ(worst.curve_a, 0u);
  EXPECT_EQ(worst.curve_b, 2u);
  // the diagonals' hulls (segments) cross: separating them needs a
  // translation by sqrt(2)/2, the margin is minus that
  EXPECT_LT(worst.margin, -0.7071);
  EXPECT_GT(worst.margin, -0.7072);
}

TYPED_TEST(ExtrusionKernels, MarginBelowTheUncertaintyIsNotCertified) {
  // A thin rectangle of height 1e-4: every condition holds for the stored
  // data, but the margins (~1e-4 / 3) are below the default 1e-3 relative
  // uncertainty: not certified, yet not refused.
  const Bezier_contour c = thin_rectangle_contour(1e-4);
  const Extrusion_report r = check<TypeParam>(c);
  EXPECT_EQ(r.verdict, Extrusion_verdict::uncertain);
  for (const auto& s : r.conditions) EXPECT_EQ(s.refused, 0u);
  EXPECT_GT(r.offending_total, 0u);
  for (const auto& p : r.offending) {
    EXPECT_GT(p.margin, 0);
    EXPECT_LE(p.margin, p.uncertainty + p.computation_error);
  }
  // With a smaller uncertainty it is certified.
  EXPECT_EQ(check<TypeParam>(c, {.relative_uncertainty = 1e-6}).verdict, Extrusion_verdict::certified);
  // The circle with a 10% uncertainty: margins ~0.033 for M = 64 do not cover it.
  const Extrusion_report big = check<TypeParam>(circle_contour(64), {.relative_uncertainty = 0.1});
  EXPECT_EQ(big.verdict, Extrusion_verdict::uncertain);
  EXPECT_EQ(big.conditions[0].uncertain, 64u);
}

TEST(Extrusion, PruneAgreesWithTheQuadraticCheck) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    // circle contours with random wiggles: some well formed, some not
    const std::size_t M = 6 + static_cast<std::size_t>(trial) * 3;
    const Bezier_contour base = circle_contour(M);
    std::vector<Point_2<double>> chain;
    const double w = trial % 2 ? 0.05 : 0.6;
    for (std::size_t m = 0; m < M; ++m)
      for (std::size_t i = 0; i < 3; ++i) {
        const auto p = base[m][i];
        chain.push_back(i == 0 ? p : Point_2<double>{p.x + w * u(rng) / static_cast<double>(M), p.y + w * u(rng)});
      }
    const Bezier_contour c = Bezier_contour::from_chain(chain, 3);
    const auto full = check_extrusion<Filtered_exact_kernel>(c, {.prune = false});
    const auto pruned = check_extrusion<Filtered_exact_kernel>(c, {.prune = true});
    EXPECT_EQ(full.verdict, pruned.verdict) << trial;
    EXPECT_EQ(full.conditions[2].verdict, pruned.conditions[2].verdict) << trial;
    EXPECT_EQ(full.conditions[2].refused, pruned.conditions[2].refused) << trial;
    EXPECT_EQ(full.conditions[2].uncertain, pruned.conditions[2].uncertain) << trial;
    EXPECT_EQ(full.pairs_computed, full.non_adjacent_pairs);
    // the pruned minimum is a lower bound of the true one, exact when the
    // smallest pair was computed
    EXPECT_LE(pruned.conditions[2].min_margin, full.conditions[2].min_margin) << trial;
    if (!pruned.conditions[2].min_margin_is_prune_bound) {
      EXPECT_EQ(pruned.conditions[2].min_margin, full.conditions[2].min_margin) << trial;
    }
  }
}

TEST(Extrusion, CertifiedContoursReallyAreSimple) {
  // Sanity check of the sufficient conditions: sample every curve of certified
  // random contours densely; no two samples of different curves (away from
  // shared end points) come closer than half the certified margin of
  // condition 3 ... a cheap necessary check: segments of the sampled polygon
  // do not cross.
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-1, 1);
  int certified = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t M = 5 + static_cast<std::size_t>(trial % 7);
    const Bezier_contour base = circle_contour(M);
    std::vector<Point_2<double>> chain;
    for (std::size_t m = 0; m < M; ++m)
      for (std::size_t i = 0; i < 3; ++i) {
        const auto p = base[m][i];
        chain.push_back(i == 0 ? p : Point_2<double>{p.x + 0.3 * u(rng), p.y + 0.3 * u(rng)});
      }
    const Bezier_contour c = Bezier_contour::from_chain(chain, 3);
    if (check_extrusion<Filtered_exact_kernel>(c, {.relative_uncertainty = 0}).verdict !=
        Extrusion_verdict::certified)
      continue;
    ++certified;
    std::vector<Point_2<double>> poly;
    for (std::size_t m = 0; m < M; ++m)
      for (int k = 0; k < 64; ++k) poly.push_back(c[m](k / 64.0));
    const auto o = Filtered_exact_kernel().orientation_2_object();
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;
        const auto &a = poly[i], &b = poly[(i + 1) % n], &p = poly[j], &q = poly[(j + 1) % n];
        const int s1 = to_int(o(a, b, p)) * to_int(o(a, b, q)), s2 = to_int(o(p, q, a)) * to_int(o(p, q, b));
        ASSERT_FALSE(s1 < 0 && s2 < 0) << "certified contour self-intersects, trial " << trial;
      }
  }
  EXPECT_GT(certified, 5);
}

TEST(Extrusion, ConditionTwoSetsAreEquivalentToTheSeparatingLineCriterion) {
  // The derivation in extrusion.h: 0 not in conv(Q') and not in conv(Q'')
  // <=> 0 not in conv(E), E = {R^{m+1}_j - P, j >= 1} u {P - R^m_i, i < v}.
  std::mt19937_64 rng(12);
  std::uniform_int_distribution<int> u(-4, 4);
  int yes = 0, no = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const std::size_t v = 1 + static_cast<std::size_t>(trial % 3);
    std::vector<Point_2<double>> a, b;
    const Point_2<double> P{0, 0};
    for (std::size_t i = 0; i < v; ++i) a.push_back({double(u(rng)), double(u(rng))});
    a.push_back(P);
    b.push_back(P);
    for (std::size_t i = 0; i < v; ++i) b.push_back({double(u(rng)), double(u(rng))});
    std::vector<Point_2<double>> q1, q2, e;
    for (std::size_t i = 0; i < v; ++i)
      for (std::size_t j = 0; j <= v; ++j) {
        q1.push_back({b[i + 1].x - a[j].x, b[i + 1].y - a[j].y});
        q2.push_back({b[j].x - a[i].x, b[j].y - a[i].y});
      }
    for (std::size_t j = 1; j <= v; ++j) e.push_back(b[j]);
    for (std::size_t i = 0; i < v; ++i) e.push_back({-a[i].x, -a[i].y});
    auto outside = [](const std::vector<Point_2<double>>& s) {
      return locate(exact_hull(s), Point_2<double>{0, 0}) == Polygon_side::outside;
    };
    const bool thesis = outside(q1) && outside(q2), line = outside(e);
    EXPECT_EQ(thesis, line) << trial;
    (thesis ? yes : no)++;
  }
  EXPECT_GT(yes, 300);
  EXPECT_GT(no, 300);
}

TEST(Extrusion, ThreeDimensionalInput) {
  // The circle contour placed in the plane d.x = 2 for d = (1, 2, 2)/3, then
  // projected back with the rotation carrying d to z.
  const Bezier_contour planar = circle_contour(12, 5.0);
  const Point_3<double> d{1.0 / 3, 2.0 / 3, 2.0 / 3};
  const Point_3<double> e1{2.0 / 3, -2.0 / 3, 1.0 / 3}, e2{2.0 / 3, 1.0 / 3, -2.0 / 3};  // orthonormal with d
  std::vector<Point_3<double>> pts;
  for (std::size_t m = 0; m < planar.size(); ++m)
    for (std::size_t i = 0; i < 3; ++i) {
      const auto p = planar[m][i];
      pts.push_back({2 * d.x + p.x * e1.x + p.y * e2.x, 2 * d.y + p.x * e1.y + p.y * e2.y,
                     2 * d.z + p.x * e1.z + p.y * e2.z});
    }
  const Plane_projection proj = project_along(pts, {3, 6, 6});  // not normalised: project_along does it
  EXPECT_NEAR(proj.height_min, 2, 1e-14);
  EXPECT_NEAR(proj.height_max, 2, 1e-14);
  Bezier_contour c = Bezier_contour::from_chain(proj.points, 3);
  std::vector<std::vector<double>> scales(c.size());
  for (std::size_t m = 0; m < c.size(); ++m)
    for (std::size_t i = 0; i <= 3; ++i) scales[m].push_back(proj.norms[(3 * m + i) % proj.norms.size()]);
  c.set_scales(scales);
  const auto r = check_extrusion<Failsafe_kernel<double>>(c, {.rotation_error = proj.rotation_error});
  EXPECT_EQ(r.verdict, Extrusion_verdict::certified);
  EXPECT_EQ(r.rotation_error, proj.rotation_error);
  // the rotation error enters every computation error
  EXPECT_GE(r.conditions[0].worst->computation_error, 2 * proj.rotation_error);
  // margins equal the planar ones up to the rotation error (rotations preserve distances)
  const auto flat = check_extrusion<Failsafe_kernel<double>>(planar);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(r.conditions[k].min_margin, flat.conditions[k].min_margin, 1e-12) << k;
}

TEST(Extrusion, BadOptions) {
  const Bezier_contour c = circle_contour(6);
  EXPECT_THROW((void)check_extrusion<Filtered_exact_kernel>(c, {.relative_uncertainty = -1}), Invalid_input);
  EXPECT_THROW((void)check_extrusion<Filtered_exact_kernel>(c, {.relative_uncertainty = std::nan("")}), Invalid_input);
  EXPECT_THROW((void)check_extrusion<Filtered_exact_kernel>(c, {.absolute_uncertainty = INFINITY}), Invalid_input);
}

TEST(Extrusion, DegenerateContours) {
  // M = 1 (one closed curve) and M = 2 (a lens): the sufficient conditions
  // can never certify them (condition 1 resp. 2 has margin 0) — refused, not a crash.
  const Bezier_contour one = Bezier_contour::from_curves({{{0, 0}, {1, 0}, {1, 1}, {0, 0}}});
  const auto r1 = check_extrusion<Filtered_exact_kernel>(one);
  EXPECT_EQ(r1.verdict, Extrusion_verdict::refused);
  EXPECT_LE(r1.conditions[0].min_margin, 0);
  const Bezier_contour lens =
      Bezier_contour::from_curves({{{0, 0}, {0.5, 1}, {1, 0}}, {{1, 0}, {0.5, -1}, {0, 0}}});
  const auto r2 = check_extrusion<Filtered_exact_kernel>(lens);
  EXPECT_EQ(r2.verdict, Extrusion_verdict::refused);
  EXPECT_EQ(r2.conditions[1].verdict, Extrusion_verdict::refused);
  EXPECT_EQ(r2.non_adjacent_pairs, 0u);
  // a repeated control point (zero derivative: possible cusp) voids condition 1
  const Bezier_contour cusp = Bezier_contour::from_chain(
      std::vector<Point_2<double>>{{0, 0}, {0, 0}, {1, 1}, {2, 0}, {2, -1}, {1, -2}, {0, -1}, {-1, -1}, {-1, 0}}, 3);
  const auto rc = check_extrusion<Filtered_exact_kernel>(cusp);
  bool found = false;
  for (const auto& p : rc.offending)
    if (p.condition == Extrusion_condition::no_self_intersection && p.curve_a == 0) {
      found = true;
      EXPECT_EQ(p.margin, 0);  // 0 is a point of q
      EXPECT_EQ(p.verdict, Extrusion_verdict::refused);
    }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace relgeo::test

namespace relgeo::test {
namespace {

// The verdict and the margins (rounded in hardware) do not depend on the
// caller's floating-point environment: the checker establishes the default.
TEST(Extrusion, SameReportInEveryFloatingPointEnvironment) {
  const std::vector<Bezier_contour> contours{circle_contour(16), thin_rectangle_contour(1e-4), bow_tie_contour(),
                                             looped_circle_contour(8)};
  for (const auto& c : contours) {
    const auto reference = check_extrusion<Failsafe_kernel<double>>(c);
    for (const auto& s : test::non_default_fp_environments()) {
      Extrusion_report r;
      {
        const test::Scoped_fp_environment environment(s);
        r = check_extrusion<Failsafe_kernel<double>>(c);
      }
      EXPECT_EQ(r.verdict, reference.verdict) << s.name;
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(r.conditions[k].min_margin, reference.conditions[k].min_margin) << s.name << " condition " << k + 1;
      EXPECT_EQ(r.max_hull_backward_error, reference.max_hull_backward_error) << s.name;
    }
  }
}

}  // namespace
}  // namespace relgeo::test
