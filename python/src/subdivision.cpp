// python/src/subdivision.cpp — Loop subdivision through the tool's subdivide
// facade (tools/relgeo/commands/subdivide/facade.h): the refined control
// mesh and its limit mesh under a kernel with constructions.
#include <string>

#include "bindings.h"
#include "commands/subdivide/facade.h"
#include "mesh_arrays.h"

namespace relgeo::python {

void bind_subdivision(py::module_& m) {
  m.def(
      "subdivide",
      [](const Double_array& v, const Index_array& f, int levels, const std::string& kernel, const std::string& rules) {
        tool::validate_subdivision_kernel(kernel);
        tool::Subdivision_request request;
        request.kernel = kernel;
        request.levels = tool::subdivision_levels(levels);
        request.options.crease_rules = tool::parse_crease_rules(rules);
        request.samples = 0;  // no sampling of the limit surface: the meshes only
        const Mesh_double mesh = checked_mesh(v, f, "subdivide");
        tool::Subdivision_result result;
        {
          py::gil_scoped_release release;
          result = tool::run_subdivision(mesh, request);
        }
        py::dict d;
        d["kernel"] = result.kernel;
        d["refined"] = mesh_arrays(result.refined);
        d["limit"] = mesh_arrays(result.limit);
        d["time_s"] = result.time_subdivision;
        return d;
      },
      py::arg("V"), py::arg("F"), py::arg("levels"), py::arg("kernel"), py::arg("rules"),
      "The tool's `subdivide` without sampling: {kernel, refined: (V, F), limit: (V, F), time_s}.");
}

}  // namespace relgeo::python
