// relgeo/linear/backward_error.h — how good is a computed solution of A x = b:
// normwise (Rigal-Gaches) and componentwise (Oettli-Prager) backward error,
// forward error against the exact rational solution, condition number
// (thesis Sec. 3.2). Every measure is computed from exact values and reported
// as a double rounded upward.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "relgeo/core/dyadic.h"
#include "relgeo/core/errors.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/core/rounding.h"
#include "relgeo/linear/exact_solution.h"
#include "relgeo/linear/gaussian_elimination.h"
#include "relgeo/linear/scalar_traits.h"

namespace relgeo {

namespace internal {

/// The entries of m in dyadic form (column-major) into `out`; false, with
/// `out` partly filled, as soon as one is not dyadic.
template <class Matrix>
bool dyadic_entries(const Matrix& m, std::vector<Dyadic>& out) {
  out.clear();
  out.reserve(static_cast<std::size_t>(m.size()));
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
      std::optional<Dyadic> d = dyadic_of(m(i, j));
      if (!d) return false;
      out.push_back(std::move(*d));
    }
  return true;
}

/// The measure a / b (a, b >= 0) rounded upward, with the conventions 0 / 0 = 0
/// and a / 0 = +inf.
inline double measure_ratio(const mpq_class& a, const mpq_class& b) {
  if (sgn(a) == 0) return 0.0;
  if (sgn(b) == 0) return std::numeric_limits<double>::infinity();
  return round_rational<double>(a / b, Rounding::upward);
}

}  // namespace internal

/// ||A||_inf ||A^-1||_inf, exact or estimated.
struct Condition_number {
  double value = 0;    ///< rounded upward when exact; +inf for a singular matrix
  bool exact = false;  ///< false: Hager-Higham estimate (a lower bound, usually within 3x)
};

/// Options of Linear_reference.
struct Linear_reference_options {
  /// Compute the exact rational solution (for the forward error) when n <= this.
  std::size_t exact_solution_limit = 100;
  /// Compute the condition number from the exact inverse when n <= this,
  /// otherwise estimate it (Hager-Higham on double LU factors).
  std::size_t exact_condition_limit = 40;
};

/// \brief Estimate of ||A^-1||_inf = ||A^-T||_1 by Hager's method as refined
/// by Higham (LAPACK xLACON; N. J. Higham, "Accuracy and Stability of
/// Numerical Algorithms", Alg. 15.4): at most 5 iterations plus the
/// alternating test vector; solves with the double LU factors (partial
/// pivoting) of A and A^T. A lower bound of the true value, usually within a
/// factor 3. Returns +inf when the double factorization meets a zero pivot.
inline double estimate_inverse_norm_inf(const Dense_matrix<double>& a) {
  const Eigen::Index n = a.rows();
  Lu_decomposition<double> lu, lut;
  try {
    lu = lu_decompose<double>(a, Pivoting::partial);
    lut = lu_decompose<double>(a.transpose(), Pivoting::partial);
  } catch (const Singular_matrix&) {
    return std::numeric_limits<double>::infinity();
  }
  // B = A^-T: B x = solve(A^T, x), B^T x = solve(A, x); ||B||_1 = ||A^-1||_inf.
  auto norm1 = [](const Dense_vector<double>& v) { return v.cwiseAbs().sum(); };
  Dense_vector<double> x = Dense_vector<double>::Constant(n, 1.0 / static_cast<double>(n));
  double est = 0;
  Dense_vector<double> xi_old = Dense_vector<double>::Zero(n);
  for (int iter = 0; iter < 5; ++iter) {
    const Dense_vector<double> y = lut.solve(x);
    const double ny = norm1(y);
    if (!std::isfinite(ny)) return std::numeric_limits<double>::infinity();
    if (iter > 0 && ny <= est) break;
    est = ny;
    Dense_vector<double> xi(n);
    for (Eigen::Index i = 0; i < n; ++i) xi(i) = y(i) >= 0 ? 1.0 : -1.0;
    if (iter > 0 && xi == xi_old) break;
    xi_old = xi;
    const Dense_vector<double> z = lu.solve(xi);
    Eigen::Index j = 0;
    z.cwiseAbs().maxCoeff(&j);
    if (iter > 0 && std::abs(z(j)) <= z.dot(x)) break;
    x.setZero();
    x(j) = 1;
  }
  Dense_vector<double> alt(n);
  for (Eigen::Index i = 0; i < n; ++i)
    alt(i) = (i % 2 ? -1.0 : 1.0) * (1.0 + static_cast<double>(i) / static_cast<double>(std::max<Eigen::Index>(n - 1, 1)));
  const double alt_est = 2 * norm1(lut.solve(alt)) / (3 * static_cast<double>(n));
  return std::max(est, alt_est);
}

/// \brief The exact data of a problem A x = b, computed once and shared by
/// the measures of every computed solution: A and b as rationals (with a
/// dyadic copy for fast exact residuals when every entry is a binary
/// floating-point value), ||A||_inf, the exact solution (n <= limit) and the
/// condition number.
class Linear_reference {
 public:
  /// \throws Invalid_input (not square, sizes differ, empty), Non_finite_input,
  ///   Singular_matrix (exactly singular, detected when the exact solution or
  ///   the exact condition number is computed).
  template <class P>
  Linear_reference(const Dense_matrix<P>& a, const Dense_vector<P>& b,
                   const Linear_reference_options& options = {}) {
    internal::require_square(a, "linear system");
    internal::require_not_empty(a, "linear system");
    internal::require_rhs_rows(a, b, "linear system");
    a_ = to_rational_matrix(a);
    b_ = to_rational_vector(b);
    init(options);
  }

  Eigen::Index size() const { return a_.rows(); }
  const Dense_matrix<mpq_class>& a() const { return a_; }
  const Dense_vector<mpq_class>& b() const { return b_; }
  /// The exact solution, when n <= exact_solution_limit.
  const std::optional<Dense_vector<mpq_class>>& solution() const { return x_; }
  const Condition_number& condition() const { return cond_; }
  /// ||A||_inf, exact.
  const mpq_class& norm_a() const { return norm_a_; }
  const mpq_class& norm_b() const { return norm_b_; }
  /// Whether A and b are dyadic (binary floating-point values): residuals use
  /// exact integer accumulation instead of rationals.
  bool dyadic() const { return dyadic_; }
  /// Row i of A and b_i in dyadic form. \pre dyadic().
  const Dyadic& a_dyadic(Eigen::Index i, Eigen::Index j) const {
    return ad_[static_cast<std::size_t>(j * a_.rows() + i)];
  }
  const Dyadic& b_dyadic(Eigen::Index i) const { return bd_[static_cast<std::size_t>(i)]; }

 private:
  void init(const Linear_reference_options& o) {
    const Eigen::Index n = a_.rows();
    norm_a_ = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      mpq_class s = 0;
      for (Eigen::Index j = 0; j < n; ++j) s += abs(a_(i, j));
      if (s > norm_a_) norm_a_ = s;
    }
    norm_b_ = 0;
    for (Eigen::Index i = 0; i < n; ++i)
      if (abs(b_(i)) > norm_b_) norm_b_ = abs(b_(i));
    dyadic_ = internal::dyadic_entries(a_, ad_) && internal::dyadic_entries(b_, bd_);
    if (!dyadic_) ad_.clear(), bd_.clear();

    if (static_cast<std::size_t>(n) <= o.exact_solution_limit) x_ = exact_solve(a_, b_);
    if (static_cast<std::size_t>(n) <= o.exact_condition_limit) {
      const Dense_matrix<mpq_class> inv = exact_inverse(a_);
      mpq_class ninv = 0;
      for (Eigen::Index i = 0; i < n; ++i) {
        mpq_class s = 0;
        for (Eigen::Index j = 0; j < n; ++j) s += abs(inv(i, j));
        if (s > ninv) ninv = s;
      }
      cond_ = {round_rational<double>(norm_a_ * ninv, Rounding::upward), true};
    } else {
      Dense_matrix<double> ad(n, n);
      for (Eigen::Index j = 0; j < n; ++j)
        for (Eigen::Index i = 0; i < n; ++i) ad(i, j) = nearest_double(a_(i, j));
      cond_ = {round_rational<double>(norm_a_, Rounding::upward) * estimate_inverse_norm_inf(ad), false};
    }
  }

  Dense_matrix<mpq_class> a_;
  Dense_vector<mpq_class> b_;
  std::optional<Dense_vector<mpq_class>> x_;
  Condition_number cond_;
  mpq_class norm_a_, norm_b_;
  bool dyadic_ = false;
  std::vector<Dyadic> ad_, bd_;
};

/// The measures of one computed solution x~ of A x = b (infinity norms).
struct Linear_solution_errors {
  bool finite = true;  ///< every entry of x~ is finite (otherwise every measure is +inf)
  /// eta = ||b - A x~|| / (||A|| ||x~|| + ||b||) (Rigal-Gaches): the smallest
  /// eps such that (A + dA) x~ = b + db with ||dA|| <= eps ||A||, ||db|| <= eps ||b||.
  double normwise_backward_error = 0;
  /// omega = max_i |b - A x~|_i / (|A| |x~| + |b|)_i (Oettli-Prager): the
  /// smallest eps with |dA| <= eps |A|, |db| <= eps |b| entrywise; 0/0 = 0,
  /// r_i / 0 = +inf.
  double componentwise_backward_error = 0;
  /// ||x~ - x|| / ||x|| against the exact rational solution x (empty when the
  /// reference has no exact solution).
  std::optional<double> forward_error;
  double residual_norm = 0;  ///< ||b - A x~||_inf
};

/// \brief The measures of the computed solution `x` (any scalar) against the
/// problem's exact data. Residuals are exact: with dyadic data each row is
/// accumulated in one GMP integer scaled to the row's smallest exponent (no
/// rounding, no gcd); otherwise in rationals. Values rounded upward.
/// \throws Invalid_input when x.size() != ref.size().
/// Complexity: O(n^2) exact operations.
template <class S>
Linear_solution_errors measure_solution(const Linear_reference& ref, const Dense_vector<S>& x) {
  const Eigen::Index n = ref.size();
  if (x.size() != n)
    throw Invalid_input("measure_solution: the solution has " + std::to_string(x.size()) +
                        " entries for a system of size " + std::to_string(n));
  Linear_solution_errors e;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!is_finite_number(x(i))) {
      const double inf = std::numeric_limits<double>::infinity();
      e.finite = false;
      e.normwise_backward_error = e.componentwise_backward_error = e.residual_norm = inf;
      if (ref.solution()) e.forward_error = inf;
      return e;
    }
  const Dense_vector<mpq_class> xq = to_rational_vector(x);
  mpq_class norm_x = 0;
  for (Eigen::Index i = 0; i < n; ++i)
    if (abs(xq(i)) > norm_x) norm_x = abs(xq(i));

  std::vector<Dyadic> xd;
  const bool dyadic = ref.dyadic() && internal::dyadic_entries(xq, xd);

  mpq_class norm_r = 0, worst_component = 0;  // worst |r_i| / s_i as a rational
  bool component_infinite = false;
  mpz_class acc, acc_abs, t;
  for (Eigen::Index i = 0; i < n; ++i) {
    mpq_class r, s;
    if (dyadic) {
      long emin = LONG_MAX;
      const Dyadic& bi = ref.b_dyadic(i);
      if (sgn(bi.mantissa) != 0) emin = bi.exponent;
      for (Eigen::Index j = 0; j < n; ++j) {
        const Dyadic& aij = ref.a_dyadic(i, j);
        const Dyadic& xj = xd[static_cast<std::size_t>(j)];
        if (sgn(aij.mantissa) != 0 && sgn(xj.mantissa) != 0) emin = std::min(emin, aij.exponent + xj.exponent);
      }
      if (emin == LONG_MAX) {  // b_i = 0 and every product 0
        r = 0, s = 0;
      } else {
        acc = 0, acc_abs = 0;
        for (Eigen::Index j = 0; j < n; ++j) {
          const Dyadic& aij = ref.a_dyadic(i, j);
          const Dyadic& xj = xd[static_cast<std::size_t>(j)];
          if (sgn(aij.mantissa) == 0 || sgn(xj.mantissa) == 0) continue;
          mpz_mul(t.get_mpz_t(), aij.mantissa.get_mpz_t(), xj.mantissa.get_mpz_t());
          mpz_mul_2exp(t.get_mpz_t(), t.get_mpz_t(), static_cast<mp_bitcnt_t>(aij.exponent + xj.exponent - emin));
          acc -= t;
          if (sgn(t) < 0) acc_abs -= t;
          else acc_abs += t;
        }
        if (sgn(bi.mantissa) != 0) {
          mpz_mul_2exp(t.get_mpz_t(), bi.mantissa.get_mpz_t(), static_cast<mp_bitcnt_t>(bi.exponent - emin));
          acc += t;
          if (sgn(t) < 0) acc_abs -= t;
          else acc_abs += t;
        }
        r = to_rational(acc, emin);
        s = to_rational(acc_abs, emin);
      }
    } else {
      r = ref.b()(i);
      s = abs(ref.b()(i));
      for (Eigen::Index j = 0; j < n; ++j) {
        const mpq_class p = ref.a()(i, j) * xq(j);
        r -= p;
        s += abs(p);
      }
    }
    const mpq_class ar = abs(r);
    if (ar > norm_r) norm_r = ar;
    if (sgn(ar) != 0) {
      if (sgn(s) == 0) component_infinite = true;
      else if (const mpq_class q = ar / s; q > worst_component) worst_component = q;
    }
  }
  e.residual_norm = round_rational<double>(norm_r, Rounding::upward);
  e.normwise_backward_error = internal::measure_ratio(norm_r, ref.norm_a() * norm_x + ref.norm_b());
  e.componentwise_backward_error = component_infinite ? std::numeric_limits<double>::infinity()
                                                      : round_rational<double>(worst_component, Rounding::upward);
  if (ref.solution()) {
    const Dense_vector<mpq_class>& xs = *ref.solution();
    mpq_class num = 0, den = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const mpq_class d = abs(xq(i) - xs(i));
      if (d > num) num = d;
      if (abs(xs(i)) > den) den = abs(xs(i));
    }
    e.forward_error = internal::measure_ratio(num, den);
  }
  return e;
}

}  // namespace relgeo
