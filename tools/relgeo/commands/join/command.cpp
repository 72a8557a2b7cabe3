// tools/relgeo/commands/join/command.cpp — `relgeo join`: mesh patches joined
// to the trimmed faces of a surface model (thesis Ch. 4): the Whitney joiner,
// naive midpoint sewing or OpenCASCADE's sewing, the joined mesh written, the
// errors before and after and the certified flip counts reported.
#include "commands/join/command.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <sstream>

#include "commands/join/facade.h"
#include "commands/join/picture.h"
#include "relgeo/io/json.h"
#include "relgeo/io/text_file.h"

namespace relgeo::tool {

namespace {

using io::Json;

std::string g3(double v) { return measure_text(v, 3); }

std::string text_report(const Join_tool_options& o, const std::string& output, const Join_tool_result& res) {
  const Join_report& r = res.report;
  std::ostringstream s;
  Key_value_text kv(18);
  kv.add("surface", o.surface + " (" + std::to_string(res.faces) + " face(s); edges: " +
                        std::to_string(r.edges_with_curve) + " with curve, " + std::to_string(r.edges_with_median) +
                        " median, " + std::to_string(r.free_edges) + " free)");
  std::string meshes;
  for (const auto& m : o.meshes) meshes += (meshes.empty() ? "" : ", ") + m;
  kv.add("meshes", meshes);
  kv.add("method", o.method + ", kernel " + o.kernel + " (" + res.kernel_model + ")");
  kv.add("output", std::to_string(r.vertices) + " vertices, " + std::to_string(r.triangles) + " triangles -> " + output);
  s << kv.str() << "\n";
  Text_table t({"face", "abs before", "abs after", "nve before", "nve after", "M", "L", "flipped before",
                "flipped after", "overlaps", "guarantees"});
  for (std::size_t f = 0; f < r.faces.size(); ++f) {
    const Join_face_report& x = r.faces[f];
    t.add_row({std::to_string(f), g3(x.before.absolute), g3(x.after.absolute), g3(x.before.normal_vector),
               g3(x.after.normal_vector), g3(x.boundary_max_abs_height), g3(x.lipschitz_constant),
               std::to_string(x.orientation_before.flipped), std::to_string(x.orientation_after.flipped),
               std::to_string(x.overlaps_after), x.guarantees_hold ? "hold" : "-"});
  }
  s << t.str() << "\n";
  Key_value_text tail(18);
  tail.add("seams", std::string(r.watertight_seams ? "watertight" : "open") + " (" +
                        std::to_string(r.seam_boundary_edges) + " boundary edges on seams), " +
                        (r.conforming ? "conforming" : "not conforming"));
  tail.add("smallest angle", g3(r.min_angle_3d) + " degrees (3D)");
  tail.add("time", duration_text(r.total_seconds));
  if (!o.svg.empty()) tail.add("picture", o.svg);
  tail.add("status", res.status + (res.failure.empty() ? "" : " (" + res.failure + ")"));
  s << tail.str();
  return s.str();
}

}  // namespace

std::string default_join_output(const Join_tool_options& o) {
  return std::filesystem::path(o.surface).stem().string() + "_joined.off";
}

std::string join_help_footer() {
  std::string kernels;
  for (const auto& k : join_kernel_names()) kernels += (kernels.empty() ? "" : ", ") + k;
  return "Input: a surface model (a JSON relgeo-surface-model, doc/joining.md; STEP or IGES when relgeo is built "
         "with OpenCASCADE) and one mesh patch per trimmed face, in face order (--mesh, repeated). Edges of the "
         "model with a 3D curve are joined along it (thesis case 1), the others along the median of the two "
         "meshes' boundaries (case 2); --curve adds edge curves from a JSON file.\n"
         "Methods: whitney (the thesis' joiner: central meshes, Ruppert-refined external regions, Whitney "
         "reprojection: |a| <= M and slope <= L on every face, no fold), naive (midpoint sewing of the "
         "boundaries, the baseline that folds), occt (OpenCASCADE's sewing and meshing of the faces).\n"
         "Measures per face: absolute error (largest |height| over the face) and normal-vector error (largest "
         "slope of the height field between two corners of a triangle), before (the input) and after (the "
         "result); M and L of the boundary data; flipped triangles and overlaps in (u,v), certified by the "
         "kernel (" + kernels + ").\n"
         "Criteria: --max-absolute-error and --max-normal-error make a result whose error exceeds them on a "
         "face 'failed'.\n"
         "JSON fields: command, kernel, kernel_model, surface, meshes, output, method, faces [{before "
         "{absolute, normal_vector}, after, after_reprojected, boundary_max_abs_height, lipschitz_constant, "
         "orientation_before, orientation_after {positive, flipped, degenerate, undecided}, overlaps_after, "
         "guarantees_hold, ...}], summary {absolute_error_before, absolute_error_after, "
         "normal_vector_error_before, normal_vector_error_after, flipped_before, flipped_after, "
         "overlaps_after}, criteria, vertices, triangles, watertight_seams, conforming, seconds, status, "
         "failure, [svg].\n"
         "Defaults: --method whitney --kernel filtered --layers 1 --min-angle 20.7; the surface file may be "
         "given positionally (relgeo join SURFACE --mesh A.off --mesh B.off); without --output: "
         "SURFACE_joined.off in the current folder.\n"
         "Exit codes: 0 success; 1 the result failed (a flipped, degenerate or overlapping triangle, an open "
         "seam, an error above a criterion) or a step of the joiner failed; 2 bad input or usage (a missing or "
         "unreadable file, a mesh that does not project onto its face, meshes that do not fit the model, a "
         "bad option).\n";
}

int run_join_command(const Join_tool_options& o, Streams io) {
  validate_join_options(o);
  const std::string output = o.output.empty() ? default_join_output(o) : o.output;
  const Join_tool_result res = run_join_explained(o, output, !o.svg.empty());
  if (!o.svg.empty())
    join_picture(res.pictures, "relgeo join --method " + o.method + ": " + std::to_string(flipped_in_picture(res.pictures)) +
                                   " flipped triangle(s) in (u,v)")
        .write(o.svg);

  Json j = join_report_json(o, output, res);
  if (!o.svg.empty()) j["svg"] = o.svg;
  if (!o.report.empty()) io::write_text_file(o.report, io::dump_json(j) + "\n", "report");
  if (o.format == Format::json) io.out << io::dump_json(j) << '\n';
  else io.out << text_report(o, output, res);
  if (res.status != "ok") {
    io.err << "relgeo: failure: the joined mesh failed its checks (" << res.failure << ")\n";
    return exit_failure;
  }
  return exit_success;
}

}  // namespace relgeo::tool
