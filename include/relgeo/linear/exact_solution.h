// relgeo/linear/exact_solution.h — exact rational solutions, inverses and
// ranks: the ground truth of the linear-equation measures.
#pragma once

#include <gmpxx.h>

#include <string>
#include <utility>

#include "relgeo/core/errors.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/linear/gaussian_elimination.h"
#include "relgeo/linear/scalar_traits.h"

namespace relgeo {

namespace internal {
/// The matrix or vector of f(entry), with entries of type T.
template <class T, class Matrix, class F>
Eigen::Matrix<T, Matrix::RowsAtCompileTime, Matrix::ColsAtCompileTime> map_entries(const Matrix& m, F f) {
  Eigen::Matrix<T, Matrix::RowsAtCompileTime, Matrix::ColsAtCompileTime> r(m.rows(), m.cols());
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.rows(); ++i) r(i, j) = f(m(i, j));
  return r;
}
}  // namespace internal

/// The exact value of every entry (throws Non_finite_input for NaN/inf).
template <class S>
Dense_matrix<mpq_class> to_rational_matrix(const Dense_matrix<S>& a) {
  return internal::map_entries<mpq_class>(a, [](const S& v) { return mpq_class(Number_traits<S>::to_rational(v)); });
}
template <class S>
Dense_vector<mpq_class> to_rational_vector(const Dense_vector<S>& v) {
  return internal::map_entries<mpq_class>(v, [](const S& x) { return mpq_class(Number_traits<S>::to_rational(x)); });
}
/// Every entry correctly rounded to S.
template <class S>
Dense_matrix<S> from_rational_matrix(const Dense_matrix<mpq_class>& q) {
  return internal::map_entries<S>(q, [](const mpq_class& x) { return Number_traits<S>::from_rational(x); });
}
template <class S>
Dense_vector<S> from_rational_vector(const Dense_vector<mpq_class>& q) {
  return internal::map_entries<S>(q, [](const mpq_class& x) { return Number_traits<S>::from_rational(x); });
}

namespace internal {

/// \brief X = A^-1 B exactly, by fraction-free (Bareiss) elimination.
///
/// Each row of [A | B] is first scaled by the lcm of its denominators (which
/// leaves the solution unchanged), so the elimination runs on integers:
/// a(i,j) <- (a(i,j) a(k,k) - a(i,k) a(k,j)) / p_{k-1}, the division exact
/// (Sylvester's identity), no gcd. The first nonzero entry of column k at or
/// below the diagonal is the pivot. Back substitution is also fraction free:
/// with d = u(n-1,n-1) = +-det, y = d x is integral (Cramer), and
/// y(k) = (d b'(k) - sum_{j>k} u(k,j) y(j)) / u(k,k) exactly.
/// \throws Singular_matrix (exactly singular) when A is singular.
inline Dense_matrix<mpq_class> bareiss_solve(const Dense_matrix<mpq_class>& a,
                                             const Dense_matrix<mpq_class>& b) {
  const Eigen::Index n = a.rows(), m = b.cols();
  if (a.cols() != n || b.rows() != n)
    throw Invalid_input("exact solve: sizes do not match");
  if (n == 0) throw Invalid_input("exact solve: empty matrix", Error_code::empty_input);
  Eigen::Matrix<mpz_class, Eigen::Dynamic, Eigen::Dynamic> w(n, n + m);
  for (Eigen::Index i = 0; i < n; ++i) {
    mpz_class l = 1;
    for (Eigen::Index j = 0; j < n; ++j) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), a(i, j).get_den_mpz_t());
    for (Eigen::Index j = 0; j < m; ++j) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), b(i, j).get_den_mpz_t());
    for (Eigen::Index j = 0; j < n; ++j) w(i, j) = a(i, j).get_num() * (l / a(i, j).get_den());
    for (Eigen::Index j = 0; j < m; ++j) w(i, n + j) = b(i, j).get_num() * (l / b(i, j).get_den());
  }
  mpz_class prev = 1, t;
  for (Eigen::Index k = 0; k < n; ++k) {
    Eigen::Index p = k;
    while (p < n && sgn(w(p, k)) == 0) ++p;
    if (p == n)
      throw Singular_matrix("exact solve: the matrix is exactly singular (no nonzero pivot in column " +
                                std::to_string(k) + " of " + std::to_string(n) + ")",
                            static_cast<std::size_t>(k), true);
    if (p != k) w.row(k).swap(w.row(p));
    const mpz_class& pivot = w(k, k);
    for (Eigen::Index i = k + 1; i < n; ++i) {
      for (Eigen::Index j = k + 1; j < n + m; ++j) {
        mpz_mul(t.get_mpz_t(), w(i, j).get_mpz_t(), pivot.get_mpz_t());
        mpz_submul(t.get_mpz_t(), w(i, k).get_mpz_t(), w(k, j).get_mpz_t());
        mpz_divexact(w(i, j).get_mpz_t(), t.get_mpz_t(), prev.get_mpz_t());
      }
      w(i, k) = 0;
    }
    prev = pivot;
  }
  const mpz_class d = w(n - 1, n - 1);
  Dense_matrix<mpq_class> x(n, m);
  std::vector<mpz_class> y(static_cast<std::size_t>(n));
  for (Eigen::Index c = 0; c < m; ++c) {
    for (Eigen::Index k = n - 1; k >= 0; --k) {
      mpz_mul(t.get_mpz_t(), d.get_mpz_t(), w(k, n + c).get_mpz_t());
      for (Eigen::Index j = k + 1; j < n; ++j)
        mpz_submul(t.get_mpz_t(), w(k, j).get_mpz_t(), y[static_cast<std::size_t>(j)].get_mpz_t());
      mpz_divexact(y[static_cast<std::size_t>(k)].get_mpz_t(), t.get_mpz_t(), w(k, k).get_mpz_t());
    }
    for (Eigen::Index k = 0; k < n; ++k) {
      x(k, c) = mpq_class(y[static_cast<std::size_t>(k)], d);
      x(k, c).canonicalize();
    }
  }
  return x;
}

}  // namespace internal

/// \brief The exact solution of A x = b in rationals (fraction-free
/// elimination, internal::bareiss_solve).
/// \throws Singular_matrix (exactly_singular() true) when A is singular;
///   Invalid_input for mismatched sizes or an empty matrix.
/// Complexity: O(n^3) operations on integers of O(n (bits per entry)) bits.
inline Dense_vector<mpq_class> exact_solve(const Dense_matrix<mpq_class>& a,
                                           const Dense_vector<mpq_class>& b) {
  internal::require_square(a, "exact solve");
  internal::require_rhs_rows(a, b, "exact solve");
  Dense_matrix<mpq_class> bb(b.size(), 1);
  bb.col(0) = b;
  return internal::bareiss_solve(a, bb).col(0);
}

/// The exact inverse. \throws as exact_solve.
inline Dense_matrix<mpq_class> exact_inverse(const Dense_matrix<mpq_class>& a) {
  if (a.rows() != a.cols()) throw Invalid_input("exact inverse: the matrix is not square");
  Dense_matrix<mpq_class> id(a.rows(), a.rows());
  for (Eigen::Index j = 0; j < a.rows(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i) id(i, j) = (i == j) ? 1 : 0;
  return internal::bareiss_solve(a, id);
}

/// The exact rank (Gaussian elimination in rationals with complete pivoting on
/// nonzero entries).
inline std::size_t exact_rank(Dense_matrix<mpq_class> a) {
  const Eigen::Index rows = a.rows(), cols = a.cols();
  std::size_t rank = 0;
  for (Eigen::Index k = 0; k < std::min(rows, cols); ++k) {
    Eigen::Index pr = -1, pc = -1;
    for (Eigen::Index j = k; j < cols && pr < 0; ++j)
      for (Eigen::Index i = k; i < rows; ++i)
        if (sgn(a(i, j)) != 0) {
          pr = i, pc = j;
          break;
        }
    if (pr < 0) break;
    a.row(k).swap(a.row(pr));
    a.col(k).swap(a.col(pc));
    ++rank;
    for (Eigen::Index i = k + 1; i < rows; ++i) {
      if (sgn(a(i, k)) == 0) continue;
      const mpq_class l = a(i, k) / a(k, k);
      for (Eigen::Index j = k; j < cols; ++j) a(i, j) -= l * a(k, j);
    }
  }
  return rank;
}

}  // namespace relgeo
