// tools/relgeo/commands/join/options.cpp — `relgeo join`'s options.
#include "cli/options.h"
#include "commands/join/command.h"

namespace relgeo::tool {

void declare_join_options(CLI::App& cmd, Join_tool_options& o) {
  add_file_operand(cmd, o.surface, "surface",
                   "the surface model: .json (relgeo-surface-model), .step/.stp/.iges/.igs (with OpenCASCADE)");
  cmd.add_option("--mesh", o.meshes, "a mesh patch (OFF, OBJ, PLY, STL), one per face in face order; repeat")
      ->type_name("FILE");
  cmd.add_option("--curve", o.curves, "edge curves from a JSON file (thesis case 1); repeatable")->type_name("FILE");
  add_output_option(cmd, o.output, "output", "the joined mesh (.off, .obj, .ply, .stl; default: SURFACE_joined.off here)");
  add_output_option(cmd, o.report, "report", "also write the JSON report to this file");
  add_output_option(cmd, o.svg, "svg", "picture: every face's part of the result in (u,v), flipped triangles red");
  add_value_option(cmd, "--method", o.method, "whitney (thesis Sec. 4.3), naive (midpoint sewing, Sec. 4.1) or occt",
                   "METHOD", "whitney");
  add_kernel_option(cmd, o.kernel, "filtered", "the kernel of the certified checks: failsafe, interval, filtered, exact");
  add_value_option(cmd, "--max-absolute-error", o.max_absolute_error,
                   "criterion: fail (exit 1) when the result's absolute error exceeds E on a face", "E", "none");
  add_value_option(cmd, "--max-normal-error", o.max_normal_error,
                   "criterion: fail (exit 1) when the result's normal-vector error (slope) exceeds E on a face", "E",
                   "none");
  cmd.add_flag("--no-edge-curves", o.no_edge_curves, "ignore the edges' 3D curves: median polylines (thesis case 2)");
  add_value_option(cmd, "--layers", o.layers, "rings of peripheral triangles removed, 1..8", "N", "1");
  add_value_option(cmd, "--min-angle", o.min_angle,
                   "Ruppert's smallest angle in the external region, degrees in (0, 30]", "DEG", "20.7");
  add_value_option(cmd, "--slope-margin", o.slope_margin, "Whitney extension: L = L* (1 + margin), margin in [0, 1]",
                   "X", "2^-30");
  add_value_option(cmd, "--extrapolation", o.extrapolation,
                   "how far a vertex may project beyond a face's parameter domain, as a fraction of it, [0, 0.5]", "X",
                   "0.05");
  add_format_option(cmd, o.format);
}

}  // namespace relgeo::tool
