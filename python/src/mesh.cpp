// python/src/mesh.cpp — meshes as (V, F) arrays: read_mesh, write_mesh
// (relgeo/mesh/mesh_io.h: OFF, OBJ, PLY, STL by extension) and
// validate_solid (relgeo/mesh/solid_validation.h) under the filtered exact
// kernel, its report as the dict of the tool's JSON (io::solid_report_json).
#include <string>

#include "bindings.h"
#include "json_to_python.h"
#include "mesh_arrays.h"
#include "relgeo/io/solid_report_json.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/mesh/mesh_io.h"
#include "relgeo/mesh/solid_validation.h"

namespace relgeo::python {

void bind_mesh(py::module_& m) {
  m.def(
      "read_mesh",
      [](const std::string& path, bool triangulate) {
        Mesh_double mesh;
        {
          py::gil_scoped_release release;
          mesh = read_mesh(path, {.triangulate_polygons = triangulate});
        }
        return mesh_arrays(mesh);
      },
      py::arg("path"), py::arg("triangulate"),
      "(V, F) of an OFF, OBJ, PLY or STL file (by extension); UnreadableFile, NonFiniteInput, InvalidMesh on bad "
      "files.");
  m.def(
      "write_mesh",
      [](const std::string& path, const Double_array& v, const Index_array& f, bool binary) {
        const Mesh_double mesh = checked_mesh(v, f, "write_mesh");
        py::gil_scoped_release release;
        write_mesh(path, mesh, {.binary = binary});
      },
      py::arg("path"), py::arg("V"), py::arg("F"), py::arg("binary"),
      "Writes (V, F) by the path's extension (17 significant digits: doubles round-trip).");
  m.def(
      "validate_solid",
      [](const Double_array& v, const Index_array& f) {
        const Mesh_double mesh = unchecked_mesh(v, f, "validate_solid");
        Solid_report report;
        {
          py::gil_scoped_release release;
          report = validate_solid(mesh, Filtered_exact_kernel{});
        }
        return json_to_python(io::solid_report_json(report));
      },
      py::arg("V"), py::arg("F"),
      "relgeo::validate_solid under Filtered_exact_kernel: the Solid_report as a dict (the tool's JSON fields).");
}

}  // namespace relgeo::python
