// tools/relgeo/extrusion_command.cpp — `relgeo extrusion`: certified
// well-formedness of an extruded object (thesis Sec. 3.4.1) from a JSON
// contour description.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>

#include "extrusion_runs.h"
#include "hull_runs.h"
#include "linear_curves_commands.h"

namespace relgeo::tool {

int run_extrusion_command(const Extrusion_command_options& o, std::istream& in, std::ostream& out,
                          std::ostream& err) {
  validate_hull_combination(o.algorithm, o.kernel);
  if (o.max_listed < 0) throw Usage_error("--max-listed must be >= 0");
  std::string text;
  if (o.input == "-") {
    text.assign(std::istreambuf_iterator<char>(in), {});
  } else {
    std::ifstream f(o.input, std::ios::binary);
    if (!f) throw Usage_error("cannot read '" + o.input + "'");
    text.assign(std::istreambuf_iterator<char>(f), {});
  }
  const std::string source = o.input == "-" ? "<stdin>" : o.input;
  const Extrusion_input input =
      parse_extrusion_input(text, source, o.uncertainty >= 0 ? std::optional<double>(o.uncertainty) : std::nullopt,
                            o.absolute_uncertainty >= 0 ? std::optional<double>(o.absolute_uncertainty) : std::nullopt);

  Extrusion_options options;
  options.relative_uncertainty = input.relative_uncertainty;
  options.absolute_uncertainty = input.absolute_uncertainty;
  options.rotation_error = input.projection ? input.projection->rotation_error : 0.0;
  options.prune = !o.no_prune;
  options.max_listed = static_cast<std::size_t>(o.max_listed);
  double time_s = 0;
  const Extrusion_report r = run_extrusion(o.algorithm, o.kernel, *input.contour, options, &time_s);
  if (!o.svg.empty())
    write_extrusion_svg(o.svg, *input.contour, r,
                        "relgeo extrusion: " + std::filesystem::path(source).filename().string() + ", kernel " +
                            o.kernel + ", " + o.algorithm);
  if (o.format == Format::json) {
    Json j = extrusion_report_json(input, o.kernel, o.algorithm, options, r, time_s);
    if (!o.svg.empty()) j["svg"] = o.svg;
    out << dump_json(j) << '\n';
  } else {
    out << extrusion_report_text(input, o.kernel, o.algorithm, options, r, time_s);
    if (!o.svg.empty()) out << "svg               " << o.svg << '\n';
  }
  if (r.hull_failures > 0) {
    err << "relgeo: failure: " << r.hull_failures << " hull computation(s) of " << o.algorithm << " under kernel '"
        << o.kernel << "' failed (e.g. non-termination)\n";
    return exit_failure;
  }
  return exit_success;
}

}  // namespace relgeo::tool
