// tools/relgeo/commands/linsolve/options.cpp — `relgeo linsolve`'s options.
#include "cli/options.h"
#include "commands/linsolve/command.h"

namespace relgeo::tool {

void declare_linsolve_options(CLI::App& cmd, Linsolve_options& o) {
  add_file_operand(cmd, o.input, "input", "the matrix file ([A | b], one row per line), '-' for standard input");
  cmd.add_option("--example", o.example, "a built-in system instead of a file: thesis")->type_name("NAME");
  cmd.add_option("--hilbert", o.hilbert, "the N x N Hilbert system (b = H * ones) in double, instead of a file")
      ->check(CLI::Range(1, 500))
      ->type_name("N");
  add_value_option(cmd, "--method", o.method, "none, partial, complete, eigen-partial, eigen-full", "METHOD",
                   "partial");
  add_value_option(cmd, "--scalar", o.scalar, "the arithmetic: float, double, long-double, mpfr-BITS, rational",
                   "SCALAR", "double");
  add_value_option(cmd, "--exact-limit", o.exact_limit, "compute the exact solution (forward error) for n <= this", "N",
                   "100");
  add_format_option(cmd, o.format);
}

}  // namespace relgeo::tool
