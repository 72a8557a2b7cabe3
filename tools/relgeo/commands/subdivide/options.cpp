// tools/relgeo/commands/subdivide/options.cpp — `relgeo subdivide`'s options.
#include "cli/options.h"
#include "commands/subdivide/command.h"

namespace relgeo::tool {

void declare_subdivide_options(CLI::App& cmd, Subdivide_options& o) {
  add_file_operand(cmd, o.input, "input", "the mesh file, '-' for OFF on standard input");
  add_file_operand(cmd, o.output, "output",
                   "the mesh file to write (.off, .obj, .ply, .stl; default: INPUT_L<K>.off in this folder)");
  add_value_option(cmd, "--levels", o.levels, "refinement levels, 0..12", "K", "1");
  cmd.add_flag("--limit", o.limit, "write the limit mesh (vertices at their limit positions)");
  cmd.add_flag("--bounds", o.bounds, "compute the per-face error bounds of the limit mesh");
  add_kernel_option(cmd, o.kernel, "double", "the kernel (see below)");
  cmd.add_option("--tags", o.tags, "crease/corner tag file")->type_name("FILE");
  add_output_option(cmd, o.report, "report", "also write the JSON report to this file");
  add_value_option(cmd, "--rules", o.rules, "crease rules: hoppe or blz", "RULES", "hoppe");
  add_value_option(cmd, "--samples", o.samples, "sample grid per face side (power of two; 0: none)", "N", "8");
  add_format_option(cmd, o.format);
}

}  // namespace relgeo::tool
