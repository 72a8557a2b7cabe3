// tools/relgeo/commands/linsolve/dispatch.cpp — every linear solver under every scalar
// (float, double, long double, MPFR at the precisions of linear_mpfr_bits,
// GMP rationals), behind the non-template entry points of facade.h.
#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "cli/text.h"
#include "commands/linsolve/facade.h"
#include "relgeo/linear.h"

namespace relgeo::tool {

namespace {

using Clock = std::chrono::steady_clock;

template <int... Bits>
struct Bit_list {};
using Mpfr_bits = Bit_list<11, 24, 32, 40, 48, 53, 64, 80, 96, 106, 113, 128, 160, 192, 256>;

template <class F, int B, int... Rest>
bool try_mpfr(std::string_view name, F& f, Bit_list<B, Rest...>, decltype(f(0.0))* out) {
  if (name == "mpfr-" + std::to_string(B)) {
    *out = f(Mpfr_number<B>{});
    return true;
  }
  if constexpr (sizeof...(Rest) > 0) return try_mpfr(name, f, Bit_list<Rest...>{}, out);
  return false;
}

/// Calls f(S{}) with the scalar type named `name`. \pre validated.
template <class F>
auto with_scalar(std::string_view name, F f) -> decltype(f(0.0)) {
  if (name == "float") return f(0.0f);
  if (name == "double") return f(0.0);
  if (name == "long-double") return f(0.0L);
  if (name == "rational") return f(mpq_class(0));
  decltype(f(0.0)) out{};
  if (try_mpfr(name, f, Mpfr_bits{}, &out)) return out;
  throw Usage_error("scalar '" + std::string(name) + "' is listed but not dispatched");
}

template <int... B>
std::vector<int> bits_of(Bit_list<B...>) {
  return {B...};
}

}  // namespace

const std::vector<int>& linear_mpfr_bits() {
  static const std::vector<int> bits = bits_of(Mpfr_bits{});
  return bits;
}

double scalar_unit_roundoff(std::string_view scalar) {
  validate_linear_combination("partial", scalar);
  return with_scalar(scalar, []<class S>(const S&) { return Number_traits<S>::unit_roundoff; });
}

Linear_run run_linear_solver(std::string_view method, std::string_view scalar, const Linear_reference& ref,
                             double min_seconds) {
  validate_linear_combination(method, scalar);
  const Linear_solver solver = linear_solver_from_string(method);
  return with_scalar(scalar, [&]<class S>(const S&) {
    if constexpr (!std::is_constructible_v<S, Eigen::Index>) {
      if (solver == Linear_solver::eigen_full_piv_lu)
        throw Usage_error("method eigen-full is not available for scalar " + std::string(scalar) +
                          " (Eigen::FullPivLU needs a constructor from Eigen::Index, which "
                          "relgeo::Mpfr_number lacks)");
    }
    const Dense_matrix<S> a = from_rational_matrix<S>(ref.a());
    const Dense_vector<S> b = from_rational_vector<S>(ref.b());
    Linear_run run;
    run.method = std::string(method);
    run.scalar = std::string(scalar);
    Dense_vector<S> x;
    const auto start = Clock::now();
    double best = -1;
    for (;;) {
      const auto t0 = Clock::now();
      if (solver == Linear_solver::ge_no_pivoting || solver == Linear_solver::ge_partial_pivoting ||
          solver == Linear_solver::ge_complete_pivoting) {
        const Pivoting p = solver == Linear_solver::ge_no_pivoting   ? Pivoting::none
                           : solver == Linear_solver::ge_partial_pivoting ? Pivoting::partial
                                                                         : Pivoting::complete;
        const Lu_decomposition<S> lu = lu_decompose<S>(a, p);
        x = lu.solve(b);
        run.growth_factor = lu.growth_factor;
      } else {
        x = solve_linear_system<S>(a, b, solver);
      }
      const auto t1 = Clock::now();
      ++run.timed_runs;
      const double t = std::chrono::duration<double>(t1 - t0).count();
      if (best < 0 || t < best) best = t;
      if (std::chrono::duration<double>(t1 - start).count() >= min_seconds) break;
    }
    run.time_s = best;
    run.errors = measure_solution(ref, x);
    run.x.reserve(static_cast<std::size_t>(x.size()));
    for (Eigen::Index i = 0; i < x.size(); ++i) run.x.push_back(nearest_double(x(i)));
    return run;
  });
}

}  // namespace relgeo::tool
