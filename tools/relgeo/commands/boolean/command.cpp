// tools/relgeo/commands/boolean/command.cpp — `relgeo boolean`: the Boolean
// of two closed meshes under a kernel, its validation, optional outputs and
// CGAL's corefinement as an oracle.
#include <fstream>
#include <ostream>

#include "commands/boolean/command.h"
#include "commands/boolean/facade.h"
#include "commands/boolean/report.h"
#include "relgeo/io/png.h"
#include "relgeo/mesh/mesh_io.h"

namespace relgeo::tool {

int run_boolean_command(const Boolean_command_options& o, Streams io) {
  if (o.a.empty() || o.b.empty()) throw Usage_error("two operands are needed: relgeo boolean A B [--op OP]");
  if (o.levels > 0) return run_subdivision_boolean_command(o, io);
  if (o.fit || !o.polyhedral_output.empty() || !o.tags_a.empty() || !o.tags_b.empty())
    throw Usage_error("--fit, --polyhedral-output, --tags-a and --tags-b need --levels K (K >= 1)");
  if (!o.oracle.empty() && o.oracle != "cgal") throw Usage_error("--oracle takes 'cgal'");
  const Boolean_operation op = parse_boolean_operation(o.op);
  validate_boolean_kernel(o.kernel);
  const Mesh_double a = read_mesh(o.a), b = read_mesh(o.b);
  const Boolean_run run = evaluate_boolean(o.kernel, a, b, op,
                                           Boolean_options{.check_self_intersections = !o.skip_self_intersection_check,
                                                           .rounding = parse_output_rounding(o.rounding),
                                                           .delaunay_retriangulation =
                                                               parse_delaunay_retriangulation(o.retriangulation)});
  std::optional<Oracle_comparison> oracle;
  if (o.oracle == "cgal") oracle = compare_with_cgal(a, b, op, run.mesh);
  if (!o.output.empty()) write_mesh(o.output, run.mesh);
  if (!o.tags_output.empty()) write_feature_tags(o.tags_output, run.mesh.tags);
  if (!o.png.empty()) {
    Render_options ro;
    ro.highlight_creases = true;
    for (const Face_origin& f : run.provenance) ro.face_groups.push_back(f.operand);
    io::write_png(o.png, render_mesh(run.mesh, ro));
  }
  const Boolean_report_input in{o.op, o.a, o.b, &a, &b, &run, oracle ? &*oracle : nullptr};
  const io::Json json = boolean_report_json(in);
  if (!o.report.empty()) {
    std::ofstream f(o.report);
    f << io::dump_json(json) << '\n';
    if (!f) throw io::Unwritable_file("cannot write the report '" + o.report + "'");
  }
  if (o.format == Format::json) io.out << io::dump_json(json) << '\n';
  else io.out << boolean_report_text(in);
  if (!run.ok()) {
    io.err << "relgeo: failure: the Boolean under kernel '" << o.kernel << "' failed: " << run.failure << '\n';
    return exit_failure;
  }
  const bool topology_expected = op != Boolean_operation::symmetric_difference;
  const Solid_report& v = run.validation;
  if (run.certified && topology_expected && !(v.closed.passed() && v.consistently_oriented.passed())) {
    io.err << "relgeo: failure: the result is not a closed oriented surface\n";
    return exit_failure;
  }
  return exit_success;
}

}  // namespace relgeo::tool
