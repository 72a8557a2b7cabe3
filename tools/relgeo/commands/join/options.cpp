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
  cmd.add_option("--method", o.method, "whitney (thesis Sec. 4.3), naive (midpoint sewing, Sec. 4.1) or occt")
      ->type_name("METHOD")
      ->default_str("whitney");
  add_kernel_option(cmd, o.kernel, "filtered", "the kernel of the certified checks: failsafe, interval, filtered, exact");
  cmd.add_option("--max-absolute-error", o.max_absolute_error,
                 "criterion: fail (exit 1) when the result's absolute error exceeds E on a face")
      ->type_name("E")
      ->default_str("none");
  cmd.add_option("--max-normal-error", o.max_normal_error,
                 "criterion: fail (exit 1) when the result's normal-vector error (slope) exceeds E on a face")
      ->type_name("E")
      ->default_str("none");
  cmd.add_flag("--no-edge-curves", o.no_edge_curves, "ignore the edges' 3D curves: median polylines (thesis case 2)");
  cmd.add_option("--layers", o.layers, "rings of peripheral triangles removed, 1..8")->type_name("N")->default_str("1");
  cmd.add_option("--min-angle", o.min_angle, "Ruppert's smallest angle in the external region, degrees in (0, 30]")
      ->type_name("DEG")
      ->default_str("20.7");
  cmd.add_option("--slope-margin", o.slope_margin, "Whitney extension: L = L* (1 + margin), margin in [0, 1]")
      ->type_name("X")
      ->default_str("2^-30");
  cmd.add_option("--extrapolation", o.extrapolation,
                 "how far a vertex may project beyond a face's parameter domain, as a fraction of it, [0, 0.5]")
      ->type_name("X")
      ->default_str("0.05");
  add_format_option(cmd, o.format);
}

}  // namespace relgeo::tool
