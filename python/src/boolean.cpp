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
}

}  // namespace relgeo::python
