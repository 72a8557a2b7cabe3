// python/src/hull.cpp — convex_hull through the tool's hull facade
// (tools/relgeo/commands/hull/facade.h): the hull, the backward-error
// certificate and E of eq. (3.2), the fields of `relgeo hull --format json`.
#include <string>
#include <vector>

#include "bindings.h"
#include "commands/hull/facade.h"
#include "kernels/registry.h"
#include "numpy_arrays.h"

namespace relgeo::python {

namespace {

py::object optional_value(const auto& v) { return v ? py::cast(*v) : py::none(); }

py::dict hull_dict(const std::string& algorithm, const tool::Kernel_entry& kernel,
                   const std::vector<Point_2<double>>& input, const tool::Hull_evaluation& e) {
  const tool::Hull_run& r = e.run;
  std::vector<double> hull;
  for (std::size_t i : r.indices) hull.insert(hull.end(), {input[i].x, input[i].y});
  py::dict d;
  d["algorithm"] = algorithm;
  d["kernel"] = kernel.label();
  d["kernel_model"] = kernel.name;
  d["certified"] = kernel.certified;
  d["n"] = input.size();
  d["status"] = r.status == Hull_status::ok ? "ok" : "failed";
  d["failure"] = r.status == Hull_status::ok ? py::none() : py::cast(r.failure);
  d["hull_size"] = r.indices.size();
  d["hull_indices"] = vector_array<std::int64_t>(r.indices);
  d["hull"] = matrix_array<double>(hull, r.indices.size(), 2);
  d["convex"] = e.error.convex;
  d["error"] = e.error.value;
  d["backward_error"] = e.backward.value;
  d["backward_error_bound"] = optional_value(r.backward_error_bound);
  d["coordinate_bound"] = e.error.coordinate_bound;
  d["moved_points"] = e.backward.moved_points.size();
  d["worst_point"] = optional_value(e.backward.worst_point);
  d["uncertain_answers"] = r.uncertain_answers;
  d["predicate_calls"] = r.predicate_calls_counted ? py::cast(r.predicate_calls) : py::none();
  d["time_s"] = r.time_s;
  return d;
}

}  // namespace

void bind_hull(py::module_& m) {
  m.def(
      "convex_hull",
      [](const Double_array& points, const std::string& algorithm, const std::string& kernel) {
        const std::size_t n = require_rows(points, 2, "convex_hull: points");
        tool::validate_hull_combination(algorithm, kernel);
        const Coordinate_rows rows = coordinate_rows(points);
        std::vector<Point_2<double>> input(n);
        for (std::size_t i = 0; i < n; ++i) input[i] = {rows(i, 0), rows(i, 1)};
        tool::Hull_evaluation e;
        {
          py::gil_scoped_release release;
          e = tool::evaluate_hull(algorithm, kernel, input);
        }
        return hull_dict(algorithm, tool::find_kernel(kernel), input, e);
      },
      py::arg("points"), py::arg("algorithm"), py::arg("kernel"),
      "The tool's `hull` on an (n, 2) array: a dict of the hull (hull_indices, hull), status, E of eq. 3.2 "
      "(error), the backward-error certificate (backward_error, moved_points, worst_point) and counts.");
}

}  // namespace relgeo::python
