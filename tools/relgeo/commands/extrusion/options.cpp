// tools/relgeo/commands/extrusion/options.cpp — `relgeo extrusion`'s options and help.
#include "cli/options.h"

#include "commands/extrusion/command.h"
#include "commands/hull/command.h"

namespace relgeo::tool {

std::string extrusion_help_footer() {
  return "Input (FILE or --input FILE, '-' for standard input; relgeo/io/contour_json.h): a JSON object with\n"
         "  \"degree\": v and \"points\": [[x, y], ...]   a closed chain of M v points: curve m has\n"
         "                                           the control points m v .. m v + v (mod M v)\n"
         "  or \"curves\": [[[x, y], ...], ...]          each curve's control points; the last point of\n"
         "                                           curve m must equal the first of curve m+1 (mod M)\n"
         "  points may be [x, y, z] (3D): then \"direction\": [dx, dy, dz] is required; the points\n"
         "  must lie on one plane orthogonal to d (within the uncertainty) and are rotated by the Q\n"
         "  carrying d to the z axis (Rodrigues); the rotation's rounding error enters the verdict.\n"
         "  optional: \"heights\": [l1, l2] (l1 < l2), \"uncertainty\": relative (default 1e-3: a\n"
         "  point R may be off by 1e-3 ||R||), \"absolute_uncertainty\" (default 0), \"name\".\n"
         "--uncertainty / --absolute-uncertainty override the file.\n"
         "\nConditions (thesis Sec. 3.4.1), each a planar convex-hull problem under --kernel and\n"
         "--algorithm, its margin the exact distance rounded down:\n"
         "  1 no-self-intersection  0 not in conv(q), q = {R_{i+1} - R_i}; margin dist(0, conv q)\n"
         "  2 adjacent-curves       0 not in conv(Q') nor conv(Q'') of each adjacent pair\n"
         "  3 disjoint-curves       disjoint control hulls of non-adjacent curves; margin: their separation\n"
         "Margins are signed (<= 0: violated). A problem is certified when margin > uncertainty +\n"
         "computation error (rounding of the differences, the hull algorithm's backward-error\n"
         "certificate, the rotation), refused when the condition fails for the stored data,\n"
         "uncertain otherwise. Condition 3 uses a sweep over bounding boxes (--no-prune: all pairs).\n"
         "\nJSON fields: input, name, kernel, algorithm, curves, degrees, dimension, direction,\n"
         "rotation, rotation_error, plane_heights, heights, uncertainty {relative, absolute},\n"
         "verdict (certified|uncertain|refused), certified, conditions [{condition, name, verdict,\n"
         "problems, certified, uncertain, refused, pruned, min_margin, min_margin_is_prune_bound,\n"
         "worst}], offending_total, offending [{condition, set, curves, margin, uncertainty,\n"
         "computation_error, slack, verdict}] (smallest slack first, at most --max-listed), hull\n"
         "{runs, failures, non_convex, predicate_calls, uncertain_answers, max_backward_error}, pairs\n"
         "{non_adjacent, computed, prune_radius}, time_s, [svg].\n"
         "SVG: curves blue, control polygons dashed, control hulls grey; offending curves red\n"
         "(condition 1), orange (2), magenta (3); y up.\n"
         "Defaults: --kernel failsafe --algorithm graham-fortune; uncertainties from the file, else 1e-3 relative, "
         "0 absolute; --max-listed 50.\n"
         "Exit codes: 0 checked (whatever the verdict); 1 a hull algorithm failed (e.g.\n"
         "graham-incremental's non-termination; the verdict is then at best uncertain); 2 bad input.\n";
}

void declare_extrusion_options(CLI::App& cmd, Extrusion_command_options& o) {
  add_file_operand(cmd, o.input, "input", "the contour (JSON), '-' for standard input");
  add_kernel_option(cmd, o.kernel, "failsafe");
  add_hull_algorithm_option(cmd, o.algorithm);
  cmd.add_option("--uncertainty", o.uncertainty, "relative input uncertainty (default: the file's, else 1e-3)")
      ->check(CLI::NonNegativeNumber)
      ->type_name("DELTA");
  cmd.add_option("--absolute-uncertainty", o.absolute_uncertainty,
                 "absolute input uncertainty added to every control point (default: the file's, else 0)")
      ->check(CLI::NonNegativeNumber)
      ->type_name("EPS");
  cmd.add_flag("--no-prune", o.no_prune, "condition 3 on every non-adjacent pair (quadratic)");
  add_output_option(cmd, o.svg, "svg", "write a picture of the contour, its control hulls and offending curves");
  add_value_option(cmd, "--max-listed", o.max_listed, "offending problems listed", "N", "50");
  add_format_option(cmd, o.format);
}

}  // namespace relgeo::tool
