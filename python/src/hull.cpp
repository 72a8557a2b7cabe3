// python/src/hull.cpp — convex_hull through the tool's hull facade
// (tools/relgeo/commands/hull/facade.h): the hull, the backward-error
// certificate and E of eq. (3.2), as the record of `relgeo hull --format
// json` (commands/hull/report.h).
#include <string>
#include <vector>

#include "bindings.h"
#include "commands/hull/facade.h"
#include "commands/hull/report.h"
#include "json_to_python.h"
#include "kernels/registry.h"
#include "numpy_arrays.h"

namespace relgeo::python {

namespace {

/// The tool's JSON record, with numpy arrays for the hull.
py::dict hull_dict(const std::string& algorithm, const tool::Kernel_entry& kernel,
                   const std::vector<Point_2<double>>& input, const tool::Hull_evaluation& e) {
  auto d = json_to_python(tool::hull_report_json(algorithm, kernel, input, e, /*with_hull=*/false)).cast<py::dict>();
  const std::vector<std::size_t>& indices = e.run.indices;
  std::vector<double> hull;
  for (std::size_t i : indices) hull.insert(hull.end(), {input[i].x, input[i].y});
  d["hull_indices"] = vector_array<std::int64_t>(indices);
  d["hull"] = matrix_array<double>(hull, indices.size(), 2);
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
