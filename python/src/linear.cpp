// python/src/linear.cpp — solve(A, b) through the tool's linsolve facade
// (tools/relgeo/commands/linsolve/facade.h): the solution and its backward
// errors measured exactly against the problem's data, as the record of
// `relgeo linsolve --format json`.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "commands/linsolve/facade.h"
#include "json_to_python.h"
#include "numpy_arrays.h"

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

/// The tool's JSON record, with numpy arrays for x and the exact solution.
py::dict solve_dict(const tool::Linear_outcome& outcome, const Linear_reference& ref) {
  auto d = json_to_python(tool::linear_outcome_json(outcome, ref)).cast<py::dict>();
  if (!outcome.failed()) d["x"] = vector_array<double>(outcome.run.x);
  if (!outcome.exact_solution.empty()) d["exact_solution"] = vector_array<double>(outcome.exact_solution);
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
        std::optional<tool::Linear_outcome> outcome;
        {
          py::gil_scoped_release release;
          // Throws Singular_matrix (exactly singular: bad input) before any solve.
          ref.emplace(am, bv,
                      Linear_reference_options{.exact_solution_limit = limit,
                                               .exact_condition_limit = std::min<std::size_t>(limit, 40)});
          outcome = tool::solve_linear_system(method, scalar, *ref);
        }
        return solve_dict(*outcome, *ref);
      },
      py::arg("A"), py::arg("b"), py::arg("method"), py::arg("scalar"), py::arg("exact_limit"),
      "The tool's `linsolve` on A x = b: x rounded to double, both backward errors, the forward error, the "
      "condition number, growth factor (a dict; status 'failed' with the reason when the method fails).");
}

}  // namespace relgeo::python
