// relgeo/linear/solvers.h — one entry point for every solver of A x = b that
// relgeo measures: its own Gaussian elimination variants and, as peers,
// Eigen's PartialPivLU and FullPivLU, in the same scalar.
#pragma once

#include <Eigen/LU>

#include <string>
#include <string_view>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/linear/gaussian_elimination.h"
#include "relgeo/linear/scalar_traits.h"

namespace relgeo {

/// A method of solving A x = b.
enum class Linear_solver {
  ge_no_pivoting,        ///< relgeo::gaussian_elimination, Pivoting::none
  ge_partial_pivoting,   ///< Pivoting::partial
  ge_complete_pivoting,  ///< Pivoting::complete
  eigen_partial_piv_lu,  ///< Eigen::PartialPivLU (blocked, partial pivoting): peer
  eigen_full_piv_lu      ///< Eigen::FullPivLU (complete pivoting): peer
};

/// Every method, in table order.
inline constexpr Linear_solver all_linear_solvers[] = {
    Linear_solver::ge_no_pivoting, Linear_solver::ge_partial_pivoting,
    Linear_solver::ge_complete_pivoting, Linear_solver::eigen_partial_piv_lu,
    Linear_solver::eigen_full_piv_lu};

/// Command-line style names: "none", "partial", "complete", "eigen-partial", "eigen-full".
constexpr std::string_view to_string(Linear_solver s) noexcept {
  switch (s) {
    case Linear_solver::ge_no_pivoting: return "none";
    case Linear_solver::ge_partial_pivoting: return "partial";
    case Linear_solver::ge_complete_pivoting: return "complete";
    case Linear_solver::eigen_partial_piv_lu: return "eigen-partial";
    case Linear_solver::eigen_full_piv_lu: return "eigen-full";
  }
  return "?";
}

/// The method named `name` (as to_string prints it); throws Invalid_input otherwise.
inline Linear_solver linear_solver_from_string(std::string_view name) {
  for (Linear_solver s : all_linear_solvers)
    if (to_string(s) == name) return s;
  throw Invalid_input("unknown linear solver '" + std::string(name) +
                      "'; solvers: none, partial, complete, eigen-partial, eigen-full");
}

namespace internal {

/// Eigen's factorizations do not report a zero pivot (they return inf/NaN, or
/// a least-squares-like answer for FullPivLU): relgeo checks U's diagonal for
/// an exact zero, so every solver reports singularity the same way.
template <class S, class Lu>
void require_nonzero_pivots(const Lu& lu, const char* who, bool pivoting_proves_rank) {
  const auto& m = lu.matrixLU();
  for (Eigen::Index k = 0; k < m.rows(); ++k)
    if (is_zero(m(k, k))) {
      const bool exact = Number_traits<S>::is_exact && pivoting_proves_rank;
      throw Singular_matrix(std::string(who) + " (" + Number_traits<S>::name() + "): zero pivot at step " +
                                std::to_string(k) + " of " + std::to_string(m.rows()) +
                                (exact ? ": the matrix is exactly singular"
                                       : ": the matrix is singular to the working precision"),
                            static_cast<std::size_t>(k), exact);
    }
}

}  // namespace internal

/// \brief x with A x = b by `method`, computed in S.
/// \throws Invalid_input (not square, sizes differ, empty), Non_finite_input,
///   Singular_matrix (zero pivot; for the Eigen peers an exact zero on U's
///   diagonal; FullPivLU's complete pivoting proves exact singularity for
///   mpq_class, PartialPivLU's too).
template <class S>
Dense_vector<S> solve_linear_system(const Dense_matrix<S>& a, const Dense_vector<S>& b,
                                    Linear_solver method) {
  switch (method) {
    case Linear_solver::ge_no_pivoting: return gaussian_elimination<S>(a, b, Pivoting::none);
    case Linear_solver::ge_partial_pivoting: return gaussian_elimination<S>(a, b, Pivoting::partial);
    case Linear_solver::ge_complete_pivoting: return gaussian_elimination<S>(a, b, Pivoting::complete);
    default: break;
  }
  // Same input checks as relgeo's own elimination.
  internal::require_square(a, "Eigen LU");
  internal::require_not_empty(a, "Eigen LU");
  internal::require_rhs_rows(a, b, "Eigen LU");
  internal::require_finite_entries(a, "Eigen LU");
  internal::require_finite_rhs(b, "Eigen LU");
  if (method == Linear_solver::eigen_partial_piv_lu) {
    const Eigen::PartialPivLU<Dense_matrix<S>> lu(a);
    internal::require_nonzero_pivots<S>(lu, "Eigen::PartialPivLU", true);
    return lu.solve(b);
  }
  if constexpr (std::is_constructible_v<S, Eigen::Index>) {
    const Eigen::FullPivLU<Dense_matrix<S>> lu(a);
    internal::require_nonzero_pivots<S>(lu, "Eigen::FullPivLU", true);
    return lu.solve(b);
  } else {
    // Eigen::FullPivLU builds RealScalar(Index); Mpfr_number's constructors
    // from int and double make that ambiguous.
    throw Invalid_input("Eigen::FullPivLU is not available for scalar " + Number_traits<S>::name() +
                        " (it needs a constructor from Eigen::Index)");
  }
}

}  // namespace relgeo
