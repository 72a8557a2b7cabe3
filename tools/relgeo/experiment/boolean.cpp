// tools/relgeo/experiment/boolean.cpp — the "boolean" section of `relgeo
// experiment` (thesis Ch. 5, the mesh engine): the everyday cases of a mesh
// Boolean (general position, touching along a face, nested, identical
// operands) under the kernels double, failsafe, filtered and exact, each
// result validated (closed, manifold, oriented, no self-intersection: exact
// test on its doubles) and its volume compared with CGAL's corefinement on
// Epeck (the oracle, once per case). A certified kernel must give a valid
// result with the oracle's volume (relative 1e-12) or fail honestly: a
// certified result that is invalid before rounding or off is a failure of
// the section. Rounding the exact vertices to doubles can make a valid result
// cross itself (CGAL issue 9154): the table counts those crossings, the exact
// kernel's row says whether its result crossed itself before rounding, and
// the headline counts a result valid only when the mesh the user receives
// (doubles) is. The engine repairs what the rounding breaks (Boolean_options::
// rounding, mesh/rounding_repair.h): each repaired result is listed with what
// the repair did; a certified result that still crosses itself in doubles
// (a repair that did not converge fails the Boolean) is listed, not a
// failure of the run.
// Pictures (PNG) in DIR/boolean/: the union of two spheres and of the torus
// with a sphere, faces coloured by operand, intersection curves in red.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "commands/boolean/facade.h"
#include "commands/boolean/report.h"
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

// The output bounds a solid, up to what the operation and rounding may
// legitimately give: closed, consistently oriented, no degenerate face, a
// positive volume (exact sum) and no failed outward-orientation test (that
// test needs a manifold mesh without crossings: two solids sharing an edge,
// a symmetric difference, a rounded crossing leave it not checked).
// Manifoldness and crossings are columns of their own.
bool bounds_a_solid(const Solid_report& v) {
  return v.closed.passed() && v.consistently_oriented.passed() && v.non_degenerate_faces.passed() &&
         v.outward_oriented.status != Check_status::fail && v.volume.computed && v.volume.lower > 0;
}

/// One run judged: is its result a valid solid, before and after rounding,
/// and how far is its volume from the oracle's.
struct Run_verdict {
  std::string status;
  /// A certified Boolean whose only failure is a repair of the rounding that
  /// did not converge: valid before rounding, listed as crossing in doubles.
  bool rounding_failed = false;
  bool solid = false, manifold = false;
  std::size_t crossings = 0;
  bool valid_exact = false;  ///< solid, and no crossing before rounding (where known)
  bool valid = false;        ///< what the user receives: the doubles, crossings of the rounded mesh included
  double relative_volume_error = 0;  ///< NaN: no oracle
};

Run_verdict judge(const Boolean_run& run, std::string status, const Oracle_comparison& oracle) {
  Run_verdict r;
  r.status = std::move(status);
  const Solid_report& v = run.validation;
  r.rounding_failed = run.certified && !run.ok() && run.failure.rfind("rounding:", 0) == 0;
  r.solid = (run.ok() || r.rounding_failed) && bounds_a_solid(v);
  r.manifold = v.edge_manifold.passed() && v.vertex_manifold.passed();
  r.crossings = v.self_intersection_free.count;
  // The Boolean's own crossings: those of the exact result, known under
  // the exact kernel (the filtered kernel's result has the same faces: the
  // exact kernel runs on it through its Double_point_kernel).
  const bool crossing_free = !run.exact_self_intersecting_pairs || *run.exact_self_intersecting_pairs == 0;
  r.valid_exact = r.solid && crossing_free;
  r.valid = r.valid_exact && r.crossings == 0;
  // No oracle when CGAL's corefinement refuses (it cannot output a
  // non-manifold edge): NaN, shown as "no oracle".
  const double volume = v.volume.value;
  r.relative_volume_error = !oracle.cgal_ok         ? std::nan("")
                            : oracle.cgal_volume != 0 ? std::abs(volume - oracle.cgal_volume) / std::abs(oracle.cgal_volume)
                                                      : std::abs(volume);
  return r;
}

Json run_json(const Boolean_case& c, const std::string& kernel, const Boolean_run& run, const Run_verdict& r,
              const Oracle_comparison& oracle) {
  const Solid_report& v = run.validation;
  const double rel = r.relative_volume_error;
  return Json{{"case", c.name},
              {"operation", std::string(to_string(c.op))},
              {"kernel", kernel},
              {"kernel_model", run.kernel_model},
              {"status", r.status},
              {"certified", run.certified},
              {"faces", run.mesh.faces.size()},
              {"valid", r.valid},
              {"valid_before_rounding", r.valid_exact},
              {"validation", run.ok() || r.rounding_failed ? Json(run.validation.summary()) : Json(nullptr)},
              {"rounding", rounding_repair_json(run.rounding, run.rounding_method)},
              {"rounded_self_intersecting_pairs", r.crossings},
              {"exact_self_intersecting_pairs",
               run.exact_self_intersecting_pairs ? Json(*run.exact_self_intersecting_pairs) : Json(nullptr)},
              {"volume", v.volume.value},
              {"oracle_volume", oracle.cgal_ok ? Json(oracle.cgal_volume) : Json(nullptr)},
              {"relative_volume_error", std::isnan(rel) ? Json(nullptr) : Json(rel)},
              {"euler_characteristic", v.euler_characteristic ? Json(*v.euler_characteristic) : Json(nullptr)},
              {"time_s", boolean_timing_json(run.time)}};
}

/// A note listing `items` under `title` (none when the list is empty).
void add_list_note(Section_report& rep, const std::string& title, const std::vector<std::string>& items) {
  if (items.empty()) return;
  std::string listed = title + ":\n";
  for (const std::string& r : items) listed += "  " + r + "\n";
  rep.add_note(listed + "\n");
}

/// The section's runs: every case under every kernel, into one table, the
/// run records, the pictures and the counts of certified results.
class Boolean_experiment {
 public:
  explicit Boolean_experiment(const Experiment_context& ctx) : ctx_(ctx) { table_.set_left_columns(4); }

  Section_report run() && {
    for (const Boolean_case& c : boolean_cases(ctx_.quick)) run_case(c);
    return std::move(*this).finish();
  }

 private:
  void run_case(const Boolean_case& c) {
    ctx_.progress(c.name + ": CGAL's corefinement (Epeck)");
    // The oracle's volume does not depend on the result passed: give it none.
    const Oracle_comparison oracle = compare_with_cgal(c.a, c.b, c.op, Mesh_double{});
    for (const std::string kernel : {"double", "failsafe", "filtered", "exact", "cgal-epeck"}) {
      ctx_.progress(c.name + ": " + kernel);
      Boolean_run run;
      std::string status;
      try {
        run = evaluate_boolean(kernel, c.a, c.b, c.op, Boolean_options{});
        status = run.ok() ? "ok" : "failed";
      } catch (const std::exception& e) {
        run.status = Boolean_run::Status::failed;  // refused: no result
        status = std::string("refused: ") + e.what();
      }
      const Run_verdict r = judge(run, std::move(status), oracle);
      tally(c, kernel, run, r);
      add_row(c, kernel, run, r);
      rows_.push_back(run_json(c, kernel, run, r, oracle));
      if (c.picture && kernel == "filtered" && run.ok()) add_picture(c, run);
    }
    table_.add_rule();
  }

  /// The repaired roundings, and the certified results: valid as delivered,
  /// valid only before rounding, or a failure of the section.
  void tally(const Boolean_case& c, const std::string& kernel, const Boolean_run& run, const Run_verdict& r) {
    const bool delivered = run.ok() || r.rounding_failed;
    if (run.certified && run.rounding.rounds > 0 && delivered)
      repaired_.push_back(c.name + " under " + kernel + ": " + std::to_string(run.rounding.defects_before) +
                          " defects after nearest rounding; " + std::to_string(run.rounding.moved_vertices) +
                          " vertices moved, " + std::to_string(run.rounding.flips) + " flips, " +
                          std::to_string(run.rounding.collapses) + " collapses, largest change " +
                          measure_text(run.rounding.largest_change) + (r.rounding_failed ? " (did not converge)" : ""));
    if (!run.certified || !delivered) return;
    ++certified_runs_;
    const double rel = r.relative_volume_error;
    const bool on_volume = std::isnan(rel) || rel <= 1e-12;
    if (r.valid_exact && on_volume) {
      ++certified_exact_;
      if (r.valid) ++certified_delivered_;
      else rounded_crossings_.push_back(c.name + " under " + kernel + ": " + std::to_string(r.crossings) +
                                        " crossing face pairs after rounding");
    } else {
      rep_.failures.push_back(
          c.name + " under " + kernel + ": certified result " +
          (r.valid_exact ? "off the oracle's volume by " + measure_text(rel) : std::string("not valid")));
    }
  }

  void add_row(const Boolean_case& c, const std::string& kernel, const Boolean_run& run, const Run_verdict& r) {
    const double rel = r.relative_volume_error;
    const auto yes_no = [&](bool x) { return run.ok() ? std::string(x ? "yes" : "NO") : std::string("-"); };
    table_.add_row({c.name, std::string(to_string(c.op)), kernel, r.status.substr(0, 40),
                    std::to_string(run.mesh.faces.size()), yes_no(r.solid), yes_no(r.manifold),
                    run.ok() ? std::to_string(r.crossings) : "-",
                    run.exact_self_intersecting_pairs ? std::to_string(*run.exact_self_intersecting_pairs) : "-",
                    run.ok() ? measure_text(run.validation.volume.value) : "-",
                    !run.ok()         ? "-"
                    : std::isnan(rel) ? "no oracle"
                                      : measure_text(rel),
                    std::to_string(run.mesh.tags.creases().size()), format_fixed(run.time.total(), 4)});
  }

  void add_picture(const Boolean_case& c, const Boolean_run& run) {
    Render_options ro;
    ro.highlight_creases = true;
    for (const Face_origin& f : run.provenance) ro.face_groups.push_back(f.operand);
    std::string file = c.name;
    std::replace(file.begin(), file.end(), ' ', '_');
    const auto path = ctx_.section_dir() / (file + ".png");
    io::write_png(path.string(), render_mesh(run.mesh, ro));
    pictures_.push_back({ctx_.relative(path), c.name + " (filtered): faces by operand, intersection curves red"});
  }

  Section_report finish() && {
    rep_.json["runs"] = rows_;
    rep_.json["notes"] =
        "solid = closed, consistently oriented, no degenerate face, positive volume, outward orientation not failed "
        "(validate_solid, exact tests on the output's doubles); manifold = edge- and vertex-manifold; crossings = self-intersecting face pairs of the "
        "rounded output; exact cr. = the same before rounding (exact kernel); valid = solid and no crossing, in "
        "the rounded output and before rounding where known (exact kernel); valid_before_rounding = the same without "
        "the rounded output's crossings; rel. error = |volume - CGAL Epeck corefinement volume| / |CGAL volume|; curves = crease edges";
    rep_.add_note(
        "Mesh Booleans (thesis Ch. 5) under every kernel, against CGAL's corefinement on Epeck (the oracle).\n"
        "solid = closed, consistently oriented, no degenerate face, positive volume (exact tests on the output's doubles);\n"
        "manifold: two solids sharing only an edge give a non-manifold edge, as they must; crossings = face pairs of\n"
        "the rounded output that cross (rounding exact points to doubles can do that, CGAL issue 9154), exact cr. =\n"
        "the same before rounding (exact kernel). rel. error = |volume - oracle volume| / |oracle volume| (no oracle:\n"
        "CGAL's corefinement refuses to output a non-manifold edge).\n"
        "Certified kernels (failsafe, filtered, exact) must return a solid without crossings before rounding and with\n"
        "the oracle's volume, or fail and say why; double may return anything (what a naive implementation gives).\n"
        "Pictures: DIR/boolean/*.png.\n\n");
    rep_.add_table(table_);
    rep_.add_gallery("Unions: faces coloured by operand, intersection curves in red (kernel filtered)",
                     std::move(pictures_));
    rep_.json["rounded_crossings"] = rounded_crossings_;
    rep_.json["rounding_repaired"] = repaired_;
    add_list_note(rep_, "Certified results whose rounding to doubles was repaired (Boolean_options::rounding)", repaired_);
    add_list_note(rep_, "Certified results valid before rounding that cross themselves in doubles", rounded_crossings_);
    rep_.add_headline("Certified Boolean results valid as delivered (in doubles) and on the oracle's volume",
                      std::to_string(certified_delivered_) + " of " + std::to_string(certified_runs_));
    rep_.add_headline("Certified Boolean results valid before rounding and on the oracle's volume",
                      std::to_string(certified_exact_) + " of " + std::to_string(certified_runs_));
    return std::move(rep_);
  }

  const Experiment_context& ctx_;
  Section_report rep_;
  Text_table table_{{"case", "op", "kernel", "status", "faces", "solid", "manifold", "crossings", "exact cr.", "volume",
                     "rel. error", "curves", "time s"}};
  Json rows_ = Json::array();
  std::vector<Picture> pictures_;
  std::size_t certified_runs_ = 0, certified_exact_ = 0, certified_delivered_ = 0;
  std::vector<std::string> rounded_crossings_;
  std::vector<std::string> repaired_;  ///< results whose rounding was repaired, with what the repair did
};

}  // namespace

Section_report boolean_section(const Experiment_context& ctx) { return Boolean_experiment(ctx).run(); }

}  // namespace relgeo::tool
