// python/src/join.cpp — join(surface, meshes) through the tool's join facade
// (tools/relgeo/commands/join/facade.h): mesh patches, files or (V, F)
// arrays, joined to the trimmed faces of a surface model (thesis Ch. 4); the
// joined mesh and the record of `relgeo join --format json`.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "commands/join/facade.h"
#include "json_to_python.h"
#include "mesh_arrays.h"
#include "numpy_arrays.h"

namespace relgeo::python {

void bind_join(py::module_& m) {
  m.def(
      "join",
      [](const std::string& surface, const std::vector<std::string>& meshes,
         const std::vector<std::optional<std::pair<Double_array, Index_array>>>& arrays,
         const std::vector<std::string>& curves, const std::string& output, const std::string& method,
         const std::string& kernel, double max_absolute_error, double max_normal_error, bool edge_curves, int layers,
         double min_angle, double slope_margin, double extrapolation) {
        tool::Join_tool_options o;
        o.surface = surface, o.meshes = meshes, o.curves = curves, o.method = method, o.kernel = kernel;
        o.max_absolute_error = max_absolute_error, o.max_normal_error = max_normal_error;
        o.no_edge_curves = !edge_curves, o.layers = layers, o.min_angle = min_angle;
        o.slope_margin = slope_margin, o.extrapolation = extrapolation;
        tool::validate_join_options(o);
        for (std::size_t i = 0; i < arrays.size(); ++i)
          o.mesh_data.push_back(arrays[i] ? std::optional(checked_mesh(arrays[i]->first, arrays[i]->second,
                                                                       "join: mesh " + std::to_string(i)))
                                          : std::nullopt);
        tool::Join_tool_result result;
        {
          py::gil_scoped_release release;
          result = tool::run_join_explained(o, output, false);
        }
        auto d = json_to_python(tool::join_report_json(o, output, result)).cast<py::dict>();
        const py::tuple mesh = mesh_arrays(result.mesh);
        d["V"] = mesh[0];
        d["F"] = mesh[1];
        d["face_of_triangle"] = vector_array<std::int64_t>(result.face_of_triangle);
        return d;
      },
      py::arg("surface"), py::arg("meshes"), py::arg("arrays"), py::arg("curves"), py::arg("output"), py::arg("method"),
      py::arg("kernel"), py::arg("max_absolute_error"), py::arg("max_normal_error"), py::arg("edge_curves"),
      py::arg("layers"), py::arg("min_angle"), py::arg("slope_margin"), py::arg("extrapolation"),
      "The tool's `join`: the surface model file, one mesh per face (meshes[i] a file, or arrays[i] = (V, F) "
      "named meshes[i]); the record of `relgeo join --format json` with the joined mesh V, F and face_of_triangle.");
}

}  // namespace relgeo::python
