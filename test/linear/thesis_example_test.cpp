// The thesis' example (Sec. 3.2): A = [[phi, 1], [1, 0]], b = [1, 1],
// phi = rho*rho - 0.01 at rho = 0.1 in double. Gaussian elimination without
// pivoting returns (0, 1); with pivoting about (1, 1). The backward errors
// explain why: the problem is perfectly conditioned (kappa ~ 1), so the wrong
// answer comes from the algorithm (backward error 1/2), not from the data.
#include <gtest/gtest.h>

#include <cmath>

#include "relgeo/linear.h"
#include "relgeo_fixtures/linear/test_problems.h"

namespace relgeo::test {
namespace {

// The thesis' program, verbatim (modulo declarations).
std::pair<double, double> thesis_program() {
  double rho = 0.1, phi = rho * rho - 0.01;
  double A[2][2] = {{phi, 1.0}, {1.0, 0.0}}, b[2] = {1.0, 1.0};
  double x[2];
  double mult = 1.0 / A[0][0];
  A[1][1] = A[1][1] - mult * A[0][1];
  b[1] = b[1] - mult * b[0];
  x[1] = b[1] / A[1][1];
  x[0] = (b[0] - A[0][1] * x[1]) / A[0][0];
  return {x[0], x[1]};
}

TEST(ThesisExample, DataAsTheProgramComputesIt) {
  const auto s = thesis_example();
  // 0.1 * 0.1 rounds to 0.010000000000000002: phi is 2^-59, not 0.
  EXPECT_EQ(s.a(0, 0), 0x1p-59);
  EXPECT_EQ(s.a(0, 1), 1.0);
  EXPECT_EQ(s.a(1, 0), 1.0);
  EXPECT_EQ(s.a(1, 1), 0.0);
  const auto [x0, x1] = thesis_program();
  EXPECT_EQ(x0, 0.0);
  EXPECT_EQ(x1, 1.0);
}

TEST(ThesisExample, NoPivotingReturnsZeroOnePivotingReturnsOneOne) {
  const auto s = thesis_example();
  const Dense_vector<double> none = gaussian_elimination<double>(s.a, s.b, Pivoting::none);
  EXPECT_EQ(none(0), 0.0);
  EXPECT_EQ(none(1), 1.0);
  // bit for bit the thesis' program
  const auto [t0, t1] = thesis_program();
  EXPECT_EQ(none(0), t0);
  EXPECT_EQ(none(1), t1);
  for (Linear_solver m : {Linear_solver::ge_partial_pivoting, Linear_solver::ge_complete_pivoting,
                          Linear_solver::eigen_partial_piv_lu, Linear_solver::eigen_full_piv_lu}) {
    const Dense_vector<double> x = solve_linear_system<double>(s.a, s.b, m);
    EXPECT_EQ(x(0), 1.0) << to_string(m);
    EXPECT_EQ(x(1), 1.0) << to_string(m);  // 1 - 2^-59 rounded to double
  }
}

TEST(ThesisExample, BackwardErrorsExplainWhy) {
  const auto s = thesis_example();
  const Linear_reference ref(s.a, s.b);
  // The exact solution (1, 1 - phi) and the condition number: ||A|| = ||A^-1|| = 1 + phi.
  ASSERT_TRUE(ref.solution());
  EXPECT_EQ((*ref.solution())(0), 1);
  EXPECT_EQ((*ref.solution())(1), 1 - mpq_class(1, 1) / mpq_class(mpz_class(1) << 59));
  EXPECT_TRUE(ref.condition().exact);
  EXPECT_GE(ref.condition().value, 1.0);
  EXPECT_LE(ref.condition().value, 1.0 + 1e-15);  // (1 + 2^-59)^2 rounded up

  const auto none = measure_solution(ref, gaussian_elimination<double>(s.a, s.b, Pivoting::none));
  // r = b - A (0, 1) = (0, 1): eta = 1 / (2 + 2^-59), omega = 1 (row 2: |r| = 1 = |b|).
  EXPECT_EQ(none.residual_norm, 1.0);
  EXPECT_EQ(none.normwise_backward_error, 0.5);  // 1/(2 + 2^-59) rounded up
  EXPECT_EQ(none.componentwise_backward_error, 1.0);
  EXPECT_EQ(*none.forward_error, 1.0);

  const double u = 0x1p-53;
  for (Pivoting p : {Pivoting::partial, Pivoting::complete}) {
    const auto e = measure_solution(ref, gaussian_elimination<double>(s.a, s.b, p));
    // r = (-phi, 0): eta = phi / (2 + phi) ~ 2^-60, far below u.
    EXPECT_LE(e.normwise_backward_error, u / 8) << to_string(p);
    EXPECT_GT(e.normwise_backward_error, 0) << to_string(p);
    EXPECT_LE(e.componentwise_backward_error, u / 4) << to_string(p);
    EXPECT_LE(*e.forward_error, u / 4) << to_string(p);
    EXPECT_GT(none.normwise_backward_error, 1e16 * e.normwise_backward_error);
  }
  // Perturbation theory (thesis eq. 3.1, Rigal-Gaches form): to first order
  // the relative forward error is at most 2 kappa eta / (1 - kappa eta):
  // kappa ~ 1, so the forward error is as large as the backward error —
  // an unstable algorithm on a well-conditioned problem.
  for (Linear_solver m : all_linear_solvers) {
    const auto e = measure_solution(ref, solve_linear_system<double>(s.a, s.b, m));
    const double ke = ref.condition().value * e.normwise_backward_error;
    ASSERT_LT(ke, 1.0);
    EXPECT_LE(*e.forward_error, 2 * ke / (1 - ke) * (1 + 1e-12)) << to_string(m);
  }
}

TEST(ThesisExample, GrowthFactorShowsTheInstability) {
  const auto s = thesis_example();
  const auto none = lu_decompose<double>(s.a, Pivoting::none);
  EXPECT_EQ(none.lu(1, 1), -0x1p59);  // 0 - 2^59 * 1
  EXPECT_EQ(none.growth_factor, 0x1p59);
  EXPECT_EQ(lu_decompose<double>(s.a, Pivoting::partial).growth_factor, 1.0);
  EXPECT_EQ(lu_decompose<double>(s.a, Pivoting::complete).growth_factor, 1.0);
}

TEST(ThesisExample, OtherScalars) {
  const auto s = thesis_example();
  // float and MPFR at 53 bits behave like double: (0, 1).
  {
    const Dense_vector<float> x =
        gaussian_elimination<float>(s.a.cast<float>(), s.b.cast<float>(), Pivoting::none);
    EXPECT_EQ(x(0), 0.0f);
    EXPECT_EQ(x(1), 1.0f);
  }
  {
    using M53 = Mpfr_number<53>;
    const auto x = gaussian_elimination<M53>(from_rational_matrix<M53>(to_rational_matrix(s.a)),
                                             from_rational_vector<M53>(to_rational_vector(s.b)), Pivoting::none);
    EXPECT_EQ(x(0).to_double(), 0.0);
    EXPECT_EQ(x(1).to_double(), 1.0);
  }
  // x87 long double has 64 bits: 1 - 2^59 and 1 - 2^-59 are exact, and
  // elimination without pivoting returns the exact solution (1, 1 - 2^-59).
  if constexpr (std::numeric_limits<long double>::digits >= 64) {
    const Dense_vector<long double> x =
        gaussian_elimination<long double>(s.a.cast<long double>(), s.b.cast<long double>(), Pivoting::none);
    EXPECT_EQ(x(0), 1.0L);
    EXPECT_EQ(x(1), 1.0L - 0x1p-59L);
  }
  // Rationals: exact, whatever the pivoting.
  for (Pivoting p : {Pivoting::none, Pivoting::partial, Pivoting::complete}) {
    const Dense_vector<mpq_class> x =
        gaussian_elimination<mpq_class>(to_rational_matrix(s.a), to_rational_vector(s.b), p);
    EXPECT_EQ(x(0), 1);
    EXPECT_EQ(x(1), 1 - mpq_class(1, 1) / mpq_class(mpz_class(1) << 59));
  }
}

}  // namespace
}  // namespace relgeo::test
