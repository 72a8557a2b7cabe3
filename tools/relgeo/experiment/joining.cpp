// tools/relgeo/experiment/joining.cpp — the "joining" section of `relgeo
// experiment` (thesis Ch. 4): naive midpoint sewing against the Whitney
// joiner on the library's joining inputs (written to joining/inputs/ and run
// through `relgeo join`'s path, filtered kernel): absolute and normal-vector
// errors before and after, flipped triangles and overlaps in (u,v)
// (certified), seams, time; a (u,v) picture of every result.
// The section fails (exit 1) when a Whitney result is not valid (a flip, an
// overlap, an open seam, a guarantee that does not hold) or naive sewing no
// longer folds the folding input (the baseline the thesis' figures show).
#include <algorithm>
#include <string>
#include <vector>

#include "commands/join/facade.h"
#include "commands/join/picture.h"
#include "experiment/joining_inputs.h"
#include "experiment/section.h"

namespace relgeo::tool {

namespace {

using io::Json;

/// The section's runs: every input under naive sewing and the Whitney
/// joiner, into one table, the run records, the pictures and the flip counts.
class Joining_experiment {
 public:
  explicit Joining_experiment(const Experiment_context& ctx) : ctx_(ctx), dir_(ctx.section_dir()) {
    table_.set_left_columns(2);
  }

  Section_report run() && {
    const std::vector<Joining_input> inputs = write_joining_inputs(dir_ / "inputs");
    rep_.add_note(
        "Mesh patches joined to trimmed faces (thesis Ch. 4): naive midpoint sewing (Sec. 4.1) against the Whitney "
        "joiner (Sec. 4.3), kernel filtered for the certified checks. Inputs: the library's test models, written to " +
        ctx_.relative(dir_ / "inputs") +
        "/ (repeat a row with relgeo join NAME.json --mesh NAME_0.off --mesh NAME_1.off ... --method M).\n"
        "abs = largest |height| over a face, nve = largest slope of the height field between two corners of a "
        "triangle (normal-vector error), both the largest over the faces; flips and overlaps in (u,v), certified.\n\n");
    for (const Joining_input& in : inputs) {
      for (const std::string method : {"naive", "whitney"}) run_method(in, method);
      table_.add_rule();
    }
    return std::move(*this).finish(inputs.size());
  }

 private:
  void run_method(const Joining_input& in, const std::string& method) {
    ctx_.progress(in.name + " " + method);
    Join_tool_options o;
    o.surface = in.surface;
    o.meshes = in.meshes;
    o.method = method;
    const std::string stem = in.name + "_" + method;
    const Join_tool_result r = run_join_tool(o, (dir_ / (stem + ".off")).string(), true);
    const Join_report& j = r.report;
    const std::size_t flips = total(j, [](const auto& f) { return f.orientation_after.flipped; });
    const double abs_before = largest(j, [](const auto& f) { return f.before.absolute; });
    const double abs_after = largest(j, [](const auto& f) { return f.after.absolute; });
    const double nve_before = largest(j, [](const auto& f) { return f.before.normal_vector; });
    const double nve_after = largest(j, [](const auto& f) { return f.after.normal_vector; });
    table_.add_row({in.name, method, std::to_string(j.vertices), std::to_string(j.triangles), measure_text(abs_before),
                    measure_text(abs_after), measure_text(nve_before), measure_text(nve_after), std::to_string(flips),
                    std::to_string(total(j, [](const auto& f) { return f.overlaps_after; })),
                    j.watertight_seams ? "closed" : "open",
                    r.status + (r.failure.empty() ? "" : " (" + r.failure + ")"), duration_text(j.total_seconds)});
    const auto svg = add_pictures(in, method, stem, r, flips);
    Json run = r.json;
    run["input"] = in.name;
    run["svg"] = ctx_.relative(svg);
    runs_.push_back(std::move(run));
    check_run(in, method, r, flips);
  }

  /// The result in (u,v), and for the folding input the seam of face 0 in
  /// detail (its strip is 0.005 wide); returns the first picture's path.
  std::filesystem::path add_pictures(const Joining_input& in, const std::string& method, const std::string& stem,
                                     const Join_tool_result& r, std::size_t flips) {
    const auto svg = dir_ / (stem + ".svg");
    join_picture(r.pictures, in.name + ", " + method + ": " + std::to_string(flipped_in_picture(r.pictures)) +
                                 " flipped triangle(s) in (u,v)")
        .write(svg.string());
    pictures_.push_back({ctx_.relative(svg), in.name + ", " + method + " (" + std::to_string(flips) + " flipped)"});
    if (in.name == "folding" && !r.pictures.empty()) {
      const double window[4] = {0.93, 0.0, 1.01, 0.3};
      const auto seam = dir_ / (stem + "_seam.svg");
      join_picture({r.pictures[0]}, in.name + ", " + method + ": face 0 at the seam", window)
          .write(seam.string());
      pictures_.push_back({ctx_.relative(seam), in.name + ", " + method + ", the seam in detail"});
    }
    return svg;
  }

  /// A Whitney result must be valid; naive sewing must still fold the
  /// folding input (the baseline the thesis' figures show).
  void check_run(const Joining_input& in, const std::string& method, const Join_tool_result& r, std::size_t flips) {
    if (method == "whitney") {
      whitney_flips_ += flips;
      if (r.status != "ok" || !r.report.guarantees_hold)
        rep_.failures.push_back(in.name + ": the Whitney joiner's result is not valid (" +
                                (r.failure.empty() ? std::string("guarantees do not hold") : r.failure) + ")");
    } else if (in.name == "folding") {
      naive_folding_flips_ = flips;
      if (flips == 0) rep_.failures.push_back("folding: naive sewing no longer folds (the baseline changed)");
    }
  }

  Section_report finish(std::size_t number_of_inputs) && {
    rep_.add_table(table_);
    rep_.add_note("Naive sewing moves both boundaries onto their midpoints and folds the thin strip of the folding "
                  "input; the Whitney joiner removes a peripheral layer, triangulates the external region anew and "
                  "reprojects it through the Whitney extension of the boundary heights: no fold, |a| <= M and slope "
                  "<= L on every face. Where an edge has no curve, the boundary data are the mesh's own noise, so the "
                  "normal-vector error stays at the boundary's (no worse, and not better). Pictures: " +
                  ctx_.relative(dir_) + "/NAME_METHOD.svg.\n");
    rep_.add_gallery("Every result in the (u,v) domains of its faces (flipped triangles red)", std::move(pictures_));
    rep_.add_headline("Folding input, flipped triangles (certified)",
                      "naive sewing " + std::to_string(naive_folding_flips_) + ", Whitney " +
                          std::to_string(whitney_flips_) + " (on all " + std::to_string(number_of_inputs) + " inputs)");
    rep_.json["runs"] = std::move(runs_);
    rep_.json["naive_folding_flips"] = naive_folding_flips_;
    rep_.json["whitney_flips"] = whitney_flips_;
    return std::move(rep_);
  }

  const Experiment_context& ctx_;
  const std::filesystem::path dir_;
  Section_report rep_;
  Text_table table_{{"input", "method", "verts", "tris", "abs before", "abs after", "nve before", "nve after", "flips",
                     "overlaps", "seams", "status", "time"}};
  Json runs_ = Json::array();
  std::vector<Picture> pictures_;
  std::size_t naive_folding_flips_ = 0, whitney_flips_ = 0;
};

}  // namespace

Section_report joining_section(const Experiment_context& ctx) { return Joining_experiment(ctx).run(); }

}  // namespace relgeo::tool
