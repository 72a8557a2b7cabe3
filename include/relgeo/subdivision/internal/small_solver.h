// relgeo/subdivision/internal/small_solver.h — Gaussian elimination for the
// small dense systems of exact limit positions (darts), in any number type.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/errors.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/subdivision/number_traits.h"

namespace relgeo::internal {

/// |x| as a double, for pivot choice (an interval's largest magnitude).
template <class FT>
double magnitude(const FT& x) {
  if constexpr (is_interval_v<FT>) return std::max(std::abs(lower_double(x)), std::abs(upper_double(x)));
  else return std::abs(nearest_double(x));
}

/// Solves the m x m system A x = b (row-major) by Gaussian elimination with
/// partial pivoting, divisions through Loop_number_traits<FT>::quotient.
/// \throws Error (computation_failure) when a pivot is not certainly nonzero.
template <class FT>
std::vector<FT> solve_small_system(std::vector<FT> A, std::vector<FT> b) {
  using Tr = Loop_number_traits<FT>;
  const std::size_t m = b.size();
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < m; ++r)
      if (magnitude(A[r * m + c]) > magnitude(A[piv * m + c])) piv = r;
    const Certified_sign pivot_sign = certified_sign(A[piv * m + c]);
    if (certainly(pivot_sign, Certified_sign::zero) || !is_certain(pivot_sign))
      throw Error(Error_code::computation_failure, "limit position: singular eigen-system");
    if (piv != c) {
      for (std::size_t k = 0; k < m; ++k) std::swap(A[c * m + k], A[piv * m + k]);
      std::swap(b[c], b[piv]);
    }
    for (std::size_t r = c + 1; r < m; ++r) {
      if (certainly(certified_sign(A[r * m + c]), Certified_sign::zero)) continue;  // nothing to eliminate
      const FT f = Tr::quotient(A[r * m + c], A[c * m + c]);
      for (std::size_t k = c; k < m; ++k) A[r * m + k] = FT(A[r * m + k] - FT(f * A[c * m + k]));
      b[r] = FT(b[r] - FT(f * b[c]));
    }
  }
  std::vector<FT> x(m);
  for (std::size_t r = m; r-- > 0;) {
    FT s = b[r];
    for (std::size_t k = r + 1; k < m; ++k) s = FT(s - FT(A[r * m + k] * x[k]));
    x[r] = Tr::quotient(s, A[r * m + r]);
  }
  return x;
}

}  // namespace relgeo::internal
