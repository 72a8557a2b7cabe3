// Gaussian elimination variants and Eigen's LU peers in every scalar:
// accuracy against the exact solution, backward errors within the classical
// bounds, singular and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "relgeo/linear.h"
#include "relgeo_fixtures/linear/test_problems.h"

namespace relgeo::test {
namespace {

/// A reproducible well-conditioned test system: entries uniform in [-1, 1]
/// plus n at the positions of a random permutation (a row-permuted diagonally
/// dominant matrix: well conditioned, but the pivots must be searched for).
Linear_system<double> random_system(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  Linear_system<double> s{Dense_matrix<double>(n, n), Dense_vector<double>(n)};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) s.a(i, j) = d(rng);
  std::vector<int> perm(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) perm[static_cast<std::size_t>(i)] = i;
  std::shuffle(perm.begin(), perm.end(), rng);
  for (int i = 0; i < n; ++i) s.a(i, perm[static_cast<std::size_t>(i)]) += n;
  for (int i = 0; i < n; ++i) s.b(i) = d(rng);
  return s;
}

template <class S>
class EliminationScalars : public ::testing::Test {};
using Scalars = ::testing::Types<float, double, long double, Mpfr_number<113>, mpq_class>;
TYPED_TEST_SUITE(EliminationScalars, Scalars);

TYPED_TEST(EliminationScalars, StableMethodsHaveBackwardErrorOfOrderNU) {
  using S = TypeParam;
  for (int n : {1, 2, 5, 17, 40}) {
    const auto s = random_system(n, static_cast<unsigned>(n));
    // The problem in S is the double data rounded to S (exact for all but float).
    const Dense_matrix<S> a = from_rational_matrix<S>(to_rational_matrix(s.a));
    const Dense_vector<S> b = from_rational_vector<S>(to_rational_vector(s.b));
    const Linear_reference ref(a, b);
    const double u = Number_traits<S>::unit_roundoff;
    for (Linear_solver m : all_linear_solvers) {
      if (m == Linear_solver::ge_no_pivoting && !Number_traits<S>::is_exact) continue;  // unstable here
      if (m == Linear_solver::eigen_full_piv_lu && !std::is_constructible_v<S, Eigen::Index>) continue;
      const Dense_vector<S> x = solve_linear_system<S>(a, b, m);
      const auto e = measure_solution(ref, x);
      ASSERT_TRUE(e.finite);
      if constexpr (Number_traits<S>::is_exact) {
        EXPECT_EQ(e.residual_norm, 0.0) << to_string(m);
        EXPECT_EQ(*e.forward_error, 0.0) << to_string(m);
      } else {
        // Higham Thm 9.4/9.5: |dA| <= gamma_3n |L||U|; with the modest growth
        // of these matrices eta stays below a few n u (measured: < 1.5 n u).
        EXPECT_LE(e.normwise_backward_error, 4.0 * n * u) << to_string(m) << " n=" << n;
        EXPECT_LE(e.componentwise_backward_error, 8.0 * n * u) << to_string(m) << " n=" << n;
        // forward <= ~2 kappa eta
        EXPECT_LE(*e.forward_error, 2.5 * ref.condition().value * e.normwise_backward_error + 4 * u)
            << to_string(m) << " n=" << n;
      }
    }
  }
}

TYPED_TEST(EliminationScalars, ExactlySingularMatrices) {
  using S = TypeParam;
  Dense_matrix<double> a(3, 3);
  a << 1, 2, 3, 2, 4, 6, 1, 0, 1;  // row 2 = 2 row 1: rank 2
  Dense_vector<double> b(3);
  b << 1, 2, 3;
  const Dense_matrix<S> as = from_rational_matrix<S>(to_rational_matrix(a));
  const Dense_vector<S> bs = from_rational_vector<S>(to_rational_vector(b));
  for (Pivoting p : {Pivoting::partial, Pivoting::complete}) {
    try {
      (void)gaussian_elimination<S>(as, bs, p);
      // A rounding scalar may miss the exact zero (then the solution is huge).
      EXPECT_FALSE(Number_traits<S>::is_exact) << "exactly singular matrix accepted";
    } catch (const Singular_matrix& e) {
      EXPECT_EQ(e.exactly_singular(), Number_traits<S>::is_exact);
      EXPECT_EQ(e.code(), Number_traits<S>::is_exact ? Error_code::invalid_input : Error_code::computation_failure);
      if (Number_traits<S>::is_exact) {
        EXPECT_EQ(e.step(), 2u) << "rank 2";
      }
      EXPECT_NE(std::string(e.what()).find("zero pivot"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(exact_solve(to_rational_matrix(a), to_rational_vector(b)), Singular_matrix);
  EXPECT_EQ(exact_rank(to_rational_matrix(a)), 2u);
  EXPECT_THROW((Linear_reference(as, bs)), Singular_matrix);
}

TEST(Elimination, ZeroPivotWithoutPivotingIsNotSingularity) {
  Dense_matrix<double> a(2, 2);
  a << 0, 1, 1, 0;
  Dense_vector<double> b(2);
  b << 2, 3;
  try {
    (void)gaussian_elimination<double>(a, b, Pivoting::none);
    FAIL() << "no exception";
  } catch (const Singular_matrix& e) {
    EXPECT_FALSE(e.exactly_singular());
    EXPECT_EQ(e.code(), Error_code::computation_failure);
    EXPECT_EQ(e.step(), 0u);
    EXPECT_NE(std::string(e.what()).find("may be nonsingular"), std::string::npos) << e.what();
  }
  const Dense_vector<double> x = gaussian_elimination<double>(a, b, Pivoting::partial);
  EXPECT_EQ(x(0), 3.0);
  EXPECT_EQ(x(1), 2.0);
  // The same with rationals: no pivoting cannot prove singularity either.
  try {
    (void)gaussian_elimination<mpq_class>(to_rational_matrix(a), to_rational_vector(b), Pivoting::none);
    FAIL() << "no exception";
  } catch (const Singular_matrix& e) {
    EXPECT_FALSE(e.exactly_singular());
  }
}

TEST(Elimination, SingularToWorkingPrecisionAndEigenPeers) {
  Dense_matrix<double> a(2, 2);
  a << 1, 2, 2, 4;
  Dense_vector<double> b(2);
  b << 1, 1;
  for (Linear_solver m : all_linear_solvers) {
    try {
      (void)solve_linear_system<double>(a, b, m);
      FAIL() << to_string(m) << ": no exception";
    } catch (const Singular_matrix& e) {
      EXPECT_FALSE(e.exactly_singular()) << to_string(m);
      EXPECT_EQ(e.code(), Error_code::computation_failure) << to_string(m);
    }
    try {
      (void)solve_linear_system<mpq_class>(to_rational_matrix(a), to_rational_vector(b), m);
      FAIL() << to_string(m) << ": no exception";
    } catch (const Singular_matrix& e) {
      // exact scalar: pivoting methods prove singularity
      EXPECT_EQ(e.exactly_singular(), m != Linear_solver::ge_no_pivoting) << to_string(m);
    }
  }
}

TEST(Elimination, BadInput) {
  Dense_matrix<double> a(2, 2);
  a << 1, 2, 3, 4;
  Dense_vector<double> b(2);
  b << 1, 1;
  Dense_vector<double> b3(3);
  b3 << 1, 1, 1;
  for (Linear_solver m : all_linear_solvers) {
    EXPECT_THROW((void)solve_linear_system<double>(a, b3, m), Invalid_input) << to_string(m);
    EXPECT_THROW((void)solve_linear_system<double>(Dense_matrix<double>(2, 3), b, m), Invalid_input) << to_string(m);
    EXPECT_THROW((void)solve_linear_system<double>(Dense_matrix<double>(0, 0), Dense_vector<double>(0), m),
                 Invalid_input)
        << to_string(m);
    Dense_matrix<double> an = a;
    an(1, 0) = std::nan("");
    EXPECT_THROW((void)solve_linear_system<double>(an, b, m), Non_finite_input) << to_string(m);
    Dense_vector<double> bn = b;
    bn(0) = INFINITY;
    EXPECT_THROW((void)solve_linear_system<double>(a, bn, m), Non_finite_input) << to_string(m);
  }
  EXPECT_THROW((Linear_reference(a, b3)), Invalid_input);
  Dense_matrix<double> an = a;
  an(0, 0) = std::nan("");
  EXPECT_THROW((Linear_reference(an, b)), Non_finite_input);
  EXPECT_THROW(linear_solver_from_string("cholesky"), Invalid_input);
  EXPECT_EQ(linear_solver_from_string("eigen-full"), Linear_solver::eigen_full_piv_lu);
  // wrong solution size for the measures
  const Linear_reference ref(a, b);
  EXPECT_THROW((void)measure_solution(ref, b3), Invalid_input);
  try {
    (void)gaussian_elimination<double>(a, b3, Pivoting::partial);
  } catch (const Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("2 rows but the right-hand side has 3"), std::string::npos) << e.what();
  }
}

TEST(Elimination, PivotOrders) {
  Dense_matrix<double> a(3, 3);
  a << 1, 2, 3, 4, 5, 6, 7, 8, 10;
  const auto partial = lu_decompose<double>(a, Pivoting::partial);
  EXPECT_EQ(partial.row_order[0], 2);  // |7| largest in column 0
  EXPECT_EQ(partial.column_order, (std::vector<Eigen::Index>{0, 1, 2}));
  const auto complete = lu_decompose<double>(a, Pivoting::complete);
  EXPECT_EQ(complete.row_order[0], 2);  // 10 at (2, 2)
  EXPECT_EQ(complete.column_order[0], 2);
  // P A Q = L U, exactly in rationals
  const auto exact = lu_decompose<mpq_class>(to_rational_matrix(a), Pivoting::complete);
  const Eigen::Index n = 3;
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      mpq_class s = 0;
      for (Eigen::Index k = 0; k <= std::min(i, j); ++k)
        s += (k == i ? mpq_class(1) : exact.lu(i, k)) * exact.lu(k, j);
      EXPECT_EQ(s, mpq_class(a(exact.row_order[static_cast<std::size_t>(i)], exact.column_order[static_cast<std::size_t>(j)])));
    }
}

TEST(Elimination, CompletePivotingSearchFusedWithTheUpdateFindsTheSamePivots) {
  // Reference: the textbook loop (search the whole trailing block, then
  // update), same arithmetic. Small integer entries make ties frequent: the
  // first maximum in column-major order must win in both.
  std::mt19937_64 rng(21);
  std::uniform_int_distribution<int> d(-3, 3);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 2 + trial % 23;
    Dense_matrix<double> a(n, n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) a(i, j) = d(rng) + (i == j ? 0.5 : 0.0);
    Dense_matrix<double> w = a;
    std::vector<Eigen::Index> rows(static_cast<std::size_t>(n)), cols(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) rows[static_cast<std::size_t>(i)] = cols[static_cast<std::size_t>(i)] = i;
    bool singular = false;
    for (int k = 0; k < n && !singular; ++k) {
      int pr = k, pc = k;
      for (int j = k; j < n; ++j)
        for (int i = k; i < n; ++i)
          if (std::abs(w(pr, pc)) < std::abs(w(i, j))) pr = i, pc = j;
      if (w(pr, pc) == 0) {
        singular = true;
        break;
      }
      w.row(k).swap(w.row(pr));
      w.col(k).swap(w.col(pc));
      std::swap(rows[static_cast<std::size_t>(k)], rows[static_cast<std::size_t>(pr)]);
      std::swap(cols[static_cast<std::size_t>(k)], cols[static_cast<std::size_t>(pc)]);
      for (int i = k + 1; i < n; ++i) w(i, k) = w(i, k) / w(k, k);
      for (int j = k + 1; j < n; ++j)
        for (int i = k + 1; i < n; ++i) w(i, j) -= w(i, k) * w(k, j);
    }
    if (singular) {
      EXPECT_THROW((void)lu_decompose<double>(a, Pivoting::complete), Singular_matrix) << trial;
      continue;
    }
    const auto f = lu_decompose<double>(a, Pivoting::complete);
    EXPECT_EQ(f.row_order, rows) << trial;
    EXPECT_EQ(f.column_order, cols) << trial;
    EXPECT_TRUE(f.lu == w) << trial;  // bit for bit
    // and the same in rationals (the generic comparison path)
    const auto q = lu_decompose<mpq_class>(to_rational_matrix(a), Pivoting::complete);
    EXPECT_EQ(q.row_order[0], rows[0]) << trial;
    EXPECT_EQ(q.column_order[0], cols[0]) << trial;
  }
}

}  // namespace
}  // namespace relgeo::test
