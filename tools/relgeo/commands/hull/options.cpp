// tools/relgeo/commands/hull/options.cpp — `relgeo hull`'s options and help.
#include "cli/options.h"
#include "commands/hull/command.h"
#include "commands/hull/facade.h"

namespace relgeo::tool {

std::string hull_help_footer() {
  return hull_algorithms_help() +
         "\nDefaults: --algorithm graham-fortune --kernel filtered (Fortune's stable scan with filtered exact "
         "predicates: the exact hull, fast).\n"
         "\nPoint file (relgeo/io/point_file.h): one point per line, two numbers separated by blanks or a comma; '#' "
         "starts a comment; blank lines are ignored. Decimal literals are correctly rounded "
         "to double; NaN, infinities, garbage and lines with one or three numbers are refused "
         "(exit 2, naming the line). An empty file gives an empty hull.\n"
         "\nMeasures (exact arithmetic, M = largest |coordinate| of the input):\n"
         "  convex          the hull, read as a polygon in the order returned, is simple,\n"
         "                  strictly convex and counterclockwise (exact check)\n"
         "  error           E of eq. (3.2): Hausdorff distance between the exact hull and the "
         "computed one, / M; inf when not convex\n"
         "  backward_error  relative perturbation after which the computed hull is exact: the "
         "largest distance of an input point outside it, / M; inf when not convex\n"
         "  backward_error_bound  graham-fortune's a-priori bound under the kernel (null when "
         "the kernel gives none, or for the other algorithms)\n"
         "\nJSON fields: algorithm, kernel, kernel_model, certified, n, status (ok|failed), "
         "failure, hull_size, hull_indices (0-based, CCW, from the lexicographically smallest "
         "vertex), hull ([x, y], 17 digits), convex, error, backward_error, "
         "backward_error_bound, coordinate_bound, moved_points (number of input points outside "
         "the hull), worst_point, uncertain_answers, predicate_calls (null for cgal), time_s "
         "(algorithm only), input, [discard_interior], [svg].\n"
         "SVG: computed hull blue, exact hull dashed green, lost points red circles, computed "
         "vertices that are not exact-hull vertices orange squares; y up.\n";
}

void add_hull_algorithm_option(CLI::App& cmd, std::string& algorithm) {
  add_value_option(cmd, "--algorithm", algorithm,
                   "the hull algorithm: graham-incremental, graham-fortune, monotone-chain or cgal", "ALGORITHM",
                   "graham-fortune");
}

void declare_hull_options(CLI::App& cmd, Hull_command_options& o) {
  add_file_operand(cmd, o.input, "input", "the point file, '-' for standard input");
  add_hull_algorithm_option(cmd, o.algorithm);
  add_kernel_option(cmd, o.kernel, "filtered");
  cmd.add_flag("--all-points", o.all_points,
               "graham-fortune, monotone-chain: scan every point, without first dropping the points "
               "certified to lie inside the polygon of 8 extreme points (same exact hull, same bound)");
  add_output_option(cmd, o.svg, "svg", "write a picture: input points, computed and exact hull, lost points");
  add_format_option(cmd, o.format);
}

}  // namespace relgeo::tool
