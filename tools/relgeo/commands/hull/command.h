// tools/relgeo/commands/hull/command.h — `relgeo hull`.
#pragma once

#include <string>

#include "cli/text.h"

namespace CLI {
class App;
}  // namespace CLI

namespace relgeo::tool {

struct Hull_command_options {
  std::string algorithm = "graham-fortune";  ///< graham-incremental | graham-fortune | monotone-chain | cgal
  std::string kernel = "filtered";           ///< with graham-fortune: the recommended pair
  std::string input;                         ///< point file, "-" for standard input
  std::string svg;                           ///< picture file, empty for none
  bool all_points = false;  ///< no interior prefilter (relgeo::Hull_options::discard_interior = false)
  Format format = Format::text;
};

int run_hull_command(const Hull_command_options& options, Streams io);

/// The text of `relgeo help hull` below the options.
std::string hull_help_footer();

/// Declares the options on the subcommand.         [options.cpp]
void declare_hull_options(CLI::App& cmd, Hull_command_options& options);

/// --algorithm ALGORITHM: the hull algorithms (hull and extrusion).   [options.cpp]
void add_hull_algorithm_option(CLI::App& cmd, std::string& algorithm);

}  // namespace relgeo::tool
