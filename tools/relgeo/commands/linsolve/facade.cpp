// tools/relgeo/commands/linsolve/facade.cpp — names and validation of the
// linear solvers and scalars, a solve with its measures and its JSON record
// (no instantiation: see dispatch.cpp).
#include "commands/linsolve/facade.h"

#include <algorithm>

#include "cli/text.h"
#include "relgeo/core/number_traits.h"

namespace relgeo::tool {

const std::vector<std::string>& linear_method_names() {
  static const std::vector<std::string> names = {"none", "partial", "complete", "eigen-partial", "eigen-full"};
  return names;
}

std::string linear_methods_help() {
  return "Methods (--method):\n"
         "  none           Gaussian elimination without pivoting (relgeo::gaussian_elimination):\n"
         "                 unstable, the thesis' example\n"
         "  partial        with partial pivoting (largest |a(i,k)| in the column; default)\n"
         "  complete       with complete ('total') pivoting (largest |a(i,j)| of the trailing block)\n"
         "  eigen-partial  Eigen::PartialPivLU (blocked; a peer)\n"
         "  eigen-full     Eigen::FullPivLU (a peer; not with mpfr-BITS)\n";
}

const std::vector<std::string>& linear_scalar_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = {"float", "double", "long-double"};
    for (int b : linear_mpfr_bits()) n.push_back("mpfr-" + std::to_string(b));
    n.push_back("rational");
    return n;
  }();
  return names;
}

std::string linear_scalars_summary() {
  std::string bits;
  for (int b : linear_mpfr_bits()) bits += (bits.empty() ? "" : ", ") + std::to_string(b);
  return "float, double, long-double, mpfr-BITS (BITS in " + bits + "), rational";
}

void validate_linear_combination(std::string_view method, std::string_view scalar) {
  const auto& m = linear_method_names();
  if (std::find(m.begin(), m.end(), method) == m.end())
    throw Usage_error("--method: unknown method '" + std::string(method) +
                      "'; methods: none, partial, complete, eigen-partial, eigen-full");
  const auto& s = linear_scalar_names();
  if (std::find(s.begin(), s.end(), scalar) == s.end())
    throw Usage_error("--scalar: unknown scalar '" + std::string(scalar) + "'; scalars: " +
                      linear_scalars_summary());
}

Linear_outcome solve_linear_system(std::string_view method, std::string_view scalar, const Linear_reference& ref) {
  Linear_outcome o;
  try {
    o.run = run_linear_solver(method, scalar, ref);
  } catch (const Singular_matrix& e) {
    if (e.exactly_singular()) throw;
    o.failure = e.what();
    o.run.method = method, o.run.scalar = scalar;
  }
  if (!o.failed() && !o.run.errors.finite) o.failure = "the solution has a NaN or infinite entry (overflow)";
  o.condition = ref.condition();
  if (!o.failed()) {
    const double ke = o.condition.value * o.run.errors.normwise_backward_error;
    if (ke < 1) o.forward_error_bound = 2 * ke / (1 - ke);
  }
  if (ref.solution())
    for (Eigen::Index i = 0; i < ref.size(); ++i) o.exact_solution.push_back(nearest_double((*ref.solution())(i)));
  return o;
}

namespace {

io::Json coordinates_json(const std::vector<double>& v) {
  io::Json x = io::Json::array();
  for (double e : v) x.push_back(io::json_coordinate(e));
  return x;
}

}  // namespace

io::Json linear_outcome_json(const Linear_outcome& outcome, const Linear_reference& ref) {
  using io::Json, io::json_measure;
  const Linear_run& run = outcome.run;
  const bool failed = outcome.failed();
  const auto m = [&](double v) { return failed ? Json(nullptr) : json_measure(v); };
  return Json{
      {"n", ref.size()},
      {"method", run.method},
      {"scalar", run.scalar},
      {"unit_roundoff", scalar_unit_roundoff(run.scalar)},
      {"status", failed ? "failed" : "ok"},
      {"failure", outcome.failure},
      {"x", failed ? Json(nullptr) : coordinates_json(run.x)},
      {"normwise_backward_error", m(run.errors.normwise_backward_error)},
      {"componentwise_backward_error", m(run.errors.componentwise_backward_error)},
      {"forward_error",
       (failed || !run.errors.forward_error) ? Json(nullptr) : json_measure(*run.errors.forward_error)},
      {"condition_number", json_measure(outcome.condition.value)},
      {"condition_number_exact", outcome.condition.exact},
      {"forward_error_bound", outcome.forward_error_bound ? Json(*outcome.forward_error_bound) : Json(nullptr)},
      {"growth_factor", (!failed && run.growth_factor) ? json_measure(*run.growth_factor) : Json(nullptr)},
      {"residual_norm", m(run.errors.residual_norm)},
      {"exact_solution", outcome.exact_solution.empty() ? Json(nullptr) : coordinates_json(outcome.exact_solution)},
      {"time_s", failed ? Json(nullptr) : Json(run.time_s)}};
}

}  // namespace relgeo::tool
