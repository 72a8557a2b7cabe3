// python/src/boolean.cpp — boolean(A, B, op) through the tool's Boolean facade
// (tools/relgeo/commands/boolean/facade.h): the result mesh as (V, F) and the
// record of `relgeo boolean --format json` (status, validation, counts,
// phase times).
#include <cstdint>
#include <string>
#include <vector>

#include "bindings.h"
#include "commands/boolean/facade.h"
#include "commands/boolean/report.h"
#include "commands/boolean/subdivision_facade.h"
#include "commands/boolean/subdivision_report.h"
#include "json_to_python.h"
#include "mesh_arrays.h"

namespace relgeo::python {

namespace {

/// Row f: the operand (0 = A, 1 = B) and its face that output face f comes from.
py::array_t<std::int64_t> provenance_array(const std::vector<Face_origin>& provenance) {
  std::vector<std::int64_t> rows;
  rows.reserve(2 * provenance.size());
  for (const Face_origin& o : provenance) rows.insert(rows.end(), {o.operand, o.face});
  return matrix_array<std::int64_t>(rows, provenance.size(), 2);
}

/// The tool's record without the operands' file names (arrays have none),
/// with the mesh and the faces' provenance.
py::dict boolean_dict(const std::string& op, const Mesh_double& a, const Mesh_double& b, const tool::Boolean_run& run) {
  tool::Boolean_report_input record;
  record.operation = op, record.a = &a, record.b = &b, record.run = &run;
  auto d = json_to_python(tool::boolean_report_json(record)).cast<py::dict>();
  for (const char* operand : {"a", "b"}) d["operands"][operand].attr("pop")("file");
  const py::tuple mesh = mesh_arrays(run.mesh);
  d["V"] = mesh[0];
  d["F"] = mesh[1];
  d["provenance"] = provenance_array(run.provenance);
  return d;
}

/// The crease edges ((k, 2) int64, a < b) and corners ((k,) int64) of a mesh's tags.
py::tuple tag_arrays(const Feature_tags& tags) {
  std::vector<Index> creases;
  for (const Edge& e : tags.creases()) creases.insert(creases.end(), {e.a, e.b});
  const std::vector<Index> corners(tags.corners().begin(), tags.corners().end());
  return py::make_tuple(matrix_array<std::int64_t>(creases, tags.creases().size(), 2),
                        vector_array<std::int64_t>(corners));
}

/// The record of `relgeo boolean --levels K --format json` without the
/// operands' file names, with the result's control mesh and tags, and the
/// polyhedral Boolean's mesh in its record.
py::dict subdivision_boolean_dict(const std::string& op, const Mesh_double& a, const Mesh_double& b,
                                  const tool::Subdivision_boolean_run& run) {
  const tool::Subdivision_boolean_report_input record{op, "", "", &a, &b, &run};
  auto d = json_to_python(tool::subdivision_boolean_report_json(record)).cast<py::dict>();
  for (const char* operand : {"a", "b"}) d["operands"][operand].attr("pop")("file");
  const py::tuple mesh = mesh_arrays(run.control), tags = tag_arrays(run.control.tags);
  d["V"] = mesh[0];
  d["F"] = mesh[1];
  d["creases"] = tags[0];
  d["corners"] = tags[1];
  if (run.polyhedral.ok()) {
    const py::tuple polyhedral = mesh_arrays(run.polyhedral.mesh);
    d["polyhedral"]["V"] = polyhedral[0];
    d["polyhedral"]["F"] = polyhedral[1];
  }
  return d;
}

}  // namespace

void bind_boolean(py::module_& m) {
  m.def(
      "boolean",
      [](const Double_array& va, const Index_array& fa, const Double_array& vb, const Index_array& fb,
         const std::string& op, const std::string& kernel, const std::string& rounding,
         const std::string& retriangulation, bool check_self_intersections) {
        const Boolean_operation operation = tool::parse_boolean_operation(op);
        tool::validate_boolean_kernel(kernel);
        const Boolean_options options{
            .check_self_intersections = check_self_intersections,
            .rounding = tool::parse_output_rounding(rounding),
            .delaunay_retriangulation = tool::parse_delaunay_retriangulation(retriangulation)};
        const Mesh_double a = checked_mesh(va, fa, "boolean: A"), b = checked_mesh(vb, fb, "boolean: B");
        tool::Boolean_run run;
        {
          py::gil_scoped_release release;
          run = tool::evaluate_boolean(kernel, a, b, operation, options);
        }
        return boolean_dict(op, a, b, run);
      },
      py::arg("VA"), py::arg("FA"), py::arg("VB"), py::arg("FB"), py::arg("op"), py::arg("kernel"), py::arg("rounding"),
      py::arg("retriangulation"), py::arg("check_self_intersections"),
      "The tool's `boolean` on two (V, F) meshes: the record of `relgeo boolean --format json` with the result "
      "as V, F; InvalidOperand for operands that do not bound a solid.");

  m.def(
      "subdivision_boolean",
      [](const Double_array& va, const Index_array& fa, const Double_array& vb, const Index_array& fb,
         const std::string& op, int levels, const std::string& kernel, bool fit, bool check_self_intersections) {
        const Boolean_operation operation = tool::parse_boolean_operation(op);
        tool::validate_boolean_kernel(kernel);
        if (levels < 1) throw py::value_error("subdivision_boolean: levels must be >= 1");
        Subdivision_boolean_options options;
        options.mesh.check_self_intersections = check_self_intersections;
        options.fit = fit;
        const Mesh_double a = checked_mesh(va, fa, "boolean: A"), b = checked_mesh(vb, fb, "boolean: B");
        tool::Subdivision_boolean_run run;
        {
          py::gil_scoped_release release;
          run = tool::evaluate_subdivision_boolean(kernel, a, b, operation, static_cast<unsigned>(levels), options);
        }
        return subdivision_boolean_dict(op, a, b, run);
      },
      py::arg("VA"), py::arg("FA"), py::arg("VB"), py::arg("FB"), py::arg("op"), py::arg("levels"), py::arg("kernel"),
      py::arg("fit"), py::arg("check_self_intersections"),
      "The tool's `boolean --levels K` on two Loop control meshes (V, F): the record of `relgeo boolean --levels K "
      "--format json` with the result's control mesh V, F and its creases and corners.");
}

}  // namespace relgeo::python
