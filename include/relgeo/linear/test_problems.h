// relgeo/linear/test_problems.h — the linear systems of the thesis (Sec. 3.2):
// its 2x2 example and Hilbert matrices; and random systems.
#pragma once

#include <gmpxx.h>

#include <random>
#include <string>

#include "relgeo/core/errors.h"
#include "relgeo/linear/exact_solution.h"
#include "relgeo/linear/gaussian_elimination.h"

namespace relgeo {

/// A x = b.
template <class S>
struct Linear_system {
  Dense_matrix<S> a;
  Dense_vector<S> b;
};

/// \brief The thesis' example (Sec. 3.2): A = [[phi, 1], [1, 0]], b = [1, 1]
/// with phi = rho*rho - 0.01 evaluated in double at rho = 0.1, exactly as the
/// thesis' program does: phi = 0.1*0.1 - 0.01 = 2^-59 = 1.7347234759768071e-18,
/// not 0 (the decimals are not binary: 0.1*0.1 rounds to 0.010000000000000002).
/// Its exact solution is x = (1, 1 - phi) (row 2: x0 = 1; row 1: phi + x1 = 1).
/// Gaussian elimination without pivoting returns (0, 1) in double: the
/// multiplier 1/phi = 7.2e16 swamps b1 = 1 and a11 = 0.
inline Linear_system<double> thesis_example(double rho = 0.1) {
  const double phi = rho * rho - 0.01;
  Linear_system<double> s{Dense_matrix<double>(2, 2), Dense_vector<double>(2)};
  s.a << phi, 1.0, 1.0, 0.0;
  s.b << 1.0, 1.0;
  return s;
}

/// The n x n Hilbert matrix h(i,j) = 1 / (i + j + 1) (0-based), exactly.
/// \throws Invalid_input for n == 0.
inline Dense_matrix<mpq_class> hilbert_matrix(Eigen::Index n) {
  if (n <= 0) throw Invalid_input("hilbert_matrix: n must be positive", Error_code::empty_input);
  Dense_matrix<mpq_class> h(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i) h(i, j) = mpq_class(1, static_cast<unsigned long>(i + j + 1));
  return h;
}

/// \brief The exact Hilbert system H x = b with b = H * ones: its exact
/// solution is x = ones.
inline Linear_system<mpq_class> hilbert_system(Eigen::Index n) {
  Linear_system<mpq_class> s{hilbert_matrix(n), Dense_vector<mpq_class>(n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    mpq_class sum = 0;
    for (Eigen::Index j = 0; j < n; ++j) sum += s.a(i, j);
    s.b(i) = sum;
  }
  return s;
}

/// The Hilbert system stored in S: every entry of H and of b = H * ones
/// (computed exactly) correctly rounded to S. The stored system is a
/// different problem from the exact one; relgeo measures solutions against
/// the stored problem's own exact solution (close to ones only when H is
/// well conditioned).
template <class S>
Linear_system<S> stored_hilbert_system(Eigen::Index n) {
  const Linear_system<mpq_class> h = hilbert_system(n);
  return {from_rational_matrix<S>(h.a), from_rational_vector<S>(h.b)};
}

/// An n x n system in double with entries uniform in [-1, 1], drawn from
/// std::mt19937_64(seed): A column by column, then b.
inline Linear_system<double> random_system(Eigen::Index n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  Linear_system<double> s{Dense_matrix<double>(n, n), Dense_vector<double>(n)};
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i) s.a(i, j) = d(rng);
  for (Eigen::Index i = 0; i < n; ++i) s.b(i) = d(rng);
  return s;
}

}  // namespace relgeo
