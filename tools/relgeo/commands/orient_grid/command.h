// tools/relgeo/commands/orient_grid/command.h — `relgeo orient-grid`.
#pragma once

#include <string>

#include "cli/text.h"

namespace CLI {
class App;
}  // namespace CLI

namespace relgeo::tool {

struct Orient_grid_options {
  std::string p, q, r;  ///< "X,Y" each, unless `triple` is given
  std::string triple;   ///< "a", "b" or "c" (Kettner et al.); none of p, q, r, triple: "a"
  std::string kernel;   ///< empty: compare the standard kernels (standard_grid_kernels)
  int size = 256;
  std::string png;      ///< picture file, empty for none (several kernels: one per kernel)
  int scale = 2;        ///< pixels per cell in the picture
  Format format = Format::text;
};

int run_orient_grid(const Orient_grid_options& options, Streams io);

/// The kernels compared when no --kernel is given: relgeo's own, without
/// MPFR (float, double, long-double, failsafe, interval, filtered, exact).
std::vector<std::string> standard_grid_kernels();

/// The text of `relgeo help orient-grid` below the options.
std::string orient_grid_help_footer();

/// Declares the options on the subcommand.         [options.cpp]
void declare_orient_grid_options(CLI::App& cmd, Orient_grid_options& options);

}  // namespace relgeo::tool
