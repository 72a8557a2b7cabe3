// tools/relgeo/commands/hull/command.cpp — `relgeo hull`: one planar convex hull under
// an algorithm and a kernel, with its error E, its backward-error certificate
// and (graham-fortune) the a-priori bound; optional SVG picture.
#include <ostream>

#include "commands/hull/command.h"
#include "commands/hull/facade.h"
#include "commands/hull/picture.h"
#include "commands/hull/report.h"
#include "kernels/registry.h"
#include "relgeo/io/point_file.h"

namespace relgeo::tool {

int run_hull_command(const Hull_command_options& o, Streams io) {
  std::ostream& out = io.out;
  std::ostream& err = io.err;
  validate_hull_combination(o.algorithm, o.kernel);
  if (o.input.empty()) throw Usage_error("no point file: give it as 'relgeo hull FILE' or --input FILE ('-': standard input)");
  const std::vector<Point_2<double>> points = o.input == "-" ? io::read_points_2(io.in) : io::read_points_2(o.input);
  const Kernel_entry& info = find_kernel(o.kernel);
  const bool sorting = o.algorithm == "graham-fortune" || o.algorithm == "monotone-chain";
  if (o.all_points && !sorting)
    throw Usage_error("--all-points applies to graham-fortune and monotone-chain only");
  const Hull_evaluation e =
      evaluate_hull(o.algorithm, o.kernel, points, 0, relgeo::Hull_options{.discard_interior = !o.all_points});
  if (!o.svg.empty())
    write_hull_svg(o.svg, points, e, "relgeo hull: " + o.algorithm + ", kernel " + info.label());
  const bool failed = e.run.status != Hull_status::ok;

  if (o.format == Format::json) {
    io::Json j = hull_report_json(o.algorithm, info, points, e);
    j["input"] = o.input;
    if (sorting) j["discard_interior"] = !o.all_points;
    if (!o.svg.empty()) j["svg"] = o.svg;
    out << io::dump_json(j) << '\n';
  } else {
    std::string text = hull_report_text(o.algorithm, info, o.input == "-" ? "<stdin>" : o.input, points, e);
    if (o.all_points) text += "prefilter        off (--all-points: every point scanned)\n";
    if (!o.svg.empty()) text += "svg              " + o.svg + "\n";
    out << text;
  }
  if (failed) {
    err << "relgeo: failure: " << o.algorithm << " under kernel '" << o.kernel
        << "' reported " << e.run.failure << '\n';
    return exit_failure;
  }
  if (!e.error.convex) {  // an invalid result, found by the exact check
    err << "relgeo: failure: " << o.algorithm << " under kernel '" << o.kernel
        << "' returned a polygon that is not simple, strictly convex and counterclockwise\n";
    return exit_failure;
  }
  return exit_success;
}

}  // namespace relgeo::tool
