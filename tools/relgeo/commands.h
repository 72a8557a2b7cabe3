// tools/relgeo/commands.h — the subcommands' options and entry points.
// main.cpp parses the command line (CLI11) into these structs; each command
// returns an exit code (0 ok, 1 computation failure) and throws Usage_error
// or relgeo::Error for bad input (exit 2, reported by main).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "tool_common.h"

namespace relgeo::tool {

struct Orient_grid_options {
  std::string p, q, r;  ///< "X,Y" each, unless `triple` is given
  std::string triple;   ///< "a", "b" or "c": the grids of Kettner et al. (SPEC Sec. 3.1)
  std::string kernel;
  int size = 256;
  std::string png;  ///< picture file, empty for none
  int scale = 2;    ///< pixels per cell in the picture
  Format format = Format::text;
};
int run_orient_grid(const Orient_grid_options& options, std::ostream& out, std::ostream& err);

struct Hull_command_options {
  std::string algorithm;  ///< graham-incremental | graham-fortune | monotone-chain | cgal
  std::string kernel;
  std::string input;      ///< point file, "-" for standard input
  std::string svg;        ///< picture file, empty for none
  bool all_points = false;  ///< no interior prefilter (relgeo::Hull_options::discard_interior = false)
  Format format = Format::text;
};
/// `relgeo hull`: reads the points from `options.input` (or `in` for "-").
int run_hull_command(const Hull_command_options& options, std::istream& in, std::ostream& out,
                     std::ostream& err);

struct Experiment_options {
  std::string output = "results";
  bool quick = false;
  bool quiet = false;                 ///< no progress lines on stderr
  std::vector<std::string> sections;  ///< empty: all
  Format format = Format::text;
};
int run_experiment(const Experiment_options& options, std::ostream& out, std::ostream& err);

/// "name  summary" lines of the experiment sections, for the help text.
std::string experiment_sections_help();
/// Throws Usage_error unless `name` is a registered experiment section.
void validate_section_name(const std::string& name);

}  // namespace relgeo::tool
