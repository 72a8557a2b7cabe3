// python/src/extrusion.cpp — check_extrusion through the tool's extrusion
// facade (tools/relgeo/commands/extrusion/facade.h): the certified
// well-formedness of an extruded object (thesis Sec. 3.4.1) from a contour
// JSON, as the record of `relgeo extrusion --format json`.
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.h"
#include "commands/extrusion/facade.h"
#include "commands/extrusion/report.h"
#include "commands/hull/facade.h"
#include "json_to_python.h"
#include "kernels/registry.h"
#include "relgeo/io/contour_json.h"

namespace relgeo::python {

void bind_extrusion(py::module_& m) {
  m.def(
      "check_extrusion",
      [](const std::string& source, const std::optional<std::string>& text, const std::string& algorithm,
         const std::string& kernel, std::optional<double> uncertainty, std::optional<double> absolute_uncertainty,
         bool prune, int max_listed) {
        tool::validate_hull_combination(algorithm, kernel);
        if (max_listed < 0) throw py::value_error("check_extrusion: max_listed must be >= 0");
        const io::Contour_overrides overrides{uncertainty, absolute_uncertainty};
        const io::Contour_input input =
            text ? io::parse_contour_json(*text, source, overrides) : io::read_contour_json(source, overrides);
        const Extrusion_options options =
            tool::extrusion_options_for(input, prune, static_cast<std::size_t>(max_listed));
        Extrusion_report report;
        double time_s = 0;
        {
          py::gil_scoped_release release;
          report = tool::run_extrusion(algorithm, kernel, *input.contour, options, &time_s);
        }
        return json_to_python(
            tool::extrusion_report_json(input, tool::find_kernel(kernel).label(), algorithm, options, report, time_s));
      },
      py::arg("source"), py::arg("text"), py::arg("algorithm"), py::arg("kernel"), py::arg("uncertainty"),
      py::arg("absolute_uncertainty"), py::arg("prune"), py::arg("max_listed"),
      "The tool's `extrusion` on a contour JSON (the file `source`, or `text` named `source`): the record of "
      "`relgeo extrusion --format json`.");
}

}  // namespace relgeo::python
