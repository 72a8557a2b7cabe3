// tools/relgeo/experiment/hull.cpp — the "hull" section of `relgeo
// experiment`: every hull algorithm under every kernel (and CGAL's
// convex_hull_2 under the CGAL kernels) on
//  (1) the classroom example A1 and Kettner et al.'s failure construction
//      (one input per failure kind), with an SVG picture per run;
//  (2) families of near-degenerate inputs (hull_inputs.h).
// Reported per run: status, hull size, convexity, E (eq. 3.2), the backward
// error certificate, graham-fortune's a-priori bound, algorithm time.
// The section fails (exit 1) only on a library bug: an exact-predicate kernel
// that does not return the exact hull, or graham-fortune under a certified
// kernel whose output is not convex or exceeds its a-priori bound.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "commands/hull/facade.h"
#include "commands/hull/picture.h"
#include "commands/hull/report.h"
#include "experiment/hull_inputs.h"
#include "experiment/section.h"
#include "kernels/registry.h"
#include "relgeo/io/point_file.h"

namespace relgeo::tool {

namespace {

/// Inputs up to this size get a picture per run and their hull in the JSON.
constexpr std::size_t small_input = 20;

using io::Json;

struct Combination {
  std::string algorithm;
  const Kernel_entry* kernel;
};

std::vector<Combination> combinations() {
  std::vector<Combination> out;
  for (const auto& a : hull_algorithm_names())
    for (const auto& k : kernel_registry())
      if (a != "cgal" || k.cgal) out.push_back({a, &k});
  return out;
}

/// Counts over the runs, for the headline figures.
struct Run_counts {
  std::size_t runs = 0, exact = 0, failed = 0, not_convex = 0;
  std::size_t fortune_certified = 0;  ///< graham-fortune runs under certified kernels
  double fortune_worst = 0;           ///< their largest backward error
  std::map<std::string, std::size_t> naive_wrong;  ///< "algorithm/kernel" of naive kernels -> runs not exact
};

std::string join(const std::set<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::string bound_text(const std::optional<double>& b, const std::string& algorithm) {
  if (algorithm != "graham-fortune") return "";
  return b ? measure_text(*b) : "none";
}

void count_run(Run_counts& c, const std::string& algorithm, const Kernel_entry& k, const Hull_evaluation& e,
               const std::vector<std::size_t>& exact) {
  const bool ok = e.run.status == Hull_status::ok;
  ++c.runs;
  c.exact += ok && e.run.indices == exact;
  c.failed += !ok;
  c.not_convex += ok && !e.error.convex;
  if (!k.certified && !(ok && e.run.indices == exact)) ++c.naive_wrong[algorithm + "/" + k.label()];
  if (algorithm == "graham-fortune" && k.certified && ok) {
    ++c.fortune_certified;
    c.fortune_worst = std::max(c.fortune_worst, e.backward.value);
  }
}

void add_headlines(const Run_counts& c, Section_report& rep) {
  rep.add_headline("Hull runs (every algorithm x kernel x input)",
                   std::to_string(c.runs) + " runs: " + std::to_string(c.exact) + " exact hulls, " +
                       std::to_string(c.failed) + " reported failures, " + std::to_string(c.not_convex) +
                       " non-convex outputs");
  rep.add_headline("graham-fortune under certified kernels, largest backward error",
                   measure_text(c.fortune_worst) + " over " + std::to_string(c.fortune_certified) + " runs");
  std::vector<std::pair<std::size_t, std::string>> worst;
  for (const auto& [who, n] : c.naive_wrong) worst.push_back({n, who});
  std::sort(worst.rbegin(), worst.rend());
  std::string list;
  for (std::size_t i = 0; i < worst.size() && i < 3; ++i)
    list += (i ? ", " : "") + worst[i].second + " (" + std::to_string(worst[i].first) + ")";
  if (!list.empty()) rep.add_headline("Uncertified pairs most often not exact (inputs)", list);
}

/// The inputs: the classroom example, Kettner et al.'s construction and the
/// near-degenerate families of n points; without --quick the families again
/// at 100000 points, where the algorithms' times differ (fast kernels only).
std::vector<Hull_input> hull_inputs(const Experiment_context& ctx, std::size_t n) {
  ctx.progress("generating inputs (Kettner et al.'s construction searches seeds)");
  std::vector<Hull_input> inputs = {
      classroom_a1_input(),
      kettner_construction_input(Kettner_failure::lost_point),
      kettner_construction_input(Kettner_failure::non_convex),
      kettner_construction_input(Kettner_failure::non_termination),
      line_ulps_input(n, 101),
      circle_input(n, 20, 102),
      clustered_input(n, 6, 103),
      large_range_input(n, 104),
  };
  std::erase_if(inputs, [](const Hull_input& in) { return in.points.empty(); });
  if (!ctx.quick) {
    const std::size_t big = 100000;
    for (Hull_input in : {line_ulps_input(big, 201), circle_input(big, 20, 202),
                          clustered_input(big, 6, 203), large_range_input(big, 204)}) {
      in.name += "-100k";
      inputs.push_back(std::move(in));
    }
  }
  return inputs;
}

/// The section's run over every input and combination: one table, the run
/// records, the pictures and counts, and what was skipped.
class Hull_experiment {
 public:
  explicit Hull_experiment(const Experiment_context& ctx)
      : ctx_(ctx), dir_(ctx.section_dir()), input_dir_(dir_ / "inputs"), family_size_(ctx.quick ? 250 : 1000),
        slow_limit_(family_size_) {
    std::filesystem::create_directories(input_dir_);
    tab_.set_left_columns(4);
  }

  Section_report run() && {
    const std::vector<Hull_input> inputs = hull_inputs(ctx_, family_size_);
    for (const Hull_input& in : inputs) run_input(in);
    rep_.add_note(note(inputs));
    rep_.add_table(tab_);
    for (auto& [title, pictures] : galleries_) rep_.add_gallery(title, std::move(pictures));
    add_headlines(counts_, rep_);
    rep_.json["inputs"] = std::move(input_records_);
    rep_.json["slow_kernel_limit"] = slow_limit_;
    rep_.json["graham_incremental_limit"] = incremental_limit;
    rep_.json["runs"] = std::move(runs_);
    return std::move(rep_);
  }

 private:
  /// graham-incremental runs where n * |exact hull| is at most this.
  static constexpr double incremental_limit = 2e8;

  void run_input(const Hull_input& in) {
    const std::span<const Point_2<double>> pts(in.points);
    const std::vector<std::size_t> exact = run_hull("monotone-chain", "filtered", pts).indices;
    record_input(in, exact);
    tab_.add_rule();
    std::string last_algorithm;
    std::vector<Picture> pictures;
    for (const Combination& c : combos_) {
      if (skipped(in, c, exact)) continue;
      if (c.algorithm != last_algorithm) {
        ctx_.progress(in.name + " (" + std::to_string(pts.size()) + " points): " + c.algorithm);
        last_algorithm = c.algorithm;
      }
      const Hull_evaluation e = evaluate_hull(c.algorithm, c.kernel->name, pts, ctx_.min_timing_seconds);
      count_run(counts_, c.algorithm, *c.kernel, e, exact);
      record_run(in, c, exact, e, pictures);
      check_run(in, c, exact, e);
    }
    galleries_.push_back({in.name + ": " + in.description, std::move(pictures)});
  }

  /// The input's point file and its JSON record.
  void record_input(const Hull_input& in, const std::vector<std::size_t>& exact) {
    const std::span<const Point_2<double>> pts(in.points);
    const std::filesystem::path file = input_dir_ / (in.name + ".txt");
    io::write_points_2(file.string(), pts,
                       in.name + ": " + in.description + "\n" + std::to_string(pts.size()) +
                           " points; rerun e.g. with: relgeo hull --algorithm graham-incremental "
                           "--kernel double " + file.filename().string());
    Json ij;
    ij["name"] = in.name;
    ij["description"] = in.description;
    ij["seed"] = in.seed;
    ij["n"] = pts.size();
    ij["exact_hull_size"] = exact.size();
    if (pts.size() <= small_input) ij["exact_hull_indices"] = exact;
    ij["file"] = ctx_.relative(file);
    input_records_.push_back(std::move(ij));
  }

  /// Slow kernels on large inputs, graham_incremental (O(n h)) where that is
  /// too long.
  bool skipped(const Hull_input& in, const Combination& c, const std::vector<std::size_t>& exact) {
    if (c.kernel->slow && in.points.size() > slow_limit_) {
      skipped_slow_ = true;
      return true;
    }
    if (c.algorithm == "graham-incremental" && double(in.points.size()) * double(exact.size()) > incremental_limit) {
      skipped_incremental_.insert(in.name);
      return true;
    }
    return false;
  }

  /// The run's table row, JSON record and, for a small input, its picture.
  void record_run(const Hull_input& in, const Combination& c, const std::vector<std::size_t>& exact,
                  const Hull_evaluation& e, std::vector<Picture>& pictures) {
    const std::span<const Point_2<double>> pts(in.points);
    const Kernel_entry& k = *c.kernel;
    const Hull_run& r = e.run;
    const bool ok = r.status == Hull_status::ok;
    const bool is_exact = ok && r.indices == exact;
    std::string status = ok ? (is_exact ? "exact" : "ok") : "FAILED";
    tab_.add_row({in.name, c.algorithm, k.label(), ok ? status : "FAILED: " + r.failure,
                  std::to_string(r.indices.size()) + "/" + std::to_string(exact.size()),
                  e.error.convex ? "yes" : "NO", measure_text(e.error.value),
                  measure_text(e.backward.value), bound_text(r.backward_error_bound, c.algorithm),
                  duration_text(r.time_s)});
    Json j;
    j["input"] = in.name;
    Json report = hull_report_json(c.algorithm, k, pts, e, pts.size() <= small_input);
    for (auto& [key, v] : report.items()) j[key] = std::move(v);
    j["exact_hull"] = is_exact;
    j["timed_runs"] = r.timed_runs;
    if (pts.size() <= small_input) {
      const std::filesystem::path svg = dir_ / (in.name + "_" + c.algorithm + "_" + k.label() + ".svg");
      write_hull_svg(svg.string(), pts, e, in.name + ": " + c.algorithm + ", kernel " + k.label());
      j["svg"] = ctx_.relative(svg);
      pictures.push_back({ctx_.relative(svg), c.algorithm + ", " + k.label() + ": " + (ok ? status : "FAILED") +
                                                  ", E = " + measure_text(e.error.value)});
    }
    runs_.push_back(std::move(j));
  }

  /// Library bugs (not the expected failures of unreliable kernels).
  void check_run(const Hull_input& in, const Combination& c, const std::vector<std::size_t>& exact,
                 const Hull_evaluation& e) {
    const Kernel_entry& k = *c.kernel;
    const Hull_run& r = e.run;
    const bool is_exact = r.status == Hull_status::ok && r.indices == exact;
    const std::string where = in.name + " " + c.algorithm + "/" + k.label();
    if (k.exact_predicates && !is_exact)
      rep_.failures.push_back(where + ": exact predicates but not the exact hull");
    if (c.algorithm == "graham-fortune" && k.certified) {
      if (!e.error.convex) rep_.failures.push_back(where + ": certified kernel, output not convex");
      if (r.backward_error_bound && !(e.backward.value <= *r.backward_error_bound))
        rep_.failures.push_back(where + ": backward error " + measure_text(e.backward.value) +
                                " exceeds the a-priori bound " + measure_text(*r.backward_error_bound));
    }
  }

  std::string note(const std::vector<Hull_input>& inputs) const {
    std::string inputs_text;
    for (const Hull_input& in : inputs)
      inputs_text += "  " + in.name + std::string(in.name.size() < 19 ? 19 - in.name.size() : 1, ' ') +
                     in.description + "\n";
    return "Planar convex hulls: every algorithm under every kernel (cgal = CGAL::convex_hull_2, CGAL "
           "kernels only).\nInputs (point files in " + ctx_.relative(input_dir_) + "/):\n" + inputs_text +
           "\nstatus: exact = the exact hull, ok = another hull, FAILED = the algorithm reported a "
           "failure;\n|hull| = computed/exact size; convex = the output polygon, in its order, is simple, strictly convex and CCW (exact check);\n"
           "E = eq. (3.2), Hausdorff distance to the exact hull / M; backward error = certificate "
           "(relative move of the input making the output exact);\na-priori bound = "
           "graham_fortune_backward_error_bound (graham-fortune only; none = the kernel gives no "
           "guarantee);\ntime = algorithm only, fastest of runs repeated for >= " +
           format_g(ctx_.min_timing_seconds * 1000, 3) + " ms. Pictures: " + ctx_.relative(dir_) +
           "/<input>_<algorithm>_<kernel>.svg for inputs of <= " + std::to_string(small_input) +
           " points.\n" +
           (!skipped_slow_ ? std::string()
                           : "Slow kernels (exact, mpfr-*, cgal-epeck) skipped on inputs of more than " +
                                 std::to_string(slow_limit_) + " points.\n") +
           (skipped_incremental_.empty()
                ? std::string()
                : "graham-incremental (O(n h)) skipped where n * |exact hull| > " +
                      format_g(incremental_limit, 3) + ": " + join(skipped_incremental_) + ".\n") +
           "\n";
  }

  const Experiment_context& ctx_;
  const std::filesystem::path dir_, input_dir_;
  const std::size_t family_size_;  ///< points of the near-degenerate families
  /// Slow kernels (exact, mpfr-*, cgal-epeck) run on inputs up to this size.
  const std::size_t slow_limit_;
  const std::vector<Combination> combos_ = combinations();
  Section_report rep_;
  Text_table tab_{{"input", "algorithm", "kernel", "status", "|hull|", "convex", "E", "backward error",
                   "a-priori bound", "time"}};
  Json input_records_ = Json::array(), runs_ = Json::array();
  Run_counts counts_;
  std::vector<std::pair<std::string, std::vector<Picture>>> galleries_;
  bool skipped_slow_ = false;
  std::set<std::string> skipped_incremental_;
};

}  // namespace

Section_report hull_section(const Experiment_context& ctx) { return Hull_experiment(ctx).run(); }

}  // namespace relgeo::tool
