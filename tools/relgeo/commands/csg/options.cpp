// tools/relgeo/commands/csg/options.cpp — `relgeo csg`'s options and help.
#include "cli/options.h"
#include "commands/boolean/facade.h"
#include "commands/csg/command.h"

namespace relgeo::tool {

std::string csg_help_footer() {
  const std::string kernels = comma_list(csg_kernel_names());
  return "\nEvaluates a CSG tree of closed triangle meshes with relgeo's Boolean (relgeo::csg, doc/boolean.md, "
         "\"CSG trees\"). TREE.json is a node: {\"op\": \"union\" | \"intersection\" | \"difference\", \"args\": "
         "[NODE, NODE, ...]} or a leaf {\"mesh\": \"file.off\"} (OFF, OBJ, PLY, STL; paths relative to the JSON "
         "file). A difference is its first argument minus all the others; unions and intersections of many "
         "arguments are reduced pairwise.\n"
         "The leaves are checked once (closed, oriented, manifold, no degenerate face, no self-intersection); "
         "every intermediate result is validated and repaired after rounding (--rounding repaired, the "
         "default), and is not checked again as the next operand.\n"
         "Kernels: " + kernels + " (default filtered).\n"
         "--intermediates exact (with --kernel exact) keeps every intermediate result in exact rationals, "
         "validated exactly, and rounds only the root (doc/boolean.md, \"Exact chains\"): the root is the "
         "exact result rounded once, at a cost that grows with every step (the coordinates' bits, reported "
         "per step).\n"
         "A bad tree (unknown op, fewer than two args, a missing or unreadable file, a leaf that is not a valid "
         "solid) exits with 2 and one line naming the node (root, root.1 = root's second argument, ...). A step "
         "that fails (a rounding that cannot be repaired, a result that is not a valid solid) exits with 1 and "
         "names it; --output then holds that step's result.\n"
         "JSON fields: tree, kernel, intermediates, status, failure, steps [{node, operation, ok, failure, "
         "faces, volume, validation, rounding {method, rounds, defects_before, moved_vertices, flips, collapses, "
         "largest_change, remaining_pairs, remaining_degenerate_faces}, coordinate_bits (exact intermediates: "
         "the largest coordinate's numerator and denominator bits), seconds}], output {vertices, faces, volume, "
         "rounding (of the output: the last step's, or the exact root's), validation}, seconds (the Booleans; "
         "reading the files not included), total_seconds (files read and written included).\n";
}

void declare_csg_options(CLI::App& cmd, Csg_command_options& o) {
  cmd.add_option("tree", o.tree, "the CSG tree (JSON)")->type_name("TREE.json");
  add_kernel_option(cmd, o.kernel, "filtered");
  add_output_option(cmd, o.output, "output", "write the root's solid (format from the extension)");
  add_output_option(cmd, o.report, "report", "write the JSON report");
  add_rounding_option(cmd, o.rounding);
  add_retriangulation_option(cmd, o.retriangulation);
  cmd.add_option("--intermediates", o.intermediates,
                 "rounded: every result rounded to doubles and repaired (default); exact: kept exact, the root "
                 "rounded once (--kernel exact)")
      ->default_str("rounded");
  cmd.add_flag("--skip-self-intersection-check", o.skip_self_intersection_check,
               "do not test the leaves for self-intersections (the other checks still run)");
  add_format_option(cmd, o.format);
}

}  // namespace relgeo::tool
