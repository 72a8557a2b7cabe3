// tools/relgeo/linear_curves_commands.h — the `linsolve` and `extrusion`
// subcommands' options and entry points (parsed in main.cpp like the others;
// kept out of commands.h so the two areas can evolve separately).
#pragma once

#include <iosfwd>
#include <string>

#include "tool_common.h"

namespace relgeo::tool {

struct Linsolve_options {
  std::string input;        ///< matrix file, "-" for standard input (or empty with example/hilbert)
  std::string example;      ///< "thesis": the thesis' 2x2 example
  int hilbert = 0;          ///< > 0: the n x n Hilbert system stored in double
  std::string method = "partial";
  std::string scalar = "double";
  int exact_limit = 100;    ///< exact solution (forward error) for n <= this
  Format format = Format::text;
};
/// `relgeo linsolve`.          [linsolve_command.cpp]
int run_linsolve_command(const Linsolve_options& options, std::istream& in, std::ostream& out,
                         std::ostream& err);
/// The help text's description of the matrix file and the JSON fields.
std::string linsolve_help_footer();

struct Extrusion_command_options {
  std::string input;  ///< contour JSON file, "-" for standard input
  std::string kernel = "failsafe";
  std::string algorithm = "graham-fortune";
  double uncertainty = -1;           ///< relative; < 0: from the file, default 1e-3
  double absolute_uncertainty = -1;  ///< < 0: from the file, default 0
  bool no_prune = false;
  std::string svg;                   ///< picture file, empty for none
  int max_listed = 50;               ///< offending problems listed
  Format format = Format::text;
};
/// `relgeo extrusion`.         [extrusion_command.cpp]
int run_extrusion_command(const Extrusion_command_options& options, std::istream& in, std::ostream& out,
                          std::ostream& err);
/// The help text's description of the input format and the JSON fields.
std::string extrusion_help_footer();

}  // namespace relgeo::tool
