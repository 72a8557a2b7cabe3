// python/src/linear.cpp — solve(A, b) through the tool's linsolve facade
// (tools/relgeo/commands/linsolve/facade.h): the solution and its backward
// errors measured exactly against the problem's data, as `relgeo linsolve`
// reports them.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "commands/linsolve/facade.h"
#include "numpy_arrays.h"
#include "relgeo/core/number_traits.h"

namespace relgeo::python {

namespace {

Dense_matrix<double> dense_matrix(const Double_array& a) {
  if (a.ndim() != 2) throw py::value_error("solve: A must be a 2-d array");
  const auto u = a.unchecked<2>();
  Dense_matrix<double> m(u.shape(0), u.shape(1));
  for (py::ssize_t i = 0; i < u.shape(0); ++i)
    for (py::ssize_t j = 0; j < u.shape(1); ++j) m(i, j) = u(i, j);
  return m;
}

Dense_vector<double> dense_vector(const Double_array& b) {
  if (b.ndim() != 1) throw py::value_error("solve: b must be a 1-d array");
  const auto u = b.unchecked<1>();
  Dense_vector<double> v(u.shape(0));
  for (py::ssize_t i = 0; i < u.shape(0); ++i) v(i) = u(i);
  return v;
}

py::object measure_or_none(bool solved, double v) { return solved ? py::cast(v) : py::none(); }

/// The fields of `relgeo linsolve --format json` (floats, inf as inf).
py::dict solve_dict(const tool::Linear_run& run, const std::string& failure, const Linear_reference& ref) {
  const bool solved = failure.empty();
  const double kappa = ref.condition().value;
  // The classical first-order bound ||x~ - x|| / ||x|| <= 2 kappa eta / (1 - kappa eta), kappa eta < 1.
  const double kappa_eta = kappa * run.errors.normwise_backward_error;
  py::dict d;
  d["status"] = solved ? "ok" : "failed";
  d["failure"] = failure;
  d["n"] = ref.size();
  d["method"] = run.method;
  d["scalar"] = run.scalar;
  d["x"] = solved ? py::object(vector_array<double>(run.x)) : py::none();
  d["normwise_backward_error"] = measure_or_none(solved, run.errors.normwise_backward_error);
  d["componentwise_backward_error"] = measure_or_none(solved, run.errors.componentwise_backward_error);
  d["forward_error"] = solved && run.errors.forward_error ? py::cast(*run.errors.forward_error) : py::none();
  d["condition_number"] = kappa;
  d["condition_number_exact"] = ref.condition().exact;
  d["forward_error_bound"] = solved && kappa_eta < 1 ? py::cast(2 * kappa_eta / (1 - kappa_eta)) : py::none();
  d["growth_factor"] = solved && run.growth_factor ? py::cast(*run.growth_factor) : py::none();
  d["residual_norm"] = measure_or_none(solved, run.errors.residual_norm);
  if (ref.solution()) {
    std::vector<double> exact;
    for (Eigen::Index i = 0; i < ref.size(); ++i) exact.push_back(nearest_double((*ref.solution())(i)));
    d["exact_solution"] = vector_array<double>(exact);
  } else {
    d["exact_solution"] = py::none();
  }
  d["time_s"] = measure_or_none(solved, run.time_s);
  return d;
}

}  // namespace

void bind_linear(py::module_& m) {
  m.def(
      "solve",
      [](const Double_array& a, const Double_array& b, const std::string& method, const std::string& scalar,
         int exact_limit) {
        tool::validate_linear_combination(method, scalar);
        if (exact_limit < 0) throw py::value_error("solve: exact_limit must be >= 0");
        const Dense_matrix<double> am = dense_matrix(a);
        const Dense_vector<double> bv = dense_vector(b);
        const auto limit = static_cast<std::size_t>(exact_limit);
        std::optional<Linear_reference> ref;
        tool::Linear_run run;
        run.method = method, run.scalar = scalar;  // reported when the solve fails
        std::string failure;
        {
          py::gil_scoped_release release;
          // Throws Singular_matrix (exactly singular: bad input) before any solve.
          ref.emplace(am, bv,
                      Linear_reference_options{.exact_solution_limit = limit,
                                               .exact_condition_limit = std::min<std::size_t>(limit, 40)});
          try {
            run = tool::run_linear_solver(method, scalar, *ref);
          } catch (const Singular_matrix& e) {
            if (e.exactly_singular()) throw;
            failure = e.what();  // a zero pivot of the elimination, not of A: the method failed
          }
        }
        if (failure.empty() && !run.errors.finite) failure = "the solution has a NaN or infinite entry (overflow)";
        return solve_dict(run, failure, *ref);
      },
      py::arg("A"), py::arg("b"), py::arg("method"), py::arg("scalar"), py::arg("exact_limit"),
      "The tool's `linsolve` on A x = b: x rounded to double, both backward errors, the forward error, the "
      "condition number, growth factor (a dict; status 'failed' with the reason when the method fails).");
}

}  // namespace relgeo::python
