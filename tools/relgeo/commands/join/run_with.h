// tools/relgeo/commands/join/run_with.h — the kernel-templated body of
// `relgeo join` (SPEC Sec. 8): read the surface model, the edge curves and the
// mesh patches, join them by the method named in the options under kernel K,
// judge the result by the criteria, write the joined mesh. The kernel comes
// from the tool's kernel list (dispatch.cpp turns `--kernel` into K); include
// this header only there (it brings the joiner's heavy headers) and in its
// test, run_with_test.cpp.
//
// Needs CGAL, Eigen and relgeo::io (nlohmann-json); STEP/IGES input and the
// occt method run in the OpenCASCADE plug-in (plugins/occt/occt_join.h),
// built with relgeo::occt; without it they are Invalid_input.
#pragma once

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "plugins/occt/occt_join.h"
#include "relgeo/core/errors.h"
#include "relgeo/joining/join_report_json.h"
#include "relgeo/joining/joiner.h"
#include "relgeo/joining/naive_sewing.h"
#include "relgeo/joining/occt_sewing_options.h"
#include "relgeo/mesh/mesh_io.h"
#include "relgeo/surfaces/surface_json.h"

namespace relgeo::tool {

/// What run_join_with reads, how it joins, where it writes: the files and
/// the joiner's parameters of Join_tool_options (dispatch.cpp fills it).
struct Join_command_options {
  /// The faces: .step/.stp/.iges/.igs (OpenCASCADE) or .json (surface_json.h).
  std::string surface;
  /// One mesh patch per face, in the model's face order (.off/.obj/.ply/.stl).
  std::vector<std::string> meshes;
  /// Per mesh, its triangles when given in memory (then `meshes` only names
  /// it); empty: every mesh is read from its file.
  std::vector<std::optional<Triangle_mesh<Point_3<double>>>> mesh_data;
  /// Files giving edges their 3D curves (read_edge_curves_json); optional.
  std::vector<std::string> curves;
  /// The joined mesh (.off/.obj/.ply/.stl); empty: not written.
  std::string output;
  /// whitney (thesis Sec. 4.3), naive (Sec. 4.1) or occt (OpenCASCADE's
  /// sewing and meshing of the faces; the meshes are only measured).
  std::string method = "whitney";
  Join_options join{};
  /// Error criteria: a result with a face whose absolute error or
  /// normal-vector error (after joining) exceeds them is "failed" [none].
  double max_absolute_error = std::numeric_limits<double>::infinity();
  double max_normal_error = std::numeric_limits<double>::infinity();
  Occt_sewing_options occt{};
};

/// run_join_with's answer: the joining report, and whether the result is valid.
struct Join_command_report {
  /// "ok": conforming, watertight seams, no flipped, degenerate or
  /// overlapping triangle in any face's (u,v) domain; "failed" otherwise
  /// (naive sewing on a folding input, for instance), or an error above the
  /// criteria of the options: `failure` says why.
  std::string status = "ok";
  std::string failure;
  std::string surface, output;
  std::vector<std::string> meshes;
  std::size_t faces = 0;
  Join_report report;
  /// The joined mesh (also written to `output` when given) and the model
  /// face of each of its triangles.
  Triangle_mesh<Point_3<double>> mesh;
  std::vector<Index> face_of_triangle;
  /// The surface model as joined (edge curves from `curves` included).
  Surface_model model;
};

/// Reads the surface model of a file (by extension). \throws Unreadable_file,
/// Invalid_input (STEP/IGES without the OpenCASCADE plug-in).
inline Surface_model read_surface_model(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".json") return read_surface_model_json(path);
  return occt_join_functions("'" + path + "': STEP/IGES input").read_cad_model(path);
}

/// \brief Reads the model and the meshes, joins them by the method named in
/// `o` with kernel K, writes the result (when `o.output` is given), returns
/// the report.
/// \throws relgeo::Error: Unreadable_file and the other Invalid_input kinds
/// for bad input (an unknown method too; exit 2), Joining_failure when a step
/// fails (exit 1).
template <class K>
Join_command_report run_join_with(const Join_command_options& o) {
  Join_command_report r;
  r.surface = o.surface, r.output = o.output, r.meshes = o.meshes;
  Surface_model model = read_surface_model(o.surface);
  for (const std::string& c : o.curves) read_edge_curves_json(c, model);
  std::vector<Triangle_mesh<Point_3<double>>> meshes;
  for (std::size_t i = 0; i < o.meshes.size(); ++i)
    meshes.push_back(i < o.mesh_data.size() && o.mesh_data[i] ? *o.mesh_data[i]
                                                              : read_mesh(o.meshes[i], {.triangulate_polygons = true}));
  r.faces = model.faces.size();
  Join_result result;
  if (o.method == "whitney") {
    result = join_meshes(model, meshes, K{}, o.join);
  } else if (o.method == "naive") {
    result = naive_sewing(model, meshes, K{}, o.join);
  } else if (o.method == "occt") {
    result = occt_join_functions("method occt").occt_sewing(K::name(), model, meshes, o.occt);
  } else {
    throw Invalid_input("unknown joining method '" + o.method + "' (whitney, naive or occt)");
  }
  r.report = std::move(result.report);
  r.mesh = std::move(result.mesh);
  r.face_of_triangle = std::move(result.face_of_triangle);
  r.model = std::move(model);
  const auto fail = [&](const std::string& why) {
    if (r.status == "ok") r.status = "failed", r.failure = why;
  };
  if (!r.report.conforming) fail("non-conforming");
  if (!r.report.watertight_seams) fail("open-seam");
  for (const Join_face_report& f : r.report.faces) {
    if (f.orientation_after.flipped) fail("flipped-triangles");
    if (f.orientation_after.degenerate) fail("degenerate-triangles");
    if (f.overlaps_after) fail("overlapping-triangles");
    if (f.orientation_after.undecided || f.overlaps_undecided_after) fail("undecided");
    if (f.after.absolute > o.max_absolute_error) fail("absolute-error");
    if (f.after.normal_vector > o.max_normal_error) fail("normal-vector-error");
  }
  if (!o.output.empty()) write_mesh(o.output, r.mesh);
  return r;
}

/// The command's JSON output.
inline io::Json to_json(const Join_command_report& r) {
  io::Json j = to_json(r.report);
  j.update(io::Json{{"status", r.status},
                    {"failure", r.failure.empty() ? io::Json(nullptr) : io::Json(r.failure)},
                    {"surface", r.surface},
                    {"meshes", r.meshes},
                    {"output", r.output},
                    {"face_count", r.faces}});
  return j;
}

}  // namespace relgeo::tool
