// tools/relgeo/commands/orient_grid/options.cpp — `relgeo orient-grid`'s
// options and help.
#include "cli/options.h"
#include "commands/orient_grid/command.h"
#include "commands/orient_grid/picture.h"

namespace relgeo::tool {

std::string orient_grid_help_footer() {
  const std::string standard = comma_list(standard_grid_kernels());
  return "Defaults: without --triple and --p/--q/--r the grid of triple a; without --kernel the standard kernels "
         "(" + standard + ") side by side, one row each.\n"
         "Coordinates are decimal literals, correctly rounded to double; NaN and infinities are refused.\n"
         "Grid triples (--triple, Kettner et al. Figs. 2-4):\n"
         "  a  p = (0.5, 0.5), q = (12, 12), r = (24, 24)\n"
         "  b  p = (0.50000000000002531, 0.5000000000000171), q = (17.300000000000001, "
         "17.300000000000001), r = (24.00000000000005, 24.000000000000053)\n"
         "  c  p = (0.5, 0.5), q = (8.8000000000000007, 8.8000000000000007), r = (12.1, 12.1)\n"
         "\nPicture (--png): " + std::string(orientation_grid_legend) +
         ". With several kernels, one picture per kernel: FILE_<kernel>.png.\n"
         "\nJSON fields (one kernel): kernel, kernel_model, certified, [triple], p, q, r, size, cells, "
         "wrong (= plus_to_zero + minus_to_zero + zero_to_sign + inversions), plus_to_zero, "
         "minus_to_zero, zero_to_sign, inversions, uncertain (never counted as wrong), "
         "correct, status, failure, [png].\n"
         "JSON fields (several kernels): [triple], p, q, r, size, cells, kernels [{kernel, kernel_model, certified, "
         "cells, wrong, plus_to_zero, minus_to_zero, zero_to_sign, inversions, uncertain, correct, status, [png]}], "
         "status, failure.\n";
}

void declare_orient_grid_options(CLI::App& cmd, Orient_grid_options& o) {
  cmd.add_option("--p", o.p, "the base point p; cell (X, Y) is p + (X, Y) * 2^-53")->type_name("X,Y");
  cmd.add_option("--q", o.q, "the point q")->type_name("X,Y");
  cmd.add_option("--r", o.r, "the point r")->type_name("X,Y");
  cmd.add_option("--triple", o.triple, "the p, q, r of Kettner et al.'s grids (instead of --p --q --r)")
      ->check(CLI::IsMember({"a", "b", "c"}))
      ->default_str("a");
  add_kernel_option(cmd, o.kernel, "", "one kernel (listed by 'relgeo help'); default: the standard kernels");
  cmd.add_option("--size", o.size, "cells per side, 1..4096")->check(CLI::Range(1, 4096))->default_str("256");
  add_output_option(cmd, o.png, "png", "write the grid as a PNG picture to this file");
  cmd.add_option("--scale", o.scale, "pixels per cell in the picture, 1..16")
      ->check(CLI::Range(1, 16))
      ->default_str("2");
  add_format_option(cmd, o.format);
}

}  // namespace relgeo::tool
