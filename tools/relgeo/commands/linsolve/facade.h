// tools/relgeo/commands/linsolve/facade.h — solving A x = b with a method
// and a scalar named at run time, measured against the problem's exact data.
// run_linear_solver instantiates every method under every scalar in
// dispatch.cpp only (the scalars are number types, not kernels: their list is
// there), so `linsolve` and the experiment's linear section compile without
// them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "relgeo/io/json.h"
#include "relgeo/linear/backward_error.h"

namespace relgeo::tool {

/// The methods of `relgeo linsolve --method`, in table order:
/// none, partial, complete, eigen-partial, eigen-full.
const std::vector<std::string>& linear_method_names();
/// One line per method, for the help text.
std::string linear_methods_help();

/// The precisions accepted in `--scalar mpfr-BITS`.
const std::vector<int>& linear_mpfr_bits();
/// The scalars of `--scalar`: float, double, long-double, mpfr-BITS (each
/// BITS of linear_mpfr_bits), rational.
const std::vector<std::string>& linear_scalar_names();
/// "float, double, long-double, mpfr-BITS (BITS in ...), rational".
std::string linear_scalars_summary();
/// Throws Usage_error unless `method` and `scalar` are known.
void validate_linear_combination(std::string_view method, std::string_view scalar);
/// u of the scalar (0 for rational).       [dispatch.cpp]
double scalar_unit_roundoff(std::string_view scalar);

/// What one solve produced.
struct Linear_run {
  std::string method, scalar;
  std::vector<double> x;  ///< the solution rounded to double (to nearest)
  Linear_solution_errors errors;
  /// max |u_ij| / max |a_ij| of relgeo's elimination (empty for the Eigen peers).
  std::optional<double> growth_factor;
  double time_s = 0;  ///< fastest timed solve (the data converted to the scalar before)
  std::size_t timed_runs = 0;
};

/// Solves the problem of `ref` (its exact data correctly rounded to `scalar`)
/// with `method`, repeating the timed solve until `min_seconds` have passed,
/// and measures the solution against `ref`.
/// \throws Usage_error for bad names or a combination Eigen cannot run
///   (eigen-full with mpfr-*); relgeo::Singular_matrix on a zero pivot.
///   [dispatch.cpp]
Linear_run run_linear_solver(std::string_view method, std::string_view scalar, const Linear_reference& ref,
                             double min_seconds = 0);

/// A solve as `relgeo linsolve` reports it: the run or why the method failed,
/// and what the reference adds.
struct Linear_outcome {
  Linear_run run;
  /// Empty when solved; else a zero pivot of the elimination (not of A: the
  /// method failed) or a NaN or infinite entry of x (overflow).
  std::string failure;
  Condition_number condition;
  /// 2 kappa eta / (1 - kappa eta), the first-order bound of the forward
  /// error: when solved and kappa eta < 1.
  std::optional<double> forward_error_bound;
  std::vector<double> exact_solution;  ///< rounded to double; empty when `ref` has none
  bool failed() const { return !failure.empty(); }
};

/// run_linear_solver once, its failure caught and the measures added.
/// 	hrows Singular_matrix when A is exactly singular (bad input), Usage_error
///   for bad names.                                          [facade.cpp]
Linear_outcome solve_linear_system(std::string_view method, std::string_view scalar, const Linear_reference& ref);

/// The record of `relgeo linsolve --format json` after `input`: n, method,
/// scalar, unit_roundoff, status, failure, x, the measures, exact_solution,
/// time_s.                                                   [facade.cpp]
io::Json linear_outcome_json(const Linear_outcome& outcome, const Linear_reference& ref);

}  // namespace relgeo::tool
