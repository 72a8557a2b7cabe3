// relgeo/linear/gaussian_elimination.h — Gaussian elimination without
// pivoting, with partial and with complete ("total") pivoting, in any
// Linear_scalar (relgeo/linear/scalar_traits.h; thesis Sec. 3.2).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/linear/scalar_traits.h"

namespace relgeo {

namespace internal {
/// v == 0 exactly (a scalar of the linear area is never an interval).
template <class S>
bool is_zero(const S& v) {
  return certainly(certified_sign(v), Certified_sign::zero);
}
}  // namespace internal

/// A dense matrix and vector of scalar S (Eigen, column-major).
template <class S>
using Dense_matrix = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
template <class S>
using Dense_vector = Eigen::Matrix<S, Eigen::Dynamic, 1>;

/// The pivoting strategy of Gaussian elimination.
enum class Pivoting {
  none,      ///< pivot a(k,k) as it comes: unstable (the thesis' example)
  partial,   ///< largest |a(i,k)|, i >= k, swapped into row k (LAPACK's getrf)
  complete   ///< largest |a(i,j)|, i, j >= k, swapped into (k,k): "total" pivoting
};

constexpr std::string_view to_string(Pivoting p) noexcept {
  switch (p) {
    case Pivoting::none: return "none";
    case Pivoting::partial: return "partial";
    case Pivoting::complete: return "complete";
  }
  return "?";
}

/// \brief A zero pivot: elimination cannot continue.
///
/// `exactly_singular()` is true when this proves the matrix singular: the
/// scalar is exact (mpq_class) and the strategy pivots (with partial pivoting
/// a zero column below the diagonal, with complete pivoting a zero trailing
/// block, both exact). Then the code is Error_code::invalid_input (bad
/// input). Otherwise — a zero pivot without pivoting (the matrix may well be
/// nonsingular: [[0,1],[1,0]]), or in a rounding scalar, where a zero pivot
/// only says that the *computed* trailing block vanished — the code is
/// Error_code::computation_failure.
class Singular_matrix : public Error {
 public:
  Singular_matrix(const std::string& what, std::size_t step, bool exactly_singular)
      : Error(exactly_singular ? Error_code::invalid_input : Error_code::computation_failure, what),
        step_(step), exactly_singular_(exactly_singular) {}
  /// 0-based elimination step whose pivot was zero (the rank, when exactly singular).
  std::size_t step() const noexcept { return step_; }
  bool exactly_singular() const noexcept { return exactly_singular_; }

 private:
  std::size_t step_;
  bool exactly_singular_;
};

/// The factorization P A Q = L U of Gaussian elimination.
template <class S>
struct Lu_decomposition {
  /// L strictly below the diagonal (unit diagonal implied), U on and above.
  Dense_matrix<S> lu;
  /// Row k of PAQ is row row_order[k] of A; column k is column column_order[k]
  /// (the identity without the corresponding pivoting).
  std::vector<Eigen::Index> row_order, column_order;
  Pivoting pivoting = Pivoting::partial;
  /// max |u_ij| / max |a_ij| (in double): the growth of the elements, a cheap
  /// lower bound of Wilkinson's growth factor (which maximises over every
  /// intermediate matrix); it enters the backward-error bound
  /// |dA| <= ~2 n u rho |A| of Gaussian elimination (Higham, Thm. 9.5).
  double growth_factor = 1;

  Eigen::Index size() const { return lu.rows(); }

  /// Solves A x = b with the factors: forward then back substitution, in S.
  /// \throws Invalid_input when b.size() != size().
  Dense_vector<S> solve(const Dense_vector<S>& b) const;
};

namespace internal {

/// The input checks of the area's entry points, each naming `who`:
/// Invalid_input unless `a` is square, unless it is not empty (code
/// empty_input), unless the right-hand side has a.rows() entries;
/// Non_finite_input naming the first NaN or infinite entry.
template <class Matrix>
void require_square(const Matrix& a, const char* who) {
  if (a.rows() != a.cols())
    throw Invalid_input(std::string(who) + ": the matrix is " + std::to_string(a.rows()) + " x " +
                        std::to_string(a.cols()) + ", not square");
}
template <class Matrix>
void require_not_empty(const Matrix& a, const char* who) {
  if (a.rows() == 0) throw Invalid_input(std::string(who) + ": empty matrix", Error_code::empty_input);
}
template <class Matrix, class Vector>
void require_rhs_rows(const Matrix& a, const Vector& b, const char* who) {
  if (b.size() != a.rows())
    throw Invalid_input(std::string(who) + ": the matrix has " + std::to_string(a.rows()) +
                        " rows but the right-hand side has " + std::to_string(b.size()) + " entries");
}
template <class S>
void require_finite_rhs(const Dense_vector<S>& b, const char* who) {
  for (Eigen::Index i = 0; i < b.size(); ++i)
    if (!is_finite_number(b(i)))
      throw Non_finite_input(std::string(who) + ": right-hand side entry " + std::to_string(i) +
                             " is NaN or infinite");
}
template <class S>
void require_finite_entries(const Dense_matrix<S>& a, const char* who) {
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      if (!is_finite_number(a(i, j)))
        throw Non_finite_input(std::string(who) + ": entry (" + std::to_string(i) + ", " +
                               std::to_string(j) + ") is NaN or infinite");
}

/// |v| compared without rounding: a < b on magnitudes.
template <class S>
bool magnitude_less(const S& a, const S& b) {
  if constexpr (Number_traits<S>::kind == Number_kind::rational)
    return mpz_cmpabs_ui(a.get_num_mpz_t(), 0) == 0 ? sgn(b) != 0 : abs(a) < abs(b);
  else if constexpr (Number_traits<S>::kind == Number_kind::mpfr) return mpfr_cmpabs(a.get(), b.get()) < 0;
  else return std::abs(a) < std::abs(b);
}

/// max |a(i,j)| over the entries on and above the diagonal (`upper`) or over
/// all, as the nearest double: the largest entry is found by exact
/// comparisons and rounded once (rounding is monotone, so this is the largest
/// of the rounded magnitudes).
template <class S>
double largest_magnitude(const Dense_matrix<S>& a, bool upper) {
  const S* best = nullptr;
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < (upper ? std::min(j + 1, a.rows()) : a.rows()); ++i)
      if (!best || magnitude_less(*best, a(i, j))) best = &a(i, j);
  return best ? std::abs(nearest_double(*best)) : 0.0;
}

}  // namespace internal

/// \brief Gaussian elimination of the square matrix `a`: P A Q = L U.
///
/// Right-looking, column-oriented (the inner loop runs down a column of
/// Eigen's column-major storage): at step k the multipliers
/// l(i,k) = a(i,k) / a(k,k) are stored in place and a(i,j) -= l(i,k) * a(k,j)
/// for i, j > k. Each operation rounds once in S (relgeo builds with
/// -ffp-contract=off, so no fused multiply-add changes the rounding): without
/// pivoting on the thesis' 2x2 example this reproduces the thesis' program
/// bit for bit.
///
/// Pivot choice: `none` takes a(k,k); `partial` the first largest |a(i,k)|,
/// i >= k; `complete` the first largest |a(i,j)|, i, j >= k, in column-major
/// order. Magnitudes are compared exactly.
///
/// \tparam S float, double, long double, Mpfr_number<Bits> or mpq_class.
/// \throws Invalid_input (not square, empty), Non_finite_input (NaN or
///   infinite entry), Singular_matrix (zero pivot; see there).
/// Complexity: 2n^3/3 flops; O(n^3) comparisons for complete pivoting.
template <class S>
Lu_decomposition<S> lu_decompose(Dense_matrix<S> a, Pivoting pivoting) {
  const Eigen::Index n = a.rows();
  internal::require_square(a, "Gaussian elimination");
  internal::require_not_empty(a, "Gaussian elimination");
  internal::require_finite_entries(a, "Gaussian elimination");

  Lu_decomposition<S> f;
  f.pivoting = pivoting;
  f.row_order.resize(static_cast<std::size_t>(n));
  f.column_order.resize(static_cast<std::size_t>(n));
  std::iota(f.row_order.begin(), f.row_order.end(), Eigen::Index{0});
  std::iota(f.column_order.begin(), f.column_order.end(), Eigen::Index{0});
  const double max_a = internal::largest_magnitude(a, false);

  // Complete pivoting: the search for step k+1 runs over the trailing block
  // while step k updates it, column by column in the same (column-major)
  // order as a separate search would, so the pivots are the same; the
  // column is still in cache.
  Eigen::Index next_r = -1, next_c = -1;
  for (Eigen::Index k = 0; k < n; ++k) {
    Eigen::Index pr = k, pc = k;
    if (pivoting == Pivoting::partial) {
      for (Eigen::Index i = k + 1; i < n; ++i)
        if (internal::magnitude_less(a(pr, k), a(i, k))) pr = i;
    } else if (pivoting == Pivoting::complete) {
      if (k == 0) {
        for (Eigen::Index j = k; j < n; ++j)
          for (Eigen::Index i = k; i < n; ++i)
            if (internal::magnitude_less(a(pr, pc), a(i, j))) pr = i, pc = j;
      } else {
        pr = next_r, pc = next_c;
      }
    }
    if (internal::is_zero(a(pr, pc))) {
      const bool exact = Number_traits<S>::is_exact && pivoting != Pivoting::none;
      std::string what = "Gaussian elimination (" +
                         std::string(pivoting == Pivoting::none ? "no" : to_string(pivoting)) + " pivoting, " +
                         Number_traits<S>::name() + "): zero pivot at step " +
                         std::to_string(k) + " of " + std::to_string(n);
      if (exact) what += ": the matrix is exactly singular (rank " + std::to_string(k) + ")";
      else if (pivoting == Pivoting::none) what += " (the matrix may be nonsingular: use pivoting)";
      else what += ": the matrix is singular to the working precision";
      throw Singular_matrix(what, static_cast<std::size_t>(k), exact);
    }
    if (pr != k) {
      a.row(k).swap(a.row(pr));
      std::swap(f.row_order[static_cast<std::size_t>(k)], f.row_order[static_cast<std::size_t>(pr)]);
    }
    if (pc != k) {
      a.col(k).swap(a.col(pc));
      std::swap(f.column_order[static_cast<std::size_t>(k)], f.column_order[static_cast<std::size_t>(pc)]);
    }
    const S pivot = a(k, k);
    for (Eigen::Index i = k + 1; i < n; ++i) a(i, k) = S(a(i, k) / pivot);
    const bool search = pivoting == Pivoting::complete && k + 1 < n;
    next_r = k + 1, next_c = k + 1;
    [[maybe_unused]] S best{};  // |a(next_r, next_c)| for floating-point S
    for (Eigen::Index j = k + 1; j < n; ++j) {
      const S akj = a(k, j);
      S* col = &a(0, j);
      const S* l = &a(0, k);
      bool skip = false;
      if constexpr (Number_traits<S>::is_exact) skip = internal::is_zero(akj);  // an exact no-op
      // (rounding scalars do the update anyway: inf * 0 = NaN must show)
      if (!skip)
        for (Eigen::Index i = k + 1; i < n; ++i) col[i] -= S(l[i] * akj);
      if (!search) continue;
      if constexpr (std::is_floating_point_v<S>) {
        if (j == k + 1) best = std::abs(col[k + 1]);
        for (Eigen::Index i = k + 1; i < n; ++i)
          if (best < std::abs(col[i])) best = std::abs(col[i]), next_r = i, next_c = j;
      } else {
        for (Eigen::Index i = k + 1; i < n; ++i)
          if (internal::magnitude_less(a(next_r, next_c), col[i])) next_r = i, next_c = j;
      }
    }
  }
  const double max_u = internal::largest_magnitude(a, true);
  f.growth_factor = max_a > 0 ? max_u / max_a : 1.0;
  f.lu = std::move(a);
  return f;
}

template <class S>
Dense_vector<S> Lu_decomposition<S>::solve(const Dense_vector<S>& b) const {
  const Eigen::Index n = size();
  if (b.size() != n)
    throw Invalid_input("Gaussian elimination: right-hand side of size " + std::to_string(b.size()) +
                        " for a " + std::to_string(n) + " x " + std::to_string(n) + " matrix");
  Dense_vector<S> y(n);
  for (Eigen::Index k = 0; k < n; ++k) y(k) = b(row_order[static_cast<std::size_t>(k)]);
  // Forward substitution with unit lower L (column-oriented, as the elimination
  // updates b in the thesis' program: b(i) -= l(i,k) * b(k)).
  for (Eigen::Index k = 0; k < n; ++k) {
    const S yk = y(k);
    if constexpr (Number_traits<S>::is_exact)
      if (internal::is_zero(yk)) continue;
    for (Eigen::Index i = k + 1; i < n; ++i) y(i) -= S(lu(i, k) * yk);
  }
  // Back substitution, row-oriented: z(k) = (y(k) - sum_{j>k} u(k,j) z(j)) / u(k,k).
  Dense_vector<S> z(n);
  for (Eigen::Index k = n - 1; k >= 0; --k) {
    S s = y(k);
    for (Eigen::Index j = k + 1; j < n; ++j) s -= S(lu(k, j) * z(j));
    z(k) = S(s / lu(k, k));
  }
  Dense_vector<S> x(n);
  for (Eigen::Index k = 0; k < n; ++k) x(column_order[static_cast<std::size_t>(k)]) = z(k);
  return x;
}

/// \brief Solves A x = b by Gaussian elimination with the given pivoting, in S.
/// \throws as lu_decompose; Invalid_input when b.size() != A.rows();
///   Non_finite_input for a NaN or infinite entry of b.
template <class S>
Dense_vector<S> gaussian_elimination(const Dense_matrix<S>& a, const Dense_vector<S>& b,
                                     Pivoting pivoting) {
  internal::require_rhs_rows(a, b, "Gaussian elimination");
  internal::require_finite_rhs(b, "Gaussian elimination");
  return lu_decompose<S>(a, pivoting).solve(b);
}

}  // namespace relgeo
