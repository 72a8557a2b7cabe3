// Fuzz harness: solve_linear_system (relgeo/linear.h) on arbitrary small
// systems in every scalar and with every solver, and the exact measures of
// the solutions.
//
// Input: byte 0 the size n (1..6), byte 1 the scalar (float, double, long
// double, MPFR at 24, 53 and 113 bits, GMP rationals), byte 2 the solver,
// then the n x n entries of A by rows and the n entries of b (fuzz_support.h
// coordinates: raw bits, specials, near-grid values).
//
// Contract (doc/reliability.md, harness linear):
//  * a solution or a relgeo::Error, nothing else; NaN or infinite entries
//    (after rounding to the scalar) end in Non_finite_input;
//  * rationals: a solution solves A x = b exactly; Singular_matrix says
//    "exactly singular" only when det A = 0, and with pivoting (relgeo's
//    partial and complete, Eigen's) det A = 0 always ends in Singular_matrix;
//  * the exact reference (Linear_reference) is refused as singular exactly
//    when det A = 0, and its measures of any solution are a normwise backward
//    error in [0, 1] (0 for the exact solution), finite exactly when the
//    solution is.
// det A is computed here independently (Gaussian elimination in GMP rationals).
#include <gmpxx.h>

#include <cmath>
#include <optional>

#include "fuzz_support.h"
#include "relgeo/linear.h"

namespace {

using namespace relgeo;
using namespace relgeo::fuzz;

bool determinant_is_zero(Dense_matrix<mpq_class> a) {
  const Eigen::Index n = a.rows();
  for (Eigen::Index k = 0; k < n; ++k) {
    Eigen::Index p = k;
    while (p < n && sgn(a(p, k)) == 0) ++p;
    if (p == n) return true;
    a.row(k).swap(a.row(p));
    for (Eigen::Index i = k + 1; i < n; ++i) {
      const mpq_class f = a(i, k) / a(k, k);
      for (Eigen::Index j = k; j < n; ++j) a(i, j) -= f * a(k, j);
    }
  }
  return false;
}

template <class S>
S from_double(double v) {
  if constexpr (std::is_same_v<S, mpq_class>) return mpq_class(v);
  else return S(v);
}

template <class S>
void check(const Dense_matrix<double>& ad, const Dense_vector<double>& bd, Linear_solver method,
           const std::optional<Linear_reference>& reference, bool input_finite, bool singular) {
  const Eigen::Index n = ad.rows();
  Dense_matrix<S> a(n, n);
  Dense_vector<S> b(n);
  bool finite = true;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!std::isfinite(ad(i, j))) continue;
      a(i, j) = from_double<S>(ad(i, j));
      finite = finite && is_finite_number(a(i, j));
    }
    if (std::isfinite(bd(i))) {
      b(i) = from_double<S>(bd(i));
      finite = finite && is_finite_number(b(i));
    }
  }
  if (!input_finite) {  // rationals cannot hold NaN: the double entries go through the double path below
    if constexpr (std::is_same_v<S, mpq_class>) return;
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index j = 0; j < n; ++j)
        if (!std::isfinite(ad(i, j))) a(i, j) = S(ad(i, j));
      if (!std::isfinite(bd(i))) b(i) = S(bd(i));
    }
    finite = false;
  }
  const std::string who = Number_traits<S>::name() + " " + std::string(to_string(method));
  Dense_vector<S> x;
  try {
    x = solve_linear_system<S>(a, b, method);
  } catch (const Non_finite_input&) {
    require(!finite, who + ": Non_finite_input for finite input");
    return;
  } catch (const Singular_matrix& e) {
    require(finite, who + ": non-finite input must be refused as such, not as singular");
    if (e.exactly_singular()) require(singular, who + ": 'exactly singular' for a nonsingular matrix");
    return;
  } catch (const relgeo::Error& e) {
    require(finite, who + ": non-finite input must be refused with Non_finite_input");
    // Eigen::FullPivLU is not offered for MPFR scalars: the only other refusal.
    require(method == Linear_solver::eigen_full_piv_lu && Number_traits<S>::kind == Number_kind::mpfr,
            who + ": unexpected error " + e.what());
    return;
  } catch (const std::exception& e) {
    require(false, who + ": untyped exception " + e.what());
  }
  require(finite, who + ": non-finite input was solved");
  require(x.size() == n, who + ": a solution of size n");
  if constexpr (std::is_same_v<S, mpq_class>) {
    require(!singular, who + ": a singular system was solved");
    for (Eigen::Index i = 0; i < n; ++i) {
      mpq_class r = b(i);
      for (Eigen::Index j = 0; j < n; ++j) r -= a(i, j) * x(j);
      require(sgn(r) == 0, who + ": A x = b exactly");
    }
  }
  if (reference) {
    Linear_solution_errors e;
    require(typed_errors_only([&] { e = measure_solution(*reference, x); }, "measure_solution"),
            who + ": measure_solution refused a solution of the right size");
    bool x_finite = true;
    for (Eigen::Index i = 0; i < n; ++i) x_finite = x_finite && is_finite_number(x(i));
    require(e.finite == x_finite, who + ": the measures say whether the solution is finite");
    if (x_finite) {
      require(e.normwise_backward_error >= 0 && e.normwise_backward_error <= 1,
              who + ": normwise backward error in [0, 1]");
      require(e.componentwise_backward_error >= 0, who + ": componentwise backward error >= 0");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  const Eigen::Index n = 1 + in.byte() % 6;
  const int scalar = in.byte() % 7;
  const Linear_solver method = all_linear_solvers[in.byte() % 5];
  Dense_matrix<double> a(n, n);
  Dense_vector<double> b(n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) a(i, j) = in.coordinate();
  for (Eigen::Index i = 0; i < n; ++i) b(i) = in.coordinate();
  bool finite = true;
  for (Eigen::Index i = 0; i < n; ++i) {
    finite = finite && std::isfinite(b(i));
    for (Eigen::Index j = 0; j < n; ++j) finite = finite && std::isfinite(a(i, j));
  }

  // The exact data of the double system (the scalars round it: float may
  // make it singular or overflow; the reference measures against the doubles).
  bool singular = false;
  std::optional<Linear_reference> reference;
  if (finite) {
    Dense_matrix<mpq_class> q(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) q(i, j) = mpq_class(a(i, j));
    singular = determinant_is_zero(q);
    try {
      reference.emplace(a, b);
      require(!singular, "Linear_reference accepted a singular matrix");
    } catch (const Singular_matrix& e) {
      require(singular && e.exactly_singular(), "Linear_reference refused a nonsingular matrix");
    } catch (const std::exception& e) {
      require(false, std::string("Linear_reference: unexpected ") + e.what());
    }
    if (reference) {
      const auto e = measure_solution(*reference, *reference->solution());
      require(e.finite && e.normwise_backward_error == 0 && e.componentwise_backward_error == 0,
              "the exact solution has backward error 0");
    }
  } else {
    bool refused = false;
    try {
      reference.emplace(a, b);
    } catch (const Non_finite_input&) {
      refused = true;
    } catch (const std::exception& e) {
      require(false, std::string("Linear_reference on non-finite input: ") + e.what());
    }
    require(refused, "Linear_reference refuses non-finite input");
    reference.reset();
  }
  // Scalars that hold every double exactly get the reference and det A;
  // float and 24-bit MPFR round A, so only the typed-error contract applies.
  switch (scalar) {
    case 0: check<float>(a, b, method, std::nullopt, finite, false); break;  // rounding to float changes A
    case 1: check<double>(a, b, method, reference, finite, singular); break;
    case 2: check<long double>(a, b, method, reference, finite, singular); break;
    case 3: check<Mpfr_number<24>>(a, b, method, std::nullopt, finite, false); break;
    case 4: check<Mpfr_number<53>>(a, b, method, reference, finite, singular); break;
    case 5: check<Mpfr_number<113>>(a, b, method, reference, finite, singular); break;
    default: check<mpq_class>(a, b, method, reference, finite, singular);
  }
  return 0;
}
