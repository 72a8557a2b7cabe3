// The measures themselves: exact residuals (dyadic and rational paths agree
// with hand-computed values), rounding direction, condition numbers (exact
// against known values and against the estimator), scalar conversions.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "relgeo/linear.h"
#include "relgeo_fixtures/linear/test_problems.h"

namespace relgeo::test {
namespace {

TEST(Measures, ExactResidualOfAOneUlpError) {
  // A = I, b = (1, 1), x~ = (1, 1 + 2^-52): r = (0, -2^-52), ||A|| = 1,
  // ||x~|| = 1 + 2^-52, ||b|| = 1: eta = 2^-52 / (2 + 2^-52), omega the same.
  Dense_matrix<double> a = Dense_matrix<double>::Identity(2, 2);
  Dense_vector<double> b(2), x(2);
  b << 1, 1;
  x << 1, 1 + 0x1p-52;
  const Linear_reference ref(a, b);
  EXPECT_TRUE(ref.dyadic());
  const auto e = measure_solution(ref, x);
  EXPECT_EQ(e.residual_norm, 0x1p-52);
  const mpq_class eps = mpq_class(1) / mpq_class(mpz_class(1) << 52);
  const mpq_class eta = eps / (2 + eps);
  EXPECT_EQ(e.normwise_backward_error, round_rational<double>(eta, Rounding::upward));
  EXPECT_GE(mpq_class(e.normwise_backward_error), eta);  // rounded upward
  EXPECT_EQ(e.componentwise_backward_error, round_rational<double>(eps / (2 + eps), Rounding::upward));
  EXPECT_EQ(*e.forward_error, 0x1p-52);
}

TEST(Measures, RationalAndDyadicPathsAgree) {
  // The same problem once with dyadic data (fast path) and once multiplied by
  // 3 in rationals (not dyadic: the rational path); the backward errors are
  // scale invariant, so they must agree exactly.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> d(-1, 1);
  const int n = 12;
  Dense_matrix<double> a(n, n);
  Dense_vector<double> b(n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) a(i, j) = d(rng);
  for (int i = 0; i < n; ++i) b(i) = d(rng) * std::ldexp(1.0, i * 40 - 200);  // wide exponent range
  const Dense_vector<double> x = gaussian_elimination<double>(a, b, Pivoting::partial);
  const Linear_reference r1(a, b);
  const Dense_matrix<mpq_class> a3 = to_rational_matrix(a) * mpq_class(1, 3);
  const Dense_vector<mpq_class> b3 = to_rational_vector(b) * mpq_class(1, 3);
  const Linear_reference r3(a3, b3);
  EXPECT_TRUE(r1.dyadic());
  EXPECT_FALSE(r3.dyadic());
  const auto e1 = measure_solution(r1, x), e3 = measure_solution(r3, x);
  EXPECT_EQ(e1.normwise_backward_error, e3.normwise_backward_error);
  EXPECT_EQ(e1.componentwise_backward_error, e3.componentwise_backward_error);
  EXPECT_EQ(*e1.forward_error, *e3.forward_error);
  EXPECT_GT(e1.normwise_backward_error, 0);
}

TEST(Measures, ComponentwiseInfiniteWhenAZeroRowHasAResidual) {
  // Row 2 of [A | b] is (0 0 | 0)... singular; use instead b_2 = 0 and x~ with
  // a component that makes |A||x~| + |b| vanish: A = diag(1, 1), b = (1, 0),
  // x~ = (1, 0) is exact; x~ = (1, 1e-300) has r_2 = -1e-300 with s_2 = 1e-300.
  Dense_matrix<double> a = Dense_matrix<double>::Identity(2, 2);
  Dense_vector<double> b(2), x(2);
  b << 1, 0;
  x << 1, 1e-300;
  const Linear_reference ref(a, b);
  const auto e = measure_solution(ref, x);
  EXPECT_EQ(e.componentwise_backward_error, 1.0);  // |r_2| / (|A||x|)_2 = 1
  EXPECT_GT(e.normwise_backward_error, 0);
  Dense_vector<double> bad(2);
  bad << 1, std::nan("");
  const auto f = measure_solution(ref, bad);
  EXPECT_FALSE(f.finite);
  EXPECT_TRUE(std::isinf(f.normwise_backward_error));
}

TEST(Measures, ExactConditionNumbersOfHilbertMatrices) {
  // kappa_inf(H_n), known integers (e.g. Higham, Table 28.1 / OEIS-style lists).
  const std::pair<int, double> known[] = {{2, 27}, {3, 748}, {4, 28375}, {5, 943656}, {6, 29070279}};
  for (const auto& [n, kappa] : known) {
    const auto h = hilbert_system(n);
    const Linear_reference ref(h.a, h.b);
    EXPECT_TRUE(ref.condition().exact);
    EXPECT_EQ(ref.condition().value, kappa) << n;
    ASSERT_TRUE(ref.solution());
    for (Eigen::Index i = 0; i < n; ++i) EXPECT_EQ((*ref.solution())(i), 1) << "x = ones";
  }
}

TEST(Measures, EstimatedConditionNumberBracketsTheExactOne) {
  for (int n : {5, 20, 35}) {
    const auto [a, b] = random_system(n, static_cast<unsigned>(n));
    const Linear_reference exact(a, b);
    const Linear_reference est(a, b, {.exact_solution_limit = 0, .exact_condition_limit = 0});
    EXPECT_TRUE(exact.condition().exact);
    EXPECT_FALSE(est.condition().exact);
    EXPECT_FALSE(est.solution());
    // Hager-Higham is a lower bound (up to rounding), usually within 3x.
    EXPECT_LE(est.condition().value, exact.condition().value * (1 + 1e-10)) << n;
    EXPECT_GE(est.condition().value, exact.condition().value / 10) << n;
    const auto e = measure_solution(est, gaussian_elimination<double>(a, b, Pivoting::partial));
    EXPECT_FALSE(e.forward_error);
  }
}

TEST(Measures, ScalarConversionsAreExactAndCorrectlyRounded) {
  const mpq_class third(1, 3);
  EXPECT_EQ(Number_traits<double>::from_rational(third), 1.0 / 3.0);
  EXPECT_EQ(Number_traits<float>::from_rational(third), 1.0f / 3.0f);
  EXPECT_EQ(Number_traits<long double>::from_rational(third), 1.0L / 3.0L);
  EXPECT_EQ(Number_traits<double>::to_rational(0.1), mpq_class(3602879701896397, 36028797018963968));
  // subnormals and the largest long double survive the round trip
  for (double v : {4.9406564584124654e-324, -2.2250738585072014e-308, 1.7976931348623157e308, 0.0})
    EXPECT_EQ(Number_traits<double>::from_rational(Number_traits<double>::to_rational(v)), v);
  const long double big = std::numeric_limits<long double>::max();
  EXPECT_EQ(Number_traits<long double>::from_rational(Number_traits<long double>::to_rational(big)), big);
  using M = Mpfr_number<200>;
  const M m = Number_traits<M>::from_rational(third);
  const mpq_class back = Number_traits<M>::to_rational(m);
  EXPECT_LT(abs(back - third), mpq_class(1) / (mpq_class(mpz_class(1) << 200)));
  EXPECT_THROW((void)Number_traits<double>::to_rational(std::nan("")), Non_finite_input);
  // Eigen sees the MPFR type's epsilon
  EXPECT_EQ(Eigen::NumTraits<Mpfr_number<64>>::epsilon().to_double(), 0x1p-63);
  EXPECT_EQ(Eigen::NumTraits<mpq_class>::epsilon(), 0);
}

}  // namespace
}  // namespace relgeo::test
