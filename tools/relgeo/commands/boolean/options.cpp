// tools/relgeo/commands/boolean/options.cpp — `relgeo boolean`'s options and help.
#include "cli/options.h"
#include "commands/boolean/command.h"
#include "commands/boolean/facade.h"

namespace relgeo::tool {

std::string boolean_help_footer() {
  const std::string kernels = comma_list(boolean_kernel_names());
  return "\nThe regularised Boolean of the solids bounded by two closed triangle meshes (OFF, OBJ, PLY, STL), exact "
         "under the filtered and exact kernels (relgeo/boolean.h, doc/boolean.md).\n"
         "Kernels: " + kernels + " (default filtered).\n"
         "Operands that are open, non-manifold, misoriented, degenerate, non-finite or self-intersecting are refused "
         "(exit 2, naming the defect and where) before any work; --skip-self-intersection-check leaves out the most "
         "expensive of these checks.\n"
         "Fail-safe and interval kernels give the exact result or fail naming the face pairs they cannot decide "
         "(exit 1); naive kernels give what their arithmetic gives, and the validation says what is wrong.\n"
         "\nOutputs: --output the result (its format from the extension), --tags-output the intersection curves "
         "as crease tags (one 'e a b' line per edge), --report the JSON report, --png a picture (faces of A grey, "
         "of B blue, curves red).\n"
         "--oracle cgal: CGAL's corefinement with Epeck on the same operands: its volume, the volume of the "
         "symmetric difference of the two results (relgeo's exact Boolean) and their Hausdorff distance.\n"
         "\nJSON fields: operation, kernel, kernel_model, certified, status, failure, undecided_pairs, operands, "
         "output, validation (validate_solid on the output's doubles: valid_solid, summary, checks {closed, "
         "edge_manifold, vertex_manifold, consistently_oriented, self_intersection_free, outward_oriented, ...: "
         "status, count, where}, euler_characteristic, components, genus, volume {value, exact, lower, upper}), "
         "exact_self_intersecting_pairs (exact kernel, when the repair changed no face: before rounding), "
         "rounding_error, rounding {method, rounds, defects_before, moved_vertices, flips, collapses, largest_change, "
         "remaining_pairs, remaining_degenerate_faces}, counts, time_s {check, broad_phase, narrow_phase, "
         "retriangulation, labelling, assembly, rounding, total, validation}, [oracle].\n"
         "Rounding the exact result to doubles can make it touch or cross itself (CGAL issue 9154). --rounding "
         "repaired (the default under the filtered and exact kernels) repairs that by local changes decided exactly "
         "(moves by one unit in the last place, flips under slivers, collapses of edges within 1e-9 of the model's "
         "size) and fails the run (exit 1) when it cannot; --rounding nearest keeps the nearest doubles and the "
         "validation says what crosses.\n"
         "A symmetric difference (xor) touches itself along the intersection curves: its non-manifold edges are "
         "expected.\n"
         "\nWith --levels K (K >= 1) the operands are Loop control meshes (their crease and corner tags from "
         "--tags-a and --tags-b: 'crease a b' and 'corner v' lines) and the Boolean is that of their limit "
         "surfaces (relgeo::subdivision_boolean, thesis Ch. 5): the Boolean of the two limit meshes at level K (the "
         "polyhedral result, --polyhedral-output), its intersection curves mapped to the level-K control meshes, "
         "which are cut and merged along them into one control mesh with the curves tagged as creases (--output, "
         "its tags with --tags-output); --fit moves the control points near the curves (least squares) and keeps "
         "the fitted mesh when it is closer to the polyhedral result; --png draws its limit mesh two levels finer "
         "with the creases in red. The same kernels; --op xor and --oracle are not available with --levels (a "
         "symmetric difference touches itself along the curves: no Loop control mesh represents it). The validation "
         "certifies what it can and reports the rest as undecided or not checked, never as valid.\n"
         "JSON fields with --levels: operation, kernel, kernel_model, certified, status, failure, level, fitted, "
         "operands, output {vertices, faces, creases, corners, curve_vertices}, counts {curve_vertices, "
         "curve_edges, bad_faces [A, B], fitted_vertices}, distance {subdivision_to_polyhedral, "
         "subdivision_to_polyhedral_fitted: limit_to_polyhedral, polyhedral_to_limit, hausdorff, mean, samples}, "
         "validation (validate_subdivision_solid: certified, summary, checks {closed, edge_manifold, "
         "vertex_manifold, consistently_oriented, valid_tags, separated_pieces, adjacent_pieces: status, count, "
         "where, note}, candidate_pairs, separated_pairs, adjacent_pairs, certified_adjacent_pairs, certified_regions, undecided_pairs), "
         "polyhedral {status, "
         "failure, undecided_pairs, output, validation (as above), counts, time_s}, time_s {limit_meshes, "
         "boolean, mapping, fitting, distance, validation, layer, total}.\n";
}

void add_rounding_option(CLI::App& cmd, std::string& rounding) {
  cmd.add_option("--rounding", rounding,
                 "repaired: repair what rounding to doubles breaks (default); nearest: nearest doubles only")
      ->default_str("repaired");
}

void add_retriangulation_option(CLI::App& cmd, std::string& retriangulation) {
  cmd.add_option("--retriangulation", retriangulation,
                 "delaunay: each split face a constrained Delaunay triangulation (default); insertion: the "
                 "triangulation of the insertion order (needles; for comparison)")
      ->default_str("delaunay");
}

void declare_boolean_options(CLI::App& cmd, Boolean_command_options& o) {
  cmd.add_option("a", o.a, "the first operand's mesh file")->type_name("A");
  cmd.add_option("b", o.b, "the second operand's mesh file")->type_name("B");
  cmd.add_option("--op", o.op, "union, intersection, difference (A - B) or xor")->default_str("union");
  add_kernel_option(cmd, o.kernel, "filtered");
  add_output_option(cmd, o.output, "output", "write the result mesh (format from the extension)");
  add_output_option(cmd, o.tags_output, "tags-output", "write the intersection curves as a crease-tag side file");
  add_output_option(cmd, o.report, "report", "write the JSON report");
  add_output_option(cmd, o.png, "png", "write a picture of the result with its intersection curves");
  cmd.add_option("--oracle", o.oracle, "cgal: compare with CGAL's corefinement (Epeck)")->type_name("cgal");
  cmd.add_flag("--skip-self-intersection-check", o.skip_self_intersection_check,
               "do not test the operands for self-intersections (the other checks still run)");
  add_rounding_option(cmd, o.rounding);
  add_retriangulation_option(cmd, o.retriangulation);
  cmd.add_option("--levels", o.levels, "K >= 1: the Boolean of two Loop subdivision solids at level K")->type_name("K");
  cmd.add_option("--tags-a", o.tags_a, "with --levels: crease/corner tag file of A")->type_name("FILE");
  cmd.add_option("--tags-b", o.tags_b, "with --levels: crease/corner tag file of B")->type_name("FILE");
  cmd.add_flag("--fit", o.fit, "with --levels: fit the control points near the curves (kept when closer)");
  add_output_option(cmd, o.polyhedral_output, "polyhedral-output",
                    "with --levels: write the Boolean of the two limit meshes");
  add_format_option(cmd, o.format);
}

}  // namespace relgeo::tool
