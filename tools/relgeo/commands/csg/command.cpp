// tools/relgeo/commands/csg/command.cpp — `relgeo csg`: read the tree and its
// meshes, evaluate, write the solid and the report.
#include "commands/csg/command.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "commands/csg/facade.h"
#include "relgeo/core/internal/stopwatch.h"
#include "relgeo/io/errors.h"
#include "relgeo/io/json.h"
#include "relgeo/mesh/mesh_io.h"

namespace relgeo::tool {
namespace {

std::string report_text(const Csg_result& r) {
  std::ostringstream s;
  char buf[256];
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const Csg_step& st = r.steps[i];
    std::snprintf(buf, sizeof buf, "step %-3zu %-14s %-12s %-7s %7zu faces  volume %.12g  %.4f s", i + 1, st.node.c_str(),
                  std::string(to_string(st.operation)).c_str(), st.ok ? "ok" : "FAILED", st.faces, st.volume, st.seconds);
    s << buf;
    if (st.rounding.defects_before)
      s << "  (rounding: " << st.rounding.defects_before << " defects repaired)";
    if (st.coordinate_bits) s << "  " << st.coordinate_bits << "-bit coordinates";
    s << "  " << st.validation << "\n";
  }
  if (!r.validation.empty()) {  // exact intermediates: the root rounded once
    s << "rounding         the exact root to doubles";
    if (r.rounding.defects_before) s << ", " << r.rounding.defects_before << " defects repaired";
    s << ": " << r.validation << "\n";
  }
  s << "status           " << (r.ok() ? "ok" : "failed: " + r.failure) << "\n";
  s << "output           " << r.mesh.vertices.size() << " vertices, " << r.mesh.faces.size() << " faces\n";
  std::snprintf(buf, sizeof buf, "%.4f s for %zu Booleans", r.seconds, r.steps.size());
  s << "time             " << buf << "\n";
  return s.str();
}

}  // namespace

int run_csg_command(const Csg_command_options& o, Streams io) {
  if (o.tree.empty()) throw Usage_error("a tree is needed: relgeo csg TREE.json");
  validate_csg_kernel(o.kernel);  // before any file is read
  internal::Stopwatch clock;
  const Csg_options options =
      csg_options(o.rounding, o.retriangulation, !o.skip_self_intersection_check, o.intermediates, o.kernel);
  const Csg_node tree = parse_csg_tree(o.tree);
  const Csg_result r = evaluate_csg(o.kernel, tree, options);
  if (!o.output.empty()) write_mesh(o.output, r.mesh);
  const io::Json json = csg_report_json(o.tree, o.kernel, o.rounding, r, clock.elapsed(), options.intermediates);
  if (!o.report.empty()) {
    std::ofstream f(o.report);
    f << io::dump_json(json) << '\n';
    if (!f) throw io::Unwritable_file("cannot write the report '" + o.report + "'");
  }
  if (o.format == Format::json) io.out << io::dump_json(json) << '\n';
  else io.out << report_text(r);
  if (!r.ok()) {
    io.err << "relgeo: failure: " << r.failure << '\n';
    return exit_failure;
  }
  return exit_success;
}

}  // namespace relgeo::tool
