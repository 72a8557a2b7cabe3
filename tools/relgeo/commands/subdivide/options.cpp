// tools/relgeo/commands/subdivide/options.cpp — `relgeo subdivide`'s options.
#include "cli/options.h"
#include "commands/subdivide/command.h"

namespace relgeo::tool {

void declare_subdivide_options(CLI::App& cmd, Subdivide_options& o) {
  add_file_operand(cmd, o.input, "input", "the mesh file, '-' for OFF on standard input");
  add_file_operand(cmd, o.output, "output",
                   "the mesh file to write (.off, .obj, .ply, .stl; default: INPUT_L<K>.off in this folder)");
  cmd.add_option("--levels", o.levels, "refinement levels, 0..12")->type_name("K")->default_str("1");
  cmd.add_flag("--limit", o.limit, "write the limit mesh (vertices at their limit positions)");
  cmd.add_flag("--bounds", o.bounds, "compute the per-face error bounds of the limit mesh");
  add_kernel_option(cmd, o.kernel, "double", "the kernel (see below)");
  cmd.add_option("--tags", o.tags, "crease/corner tag file")->type_name("FILE");
  add_output_option(cmd, o.report, "report", "also write the JSON report to this file");
  cmd.add_option("--rules", o.rules, "crease rules: hoppe or blz")->type_name("RULES")->default_str("hoppe");
  cmd.add_option("--samples", o.samples, "sample grid per face side (power of two; 0: none)")
      ->type_name("N")
      ->default_str("8");
  add_format_option(cmd, o.format);
}

}  // namespace relgeo::tool
