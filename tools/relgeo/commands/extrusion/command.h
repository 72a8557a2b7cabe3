// tools/relgeo/commands/extrusion/command.h — `relgeo extrusion`.
#pragma once

#include <string>

#include "cli/text.h"

namespace CLI {
class App;
}  // namespace CLI

namespace relgeo::tool {

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

int run_extrusion_command(const Extrusion_command_options& options, Streams io);

/// The text of `relgeo help extrusion` below the options.
std::string extrusion_help_footer();

/// Declares the options on the subcommand.         [options.cpp]
void declare_extrusion_options(CLI::App& cmd, Extrusion_command_options& options);

}  // namespace relgeo::tool
