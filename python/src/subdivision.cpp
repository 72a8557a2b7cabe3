// python/src/subdivision.cpp — Loop subdivision through the tool's subdivide
// facade (tools/relgeo/commands/subdivide/facade.h): the refined control
// mesh and its limit mesh under a kernel with constructions.
#include <cstdint>
#include <string>
#include <vector>

#include "bindings.h"
#include "commands/subdivide/facade.h"
#include "mesh_arrays.h"
#include "numpy_arrays.h"

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

  m.def(
      "limit_evaluate",
      [](const Double_array& v, const Index_array& f, const py::array_t<std::int64_t, py::array::forcecast>& faces,
         const Double_array& us, const Double_array& vs, const std::string& kernel, const std::string& rules) {
        if (faces.ndim() != 1 || us.ndim() != 1 || vs.ndim() != 1 || us.shape(0) != faces.shape(0) ||
            vs.shape(0) != faces.shape(0))
          throw py::value_error("limit_evaluate: face, u and v must be 1-d arrays of one length");
        tool::validate_subdivision_kernel(kernel);
        Loop_options options;
        options.crease_rules = tool::parse_crease_rules(rules);
        const Mesh_double mesh = checked_mesh(v, f, "limit_evaluate");
        const auto n = faces.shape(0);
        std::vector<std::int64_t> face(n);
        std::vector<double> u(n), w(n);
        const auto fi = faces.unchecked<1>();
        const auto ui = us.unchecked<1>(), wi = vs.unchecked<1>();
        for (py::ssize_t i = 0; i < n; ++i) face[i] = fi(i), u[i] = ui(i), w[i] = wi(i);  // any strides
        std::vector<Point_3<double>> points;
        {
          py::gil_scoped_release release;
          points = tool::evaluate_limit_surface(kernel, mesh, face, u, w, options);
        }
        std::vector<double> coordinates;
        coordinates.reserve(3 * points.size());
        for (const auto& p : points) coordinates.insert(coordinates.end(), {p.x, p.y, p.z});
        return matrix_array<double>(coordinates, points.size(), 3);
      },
      py::arg("V"), py::arg("F"), py::arg("face"), py::arg("u"), py::arg("v"), py::arg("kernel"), py::arg("rules"),
      "The Loop limit surface of the control mesh (V, F) at (face[i], u[i], v[i]), exact under the exact kernel "
      "(relgeo::Loop_limit_surface), rounded to double: an (n, 3) array.");
}

}  // namespace relgeo::python
