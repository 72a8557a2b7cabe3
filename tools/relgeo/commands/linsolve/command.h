// tools/relgeo/commands/linsolve/command.h — `relgeo linsolve`.
#pragma once

#include <string>

#include "cli/text.h"

namespace CLI {
class App;
}  // namespace CLI

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

int run_linsolve_command(const Linsolve_options& options, Streams io);

/// The text of `relgeo help linsolve` below the options.
std::string linsolve_help_footer();

/// Declares the options on the subcommand.         [options.cpp]
void declare_linsolve_options(CLI::App& cmd, Linsolve_options& options);

}  // namespace relgeo::tool
