// tools/relgeo/commands/boolean/subdivision_command.cpp — `relgeo boolean
// --levels K`: the Boolean of two Loop subdivision solids, its validation,
// distances, outputs and picture.
#include <fstream>
#include <ostream>

#include "commands/boolean/command.h"
#include "commands/boolean/subdivision_facade.h"
#include "commands/boolean/subdivision_report.h"
#include "relgeo/io/png.h"
#include "relgeo/mesh/mesh_io.h"

namespace relgeo::tool {

namespace {

// The picture: the result's limit surface (two levels finer than its control
// mesh), its creases (the intersection curves, the operands' creases) in red.
void write_subdivision_png(const std::string& path, const Subdivision_boolean_run& run, const Loop_options& loop) {
  Render_options ro;
  ro.highlight_creases = true;
  io::write_png(path, render_mesh(finer_limit_mesh(run.control, 2, loop), ro));
}

}  // namespace

int run_subdivision_boolean_command(const Boolean_command_options& o, Streams io) {
  if (!o.oracle.empty()) throw Usage_error("--oracle is not available with --levels");
  const Boolean_operation op = parse_boolean_operation(o.op);
  validate_boolean_kernel(o.kernel);
  const Mesh_double a = read_mesh(o.a, Read_options{.tags_path = o.tags_a});
  const Mesh_double b = read_mesh(o.b, Read_options{.tags_path = o.tags_b});
  Subdivision_boolean_options options;
  options.mesh.check_self_intersections = !o.skip_self_intersection_check;
  options.fit = o.fit;
  const Subdivision_boolean_run run = evaluate_subdivision_boolean(o.kernel, a, b, op, o.levels, options);
  if (run.ok()) {
    if (!o.output.empty()) write_mesh(o.output, run.control);
    if (!o.tags_output.empty()) write_feature_tags(o.tags_output, run.control.tags);
    if (!o.png.empty()) write_subdivision_png(o.png, run, options.loop);
  }
  if (!o.polyhedral_output.empty() && run.polyhedral.ok()) write_mesh(o.polyhedral_output, run.polyhedral.mesh);
  const Subdivision_boolean_report_input in{o.op, o.a, o.b, &a, &b, &run};
  const io::Json json = subdivision_boolean_report_json(in);
  if (!o.report.empty()) {
    std::ofstream f(o.report);
    f << io::dump_json(json) << '\n';
    if (!f) throw io::Unwritable_file("cannot write the report '" + o.report + "'");
  }
  if (o.format == Format::json) io.out << io::dump_json(json) << '\n';
  else io.out << subdivision_boolean_report_text(in);
  if (!run.ok()) {
    io.err << "relgeo: failure: the subdivision Boolean under kernel '" << o.kernel << "' failed: " << run.failure << '\n';
    return exit_failure;
  }
  // Undecided and not-checked checks are not defects (the report says which).
  if (run.certified && !run.validation.has_no_defect()) {
    io.err << "relgeo: failure: the result is not a valid subdivision solid: " << run.validation.summary() << '\n';
    return exit_failure;
  }
  return exit_success;
}

}  // namespace relgeo::tool
