// Loop weights through the number hook: exact rationals where the formulas
// are rational, enclosures under intervals, documented precision elsewhere.
#include <gtest/gtest.h>

#include <cmath>

#include "relgeo/kernel.h"
#include "relgeo/subdivision/loop_weights.h"

namespace {

using namespace relgeo;

// beta and chi at `bits` bits, independent of the library's formula code:
// beta = (5/8 - (3/8 + cos(2 pi/n)/4)^2)/n with mpfr_cos(2*pi/n).
struct Reference {
  double beta, chi;
  mpq_class beta_q;
};
Reference reference(long n, mpfr_prec_t bits = 400) {
  mpfr_t x, c, b, t;
  mpfr_inits2(bits, x, c, b, t, (mpfr_ptr)0);
  mpfr_const_pi(x, MPFR_RNDN);
  mpfr_mul_ui(x, x, 2, MPFR_RNDN);
  mpfr_div_si(x, x, n, MPFR_RNDN);
  mpfr_cos(c, x, MPFR_RNDN);
  mpfr_div_ui(t, c, 4, MPFR_RNDN);
  mpfr_add_d(t, t, 0.375, MPFR_RNDN);
  mpfr_sqr(t, t, MPFR_RNDN);
  mpfr_d_sub(b, 0.625, t, MPFR_RNDN);
  mpfr_div_si(b, b, n, MPFR_RNDN);
  Reference r;
  r.beta = mpfr_get_d(b, MPFR_RNDN);
  mpfr_get_q(r.beta_q.get_mpq_t(), b);
  // chi = 8 beta / (3 + 8 n beta)
  mpfr_mul_ui(t, b, 8 * n, MPFR_RNDN);
  mpfr_add_ui(t, t, 3, MPFR_RNDN);
  mpfr_mul_ui(x, b, 8, MPFR_RNDN);
  mpfr_div(x, x, t, MPFR_RNDN);
  r.chi = mpfr_get_d(x, MPFR_RNDN);
  mpfr_clears(x, c, b, t, (mpfr_ptr)0);
  return r;
}

TEST(LoopWeights, ExactRationalsAtValences3_4_6UnderTheExactKernel) {
  Loop_weights<Exact_kernel> w;
  EXPECT_EQ(w.beta(3), mpq_class(3, 16));
  EXPECT_EQ(w.beta(4), mpq_class(31, 256));
  EXPECT_EQ(w.beta(6), mpq_class(1, 16));
  EXPECT_EQ(w.centre(6), mpq_class(5, 8));
  EXPECT_EQ(w.chi(3), mpq_class(1, 5));
  EXPECT_EQ(w.chi(4), mpq_class(31, 220));
  EXPECT_EQ(w.chi(6), mpq_class(1, 12));
  EXPECT_EQ(w.limit_centre(6), mpq_class(1, 2));
  EXPECT_EQ(w.cos_2pi_n(6), mpq_class(1, 2));
  EXPECT_EQ(w.sixth(), mpq_class(1, 6));
  EXPECT_EQ(w.two_thirds(), mpq_class(2, 3));
  // every mask is exactly affine, at every valence
  w.reserve(40);
  for (Index n = 1; n <= 40; ++n) {
    EXPECT_EQ(w.centre(n) + n * w.beta(n), 1) << n;
    EXPECT_EQ(w.limit_centre(n) + n * w.chi(n), 1) << n;
  }
}

TEST(LoopWeights, IrrationalValencesUnderTheExactKernelAreWithin2ToMinus250) {
  Loop_weights<Exact_kernel> w;
  w.reserve(20);
  for (long n : {5L, 7L, 8L, 9L, 12L, 20L}) {
    const mpq_class err = abs(w.beta(Index(n)) - reference(n).beta_q);
    EXPECT_LT(err, mpq_class(1) / (mpz_class(1) << 250)) << n;
    EXPECT_GT(err, 0) << n << ": an irrational beta cannot be exact";
  }
}

TEST(LoopWeights, WarrenWeightsAreRationalEverywhere) {
  Loop_weights<Exact_kernel> w(Loop_options{.vertex_weights = Loop_vertex_weights::warren});
  w.reserve(12);
  EXPECT_EQ(w.beta(3), mpq_class(3, 16));
  for (Index n = 4; n <= 12; ++n) {
    mpq_class b(3, 8 * n);
    b.canonicalize();
    EXPECT_EQ(w.beta(n), b) << n;
    EXPECT_EQ(w.chi(n), mpq_class(1, 2 * n)) << n;  // 1 / (n + 3 / (8 beta))
  }
}

TEST(LoopWeights, DoubleWeightsAreCorrectlyRoundedUpToAFewUlps) {
  Loop_weights<Naive_kernel<double>> w;
  w.reserve(30);
  for (Index n = 3; n <= 30; ++n) {
    const Reference r = reference(n);
    EXPECT_NEAR(w.beta(n), r.beta, 4 * (std::nextafter(r.beta, 1.0) - r.beta)) << n;
  }
}

TEST(LoopWeights, IntervalWeightsEncloseTheTrueValues) {
  Loop_weights<Interval_kernel> w;
  w.reserve(30);
  for (Index n = 3; n <= 30; ++n) {
    const Reference r = reference(n);
    EXPECT_LE(w.beta(n).inf(), r.beta) << n;
    EXPECT_GE(w.beta(n).sup(), r.beta) << n;
    EXPECT_LE(w.chi(n).inf(), r.chi) << n;
    EXPECT_GE(w.chi(n).sup(), r.chi) << n;
    EXPECT_LT(w.beta(n).sup() - w.beta(n).inf(), 1e-15) << n;
  }
  EXPECT_TRUE(w.beta(6).is_point());  // 1/16: exact
  EXPECT_TRUE(w.beta(4).is_point());
}

TEST(LoopWeights, MpfrWeightsFollowThePrecision) {
  Loop_weights<Mpfr_kernel<200>> w;
  w.reserve(9);
  const Reference r = reference(7);
  EXPECT_NEAR(w.beta(7).to_double(), r.beta, 1e-17);
  EXPECT_EQ(w.beta(6).to_double(), 1.0 / 16);
}

TEST(LoopWeights, CosineHookIsExactExactlyWhereNivenSays) {
  using T = Loop_number_traits<mpq_class>;
  EXPECT_EQ(T::cos_2pi(1, 1), 1);
  EXPECT_EQ(T::cos_2pi(1, 2), -1);
  EXPECT_EQ(T::cos_2pi(1, 3), mpq_class(-1, 2));
  EXPECT_EQ(T::cos_2pi(1, 4), 0);
  EXPECT_EQ(T::cos_2pi(1, 6), mpq_class(1, 2));
  EXPECT_EQ(T::cos_2pi(2, 12), mpq_class(1, 2));   // reduced: 1/6
  EXPECT_EQ(T::cos_2pi(5, 6), mpq_class(1, 2));
  EXPECT_EQ(T::cos_2pi(9, 12), 0);                 // 3/4
  const double c5 = T::cos_2pi(1, 5).get_d();
  EXPECT_NEAR(c5, (std::sqrt(5.0) - 1) / 4, 1e-16);
  EXPECT_FALSE(T::policy().empty());
  EXPECT_EQ(Loop_number_traits<double>::cos_2pi(1, 6), 0.5);  // std::cos(pi/3) is not
}

TEST(LoopWeights, BlzGammaAtSmallSectors) {
  Loop_weights<Exact_kernel> w(Loop_options{.crease_rules = Loop_crease_rules::biermann_levin_zorin});
  EXPECT_EQ(w.gamma(1, false), mpq_class(3, 4));
  EXPECT_EQ(w.gamma(2, false), mpq_class(1, 2));
  EXPECT_EQ(w.gamma(3, false), mpq_class(3, 8));  // the regular boundary: the smooth 3/8
  EXPECT_EQ(w.gamma(1, true), mpq_class(1, 2));   // corner, alpha = pi/2
  EXPECT_THROW(Loop_weights<Exact_kernel>(Loop_options{.corner_angle_num = 3, .corner_angle_den = 2}),
               Precondition_violation);
}

}  // namespace
