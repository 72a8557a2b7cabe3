// The Whitney extension (thesis Sec. 4.3.1) in floating point: the
// guarantees (G1) |a^| <= max|e|, (G2) |a^(p) - e_i| <= L |p - q_i| and
// (G3) |a^ - a| <= deviation checked exactly (rationals, MPFR), near and at
// the samples too; the kd-tree's values equal brute force bit for bit; the
// floating-point environment does not change them; bad data is refused.
#include <gtest/gtest.h>

#include <gmpxx.h>
#include <mpfr.h>

#include <cmath>
#include <limits>
#include <random>

#include "relgeo/core/dyadic.h"
#include "relgeo/core/mpfr_number.h"
#include "relgeo/joining/whitney_extension.h"
#include "support/fp_environments.h"

namespace {

using namespace relgeo;
using Q = mpq_class;

Q exact(double x) { return exact_rational(x); }

// Samples on a closed curve (a wobbly circle) with heights of two kinds:
// smooth (a trend) plus noise of the given amplitude.
std::vector<Whitney_sample> boundary_samples(std::mt19937_64& rng, std::size_t n, double noise) {
  std::uniform_real_distribution<double> r(-1, 1);
  std::vector<Whitney_sample> s;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    const double rad = 0.4 * (1 + 0.15 * std::sin(5 * t));
    const Point_2<double> q{0.5 + rad * std::cos(t), 0.5 + rad * std::sin(t)};
    s.push_back({q, 1e-3 * std::sin(3 * t) + noise * r(rng)});
  }
  return s;
}

// (G1) and (G2) exactly, in rationals.
void expect_guarantees(const Whitney_extension& w, const Point_2<double>& p, const Whitney_value& v) {
  ASSERT_TRUE(v.certified);
  EXPECT_LE(std::abs(v.height), w.max_abs_height());
  const Q L = exact(w.lipschitz_constant()), a = exact(v.height), px = exact(p.x), py = exact(p.y);
  for (const auto& s : w.samples()) {
    const Q d = a - exact(s.e), dx = px - exact(s.q.x), dy = py - exact(s.q.y);
    ASSERT_LE(d * d, L * L * (dx * dx + dy * dy)) << "p = (" << p.x << ", " << p.y << ")";
  }
}

// a(p) at 600 bits (directed: the bracket [a_lo, a_hi] holds the exact value).
std::pair<Q, Q> exact_bracket(const Whitney_extension& w, const Point_2<double>& p) {
  Mpfr_value l_lo(600), l_hi(600), u_lo(600), u_hi(600), d2(2200), d_lo(600), d_hi(600), t(600), s(2200);
  mpfr_set_inf(l_lo.get(), -1), mpfr_set_inf(l_hi.get(), -1), mpfr_set_inf(u_lo.get(), 1), mpfr_set_inf(u_hi.get(), 1);
  for (const auto& q : w.samples()) {
    mpfr_set_d(d2.get(), p.x, MPFR_RNDN), mpfr_sub_d(d2.get(), d2.get(), q.q.x, MPFR_RNDN), mpfr_sqr(d2.get(), d2.get(), MPFR_RNDN);
    mpfr_set_d(s.get(), p.y, MPFR_RNDN), mpfr_sub_d(s.get(), s.get(), q.q.y, MPFR_RNDN), mpfr_sqr(s.get(), s.get(), MPFR_RNDN);
    mpfr_add(d2.get(), d2.get(), s.get(), MPFR_RNDN);
    mpfr_sqrt(d_lo.get(), d2.get(), MPFR_RNDD), mpfr_sqrt(d_hi.get(), d2.get(), MPFR_RNDU);
    mpfr_mul_d(t.get(), d_hi.get(), w.lipschitz_constant(), MPFR_RNDU), mpfr_d_sub(t.get(), q.e, t.get(), MPFR_RNDD);
    mpfr_max(l_lo.get(), l_lo.get(), t.get(), MPFR_RNDD);
    mpfr_mul_d(t.get(), d_lo.get(), w.lipschitz_constant(), MPFR_RNDD), mpfr_d_sub(t.get(), q.e, t.get(), MPFR_RNDU);
    mpfr_max(l_hi.get(), l_hi.get(), t.get(), MPFR_RNDU);
    mpfr_mul_d(t.get(), d_lo.get(), w.lipschitz_constant(), MPFR_RNDD), mpfr_add_d(t.get(), t.get(), q.e, MPFR_RNDD);
    mpfr_min(u_lo.get(), u_lo.get(), t.get(), MPFR_RNDD);
    mpfr_mul_d(t.get(), d_hi.get(), w.lipschitz_constant(), MPFR_RNDU), mpfr_add_d(t.get(), t.get(), q.e, MPFR_RNDU);
    mpfr_min(u_hi.get(), u_hi.get(), t.get(), MPFR_RNDU);
  }
  Q a, b, c, d;
  mpfr_get_q(a.get_mpq_t(), l_lo.get()), mpfr_get_q(b.get_mpq_t(), u_lo.get());
  mpfr_get_q(c.get_mpq_t(), l_hi.get()), mpfr_get_q(d.get_mpq_t(), u_hi.get());
  return {(a + b) / 2, (c + d) / 2};
}

TEST(WhitneyExtension, GuaranteesHoldExactlyForComputedValues) {
  std::mt19937_64 rng(31);
  for (double noise : {0.0, 1e-4, 1e-2}) {
    const Whitney_extension w(boundary_samples(rng, 300, noise));
    EXPECT_GE(w.lipschitz_constant(), w.data_lipschitz_constant());
    std::vector<Point_2<double>> pts;
    std::uniform_real_distribution<double> r(0.05, 0.95);
    for (int k = 0; k < 150; ++k) pts.push_back({r(rng), r(rng)});
    // Next to samples: one ulp, 2^-30 and 2^-20 away (the bracket narrows).
    for (std::size_t i = 0; i < w.samples().size(); i += 37) {
      const Point_2<double> q = w.samples()[i].q;
      pts.push_back({std::nextafter(q.x, 0.5), q.y});
      pts.push_back({q.x + 0x1p-30, q.y - 0x1p-30});
      pts.push_back({q.x - 0x1p-20, q.y});
      pts.push_back(q);  // exactly a sample
    }
    const auto values = w.evaluate_all(pts);
    int fallbacks = 0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      expect_guarantees(w, pts[k], values[k]);
      fallbacks += values[k].fallback;
      const auto [lo, hi] = exact_bracket(w, pts[k]);
      const Q dev = exact(values[k].deviation), a = exact(values[k].height);
      EXPECT_LE(a - dev, lo) << k;  // |a^ - a| <= deviation, a in [lo, hi]
      EXPECT_GE(a + dev, hi) << k;
    }
    EXPECT_GT(fallbacks, 0);  // the MPFR stage was exercised (near and at samples)
    // Interpolation: a^(q_i) = e_i exactly.
    for (std::size_t i = 0; i < w.samples().size(); i += 17)
      EXPECT_EQ(w.evaluate(w.samples()[i].q).height, w.samples()[i].e);
    // (G3): between any two computed values.
    const Q L = exact(w.lipschitz_constant());
    for (std::size_t i = 0; i < 150; ++i)
      for (std::size_t j = i + 1; j < 150; j += 7) {
        Q diff = exact(values[i].height) - exact(values[j].height);
        if (diff < 0) diff = -diff;
        const Q slack = diff - exact(values[i].deviation) - exact(values[j].deviation);
        if (slack <= 0) continue;
        const Q dx = exact(pts[i].x) - exact(pts[j].x), dy = exact(pts[i].y) - exact(pts[j].y);
        EXPECT_LE(slack * slack, L * L * (dx * dx + dy * dy));
      }
  }
}

TEST(WhitneyExtension, DataSlopeIsACertifiedTightUpperBound) {
  std::mt19937_64 rng(35);
  for (double noise : {0.0, 1e-3}) {
    const Whitney_extension w(boundary_samples(rng, 150, noise));
    const auto s = w.samples();
    Q best = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
      for (std::size_t j = i + 1; j < s.size(); ++j) {
        const Q de = exact(s[i].e) - exact(s[j].e), dx = exact(s[i].q.x) - exact(s[j].q.x),
                dy = exact(s[i].q.y) - exact(s[j].q.y);
        const Q s2 = de * de / (dx * dx + dy * dy);
        if (s2 > best) best = s2;
      }
    const Q L = exact(w.data_lipschitz_constant());
    EXPECT_GE(L * L, best);
    EXPECT_LE(L * L, best * Q(1 + 1e-14));
    EXPECT_GE(w.lipschitz_constant(), w.data_lipschitz_constant() * (1 + 0x1p-30));
  }
}

TEST(WhitneyExtension, DeviationIsAFewUnitsInTheLastPlace) {
  std::mt19937_64 rng(32);
  const Whitney_extension w(boundary_samples(rng, 200, 1e-3));
  std::uniform_real_distribution<double> r(0.1, 0.9);
  double worst = 0;
  for (int k = 0; k < 500; ++k) {
    const Whitney_value v = w.evaluate({r(rng), r(rng)});
    if (!v.fallback) worst = std::max(worst, v.deviation / (w.max_abs_height() + w.lipschitz_constant()));
  }
  EXPECT_LT(worst, 1e-13);
}

TEST(WhitneyExtension, LinearDataIsReproduced) {
  // e = s x on the boundary of a square: l = u = s x inside (the maximiser is
  // the sample straight to the right), so a^ = s x up to its deviation.
  std::vector<Whitney_sample> s;
  const double slope = 0.75;
  for (int i = 0; i <= 64; ++i) {
    const double t = i / 64.0;
    for (const Point_2<double> q : {Point_2<double>{t, 0}, {t, 1}, {0, t}, {1, t}}) s.push_back({q, slope * q.x});
  }
  const Whitney_extension w(s);
  EXPECT_GE(w.data_lipschitz_constant(), slope);  // an upper bound, within rounding
  EXPECT_LE(w.data_lipschitz_constant(), slope * (1 + 1e-15));
  for (int i = 1; i < 64; ++i)
    for (int j = 1; j < 64; j += 9) {
      const Point_2<double> p{i / 64.0, j / 64.0};
      const Whitney_value v = w.evaluate(p);
      EXPECT_NEAR(v.height, slope * p.x, v.deviation + 1e-9 * slope) << p.x << " " << p.y;
      expect_guarantees(w, p, v);
    }
  // Constant data: exactly that constant, everywhere.
  std::vector<Whitney_sample> c{{{0, 0}, 0.25}, {{1, 0}, 0.25}, {{0, 1}, 0.25}};
  const Whitney_extension k(c);
  EXPECT_EQ(k.lipschitz_constant(), 0.0);
  EXPECT_EQ(k.evaluate({0.3, 0.4}).height, 0.25);
  EXPECT_EQ(k.evaluate({7, -3}).deviation, 0.0);
}

TEST(WhitneyExtension, IndexEqualsBruteForceBitForBit) {
  std::mt19937_64 rng(33);
  for (double noise : {0.0, 1e-5, 1e-2}) {
    const auto samples = boundary_samples(rng, 2000, noise);
    const Whitney_extension fast(samples), slow(samples, {.use_index = false});
    ASSERT_EQ(fast.lipschitz_constant(), slow.lipschitz_constant());
    std::uniform_real_distribution<double> r(0.0, 1.0);
    std::vector<Point_2<double>> pts;
    for (int k = 0; k < 4000; ++k) pts.push_back({r(rng), r(rng)});
    const auto a = fast.evaluate_all(pts), b = slow.evaluate_all(pts);
    std::size_t fast_cones = 0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(a[k].height), std::bit_cast<std::uint64_t>(b[k].height)) << k;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(a[k].lower), std::bit_cast<std::uint64_t>(b[k].lower)) << k;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(a[k].upper), std::bit_cast<std::uint64_t>(b[k].upper)) << k;
      fast_cones += a[k].cones;
    }
    // The index looks at a small part of the samples.
    EXPECT_LT(fast_cones, pts.size() * samples.size() / 10) << "noise " << noise;
  }
}

TEST(WhitneyExtension, ValuesDoNotDependOnTheFloatingPointEnvironment) {
  std::mt19937_64 rng(34);
  const auto samples = boundary_samples(rng, 400, 1e-3);
  std::vector<Point_2<double>> pts;
  std::uniform_real_distribution<double> r(0.0, 1.0);
  for (int k = 0; k < 300; ++k) pts.push_back({r(rng), r(rng)});
  const Whitney_extension reference(samples);
  const auto expected = reference.evaluate_all(pts);
  for (const auto& setting : test::non_default_fp_environments()) {
    std::vector<Whitney_value> got;
    double slope = 0;
    {
      const test::Scoped_fp_environment env(setting);
      const Whitney_extension w(samples);
      slope = w.lipschitz_constant();
      got = w.evaluate_all(pts);
    }
    EXPECT_EQ(slope, reference.lipschitz_constant()) << setting.name;
    for (std::size_t k = 0; k < pts.size(); ++k) ASSERT_EQ(got[k].height, expected[k].height) << setting.name << " " << k;
  }
}

TEST(WhitneyExtensionBadInput, TypedErrors) {
  EXPECT_THROW(Whitney_extension({}), Invalid_input);
  EXPECT_THROW(Whitney_extension({{{0, 0}, std::numeric_limits<double>::quiet_NaN()}}), Non_finite_input);
  EXPECT_THROW(Whitney_extension({{{std::numeric_limits<double>::infinity(), 0}, 0}}), Non_finite_input);
  EXPECT_THROW(Whitney_extension({{{0, 0}, 0}, {{0, 0}, 1e-3}}), Invalid_input);  // same (u,v), two heights
  EXPECT_THROW(Whitney_extension({{{0x1p501, 0}, 0}}), Invalid_input);
  EXPECT_THROW(Whitney_extension({{{0, 0}, 0}, {{0x1p-1000, 0}, 1}}), Invalid_input);  // slope beyond 2^500
  // Duplicates with the same height are one sample.
  const Whitney_extension w({{{0, 0}, 1}, {{0, 0}, 1}, {{1, 0}, 2}});
  EXPECT_EQ(w.samples().size(), 2u);
  EXPECT_THROW((void)w.evaluate({std::numeric_limits<double>::quiet_NaN(), 0}), Non_finite_input);
}

}  // namespace
