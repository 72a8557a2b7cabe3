// tools/relgeo/commands/extrusion/command.cpp — `relgeo extrusion`: certified
// well-formedness of an extruded object (thesis Sec. 3.4.1) from a JSON
// contour description.
#include "commands/extrusion/command.h"

#include <filesystem>
#include <ostream>

#include "commands/extrusion/facade.h"
#include "commands/extrusion/report.h"
#include "commands/hull/facade.h"
#include "kernels/registry.h"
#include "relgeo/io/contour_json.h"

namespace relgeo::tool {

int run_extrusion_command(const Extrusion_command_options& o, Streams io) {
  std::ostream& out = io.out;
  std::ostream& err = io.err;
  validate_hull_combination(o.algorithm, o.kernel);
  if (o.max_listed < 0) throw Usage_error("--max-listed must be >= 0");
  if (o.input.empty()) throw Usage_error("no contour file: give it as 'relgeo extrusion FILE' or --input FILE ('-': standard input)");
  const std::string kernel = find_kernel(o.kernel).label();
  const std::string source = o.input == "-" ? "<stdin>" : o.input;
  const io::Contour_overrides overrides{
      o.uncertainty >= 0 ? std::optional<double>(o.uncertainty) : std::nullopt,
      o.absolute_uncertainty >= 0 ? std::optional<double>(o.absolute_uncertainty) : std::nullopt};
  const io::Contour_input input = o.input == "-" ? io::parse_contour_json(io::read_text_stream(io.in), source, overrides)
                                                 : io::read_contour_json(o.input, overrides);

  const Extrusion_options options = extrusion_options_for(input, !o.no_prune, static_cast<std::size_t>(o.max_listed));
  double time_s = 0;
  const Extrusion_report r = run_extrusion(o.algorithm, o.kernel, *input.contour, options, &time_s);
  if (!o.svg.empty())
    write_extrusion_svg(o.svg, *input.contour, r,
                        "relgeo extrusion: " + std::filesystem::path(source).filename().string() + ", kernel " +
                            kernel + ", " + o.algorithm);
  if (o.format == Format::json) {
    io::Json j = extrusion_report_json(input, kernel, o.algorithm, options, r, time_s);
    if (!o.svg.empty()) j["svg"] = o.svg;
    out << io::dump_json(j) << '\n';
  } else {
    out << extrusion_report_text(input, kernel, o.algorithm, options, r, time_s);
    if (!o.svg.empty()) out << "svg               " << o.svg << '\n';
  }
  if (r.hull_failures > 0) {
    err << "relgeo: failure: " << r.hull_failures << " hull computation(s) of " << o.algorithm << " under kernel '"
        << kernel << "' failed (e.g. non-termination)\n";
    return exit_failure;
  }
  return exit_success;
}

}  // namespace relgeo::tool
