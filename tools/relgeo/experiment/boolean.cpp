// tools/relgeo/experiment/boolean.cpp — the "boolean" section of `relgeo
// experiment` (thesis Ch. 5, the mesh engine): the everyday cases of a mesh
// Boolean (general position, touching along a face, nested, identical
// operands) under the kernels double, failsafe, filtered and exact, each
// result validated (closed, manifold, oriented, no self-intersection: exact
// test on its doubles) and its volume compared with CGAL's corefinement on
// Epeck (the oracle, once per case). A certified kernel must give a valid
// result with the oracle's volume (relative 1e-12) or fail honestly: a
// certified result that is invalid or off is a failure of the section.
// Pictures (PNG) in DIR/boolean/: the union of two spheres and of the torus
// with a sphere, faces coloured by operand, intersection curves in red.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "commands/boolean/facade.h"
#include "experiment/section.h"
#include "relgeo/mesh/shapes.h"
#include "render/mesh_render.h"

namespace relgeo::tool {

namespace {

using io::Json;

struct Boolean_case {
  std::string name;
  Mesh_double a, b;
  Boolean_operation op;
  bool picture = false;
};

std::vector<Boolean_case> boolean_cases(bool quick) {
  const int sphere_level = quick ? 2 : 3;
  const Mesh_double sphere = icosphere(sphere_level);
  return {
      {"cube - moved cube", cube(0, 0, 0, 1), cube(0.5, 0.25, 0.125, 1), Boolean_operation::difference},
      {"sphere u sphere", sphere, icosphere(sphere_level, {0.6, 0.3, 0.2}), Boolean_operation::union_of, true},
      {"sphere n sphere", sphere, icosphere(sphere_level, {0.6, 0.3, 0.2}), Boolean_operation::intersection},
      {"torus u sphere", torus(1, 0.3, 24, 12), rigidly_moved(icosphere(2), 0.3, 0.2, {0, 0, 0.05}),
       Boolean_operation::union_of, true},
      {"cubes sharing a face", cube(0, 0, 0, 1), cube(1, 0, 0, 1), Boolean_operation::union_of},
      {"cubes sharing an edge", cube(0, 0, 0, 1), cube(1, 1, 0, 1), Boolean_operation::union_of},
      {"sphere in cube", cube(-2, -2, -2, 4), sphere, Boolean_operation::difference},
      {"sphere n itself", sphere, sphere, Boolean_operation::intersection},
      {"sphere xor moved", sphere, icosphere(sphere_level, {0.6, 0.3, 0.2}), Boolean_operation::symmetric_difference},
  };
}

std::string g3(double v) { return measure_text(v, 3); }

// "valid" when the output bounds a solid: closed, manifold, oriented, without
// degenerate faces or self-intersections (the symmetric difference may touch
// itself along the curves: only closed and oriented are asked of it).
bool is_valid(const Mesh_checks& c, Boolean_operation op) {
  if (op == Boolean_operation::symmetric_difference) return c.closed && c.oriented;
  return c.closed && c.manifold && c.oriented && c.no_degenerate_faces && c.self_intersecting_pairs == 0;
}

}  // namespace

Section_report boolean_section(const Experiment_context& ctx) {
  Section_report rep;
  const std::vector<std::string> kernels = {"double", "failsafe", "filtered", "exact"};
  Text_table t({"case", "op", "kernel", "status", "faces", "valid", "volume", "rel. error", "curves", "time s"});
  t.set_left_columns(4);
  Json rows = Json::array();
  std::vector<Picture> pictures;
  std::size_t certified_runs = 0, certified_exact = 0;
  for (const Boolean_case& c : boolean_cases(ctx.quick)) {
    ctx.progress(c.name + ": CGAL's corefinement (Epeck)");
    // The oracle's volume does not depend on the result passed: give it none.
    const Oracle_comparison oracle = compare_with_cgal(c.a, c.b, c.op, Mesh_double{});
    for (const std::string& kernel : kernels) {
      ctx.progress(c.name + ": " + kernel);
      Boolean_run run;
      std::string status;
      try {
        run = evaluate_boolean(kernel, c.a, c.b, c.op, Boolean_options{});
        status = run.ok ? "ok" : "failed";
      } catch (const std::exception& e) {
        status = std::string("refused: ") + e.what();
      }
      const Mesh_checks checks = check_output(run.output, /*self_intersections=*/run.ok);
      const bool valid = run.ok && is_valid(checks, c.op);
      const double rel = oracle.cgal_ok && oracle.cgal_volume != 0
                             ? std::abs(checks.volume - oracle.cgal_volume) / std::abs(oracle.cgal_volume)
                             : std::abs(checks.volume);
      if (run.certified && run.ok) {
        ++certified_runs;
        if (valid && rel <= 1e-12) ++certified_exact;
        else
          rep.failures.push_back(c.name + " under " + kernel + ": certified result " +
                                 (valid ? "off the oracle's volume by " + g3(rel) : std::string("not valid")));
      }
      t.add_row({c.name, std::string(to_string(c.op)), kernel, status.substr(0, 40), std::to_string(run.output.faces.size()),
                 run.ok ? (valid ? "yes" : "NO") : "-", run.ok ? g3(checks.volume) : "-", run.ok ? g3(rel) : "-",
                 std::to_string(run.output.tags.creases().size()), format_fixed(run.time.total(), 4)});
      Json j;
      j["case"] = c.name;
      j["operation"] = std::string(to_string(c.op));
      j["kernel"] = kernel;
      j["kernel_model"] = run.kernel_model;
      j["status"] = status;
      j["certified"] = run.certified;
      j["faces"] = run.output.faces.size();
      j["valid"] = valid;
      j["volume"] = checks.volume;
      j["oracle_volume"] = oracle.cgal_volume;
      j["relative_volume_error"] = rel;
      j["euler_characteristic"] = checks.euler_characteristic;
      j["time_s"] = {{"check", run.time.check},           {"broad_phase", run.time.broad_phase},
                     {"narrow_phase", run.time.narrow_phase}, {"retriangulation", run.time.retriangulation},
                     {"labelling", run.time.labelling},   {"assembly", run.time.assembly}};
      rows.push_back(j);
      if (c.picture && kernel == "filtered" && run.ok) {
        Render_options ro;
        ro.highlight_creases = true;
        for (const Face_origin& f : run.provenance) ro.face_groups.push_back(f.operand);
        std::string file = c.name;
        std::replace(file.begin(), file.end(), ' ', '_');
        const auto path = ctx.section_dir() / (file + ".png");
        io::write_png(path.string(), render_mesh(run.output, ro));
        pictures.push_back({ctx.relative(path), c.name + " (filtered): faces by operand, intersection curves red"});
      }
    }
    t.add_rule();
  }
  rep.json["runs"] = rows;
  rep.json["notes"] =
      "valid = closed, edge- and vertex-manifold, oriented, no degenerate face, no self-intersection (exact test on "
      "the output's doubles; xor: closed and oriented); rel. error = |volume - CGAL Epeck corefinement volume| / "
      "|CGAL volume|; curves = crease edges (intersection curves) in the output";
  rep.add_note(
      "Mesh Booleans (thesis Ch. 5) under every kernel, against CGAL's corefinement on Epeck (the oracle):\n"
      "valid = the output bounds a solid (closed, manifold, oriented, no degenerate face, no self-intersection,\n"
      "exact tests on its doubles); rel. error = |volume - oracle volume| / |oracle volume|. Certified kernels\n"
      "(failsafe, filtered, exact) return a valid result with the oracle's volume or fail and say why; double\n"
      "may return anything (its row is what a naive implementation gives). Pictures: DIR/boolean/*.png.\n\n");
  rep.add_table(t);
  rep.add_gallery("Unions: faces coloured by operand, intersection curves in red (kernel filtered)",
                  std::move(pictures));
  rep.add_headline("Certified Boolean results valid and on the oracle's volume",
                   std::to_string(certified_exact) + " of " + std::to_string(certified_runs));
  return rep;
}

}  // namespace relgeo::tool
