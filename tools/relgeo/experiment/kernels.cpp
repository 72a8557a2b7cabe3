// tools/relgeo/experiment/kernels.cpp — the "kernels" section of `relgeo
// experiment`: every kernel of the tool on
//  (1) the three orientation grids of Kettner et al. (SPEC Sec. 3.1), with a
//      picture per kernel and grid;
//  (2) the standard orientation_2 / orientation_3 workloads: wrong answers
//      against the exact signs, rate of `uncertain`, time per predicate.
#include <cstddef>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "commands/orient_grid/facade.h"
#include "commands/orient_grid/picture.h"
#include "commands/orient_grid/report.h"
#include "experiment/section.h"
#include "experiment/workloads.h"
#include "kernels/registry.h"
#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/analysis/sign_tally.h"

namespace relgeo::tool {

namespace {

using io::Json;

constexpr int grid_size = 256;
constexpr int grid_scale = 2;

std::string rate_text(double rate) {
  if (rate == 0) return "0";
  const double percent = rate * 100;
  return (percent >= 0.1 ? format_fixed(percent, 1) : format_g(percent, 2)) + "%";
}

/// The wrong count, flagged when a certified kernel has any.
std::string wrong_text(std::size_t wrong, bool certified) {
  return std::to_string(wrong) + (certified && wrong > 0 ? " !" : "");
}

/// Headline figures gathered while the section runs.
struct Headline_figures {
  std::map<std::string, std::size_t> grid_a_wrong;  ///< kernel -> wrong answers on grid a
  std::size_t certified_wrong = 0, certified_answers = 0;
  std::map<std::string, double> ns_orientation_2;  ///< kernel -> mean ns per orientation_2
};

// ---- (1) the grids ----------------------------------------------------------

void run_grids(const Experiment_context& ctx, const std::vector<Kernel_entry>& kernels, Section_report& rep,
               Headline_figures& figures) {
  const std::filesystem::path dir = ctx.section_dir();
  Json records = Json::array();
  for (const auto& triple : analysis::kettner_grid_triples()) {
    std::vector<std::string> header = {"kernel", "certified"};
    for (auto& h : tally_header()) header.push_back(h);
    Text_table tab(header);
    std::vector<Picture> pictures;
    for (const auto& k : kernels) {
      ctx.progress("grid " + triple.name + ": " + k.label());
      const auto g = evaluate_grid(k.name, triple, grid_size);
      const auto& t = g.tally;
      const std::filesystem::path png = dir / ("grid_" + triple.name + "_" + k.label() + ".png");
      io::write_png(png.string(), orientation_grid_image(g.answers, g.exact, g.size, grid_scale));
      pictures.push_back({ctx.relative(png), k.label() + ": " + std::to_string(t.wrong()) + " wrong" +
                                                 (t.uncertain ? ", " + std::to_string(t.uncertain) + " uncertain" : "")});
      std::vector<std::string> row = {k.label(), k.certified ? "yes" : "no"};
      for (auto& c : tally_cells(t, k.certified)) row.push_back(std::move(c));
      tab.add_row(std::move(row));
      Json r{{"triple", triple.name}, {"kernel", k.label()}, {"certified", k.certified}, {"size", g.size}};
      add_tally_json(r, t, "cells");
      r["png"] = ctx.relative(png);
      records.push_back(std::move(r));
      if (triple.name == "a") figures.grid_a_wrong[k.label()] = t.wrong();
      if (k.certified) figures.certified_wrong += t.wrong(), figures.certified_answers += t.cases;
      if (k.certified && t.wrong() > 0)
        rep.failures.push_back("soundness violation: certified kernel " + k.label() + " gave " +
                               std::to_string(t.wrong()) + " wrong answers on grid " + triple.name);
    }
    rep.add_note("Orientation grid " + triple.name + ": p = " + format_point_17(triple.px, triple.py) + ", q = " +
                 format_point_17(triple.qx, triple.qy) + ", r = " + format_point_17(triple.rx, triple.ry) + "\n" +
                 std::to_string(grid_size) + " x " + std::to_string(grid_size) + " cells p + (X, Y) * 2^-53; pictures " +
                 ctx.relative(dir) + "/grid_" + triple.name + "_<kernel>.png\n\n");
    rep.add_table(tab);
    rep.add_gallery("Grid " + triple.name + " under every kernel (" + orientation_grid_legend + ")", std::move(pictures));
  }
  Json triples = Json::array();
  for (const auto& t : analysis::kettner_grid_triples())
    triples.push_back(Json{{"name", t.name},
                           {"p", io::json_point(t.px, t.py)},
                           {"q", io::json_point(t.qx, t.qy)},
                           {"r", io::json_point(t.rx, t.ry)}});
  rep.json["grid_size"] = grid_size;
  rep.json["grid_triples"] = std::move(triples);
  rep.json["grids"] = std::move(records);
}

// ---- (2) the workloads --------------------------------------------------------

/// The workloads' two tables: soundness (wrong / uncertain per workload and
/// over all) and time per predicate.
struct Workload_tables {
  Text_table soundness, time;
};

template <class Case>
Workload_tables workload_tables(const std::vector<analysis::Workload<Case>>& workloads) {
  std::vector<std::string> header = {"kernel", "certified", "cases"};
  std::vector<std::pair<std::string, std::size_t>> groups = {{"", 3}};
  std::vector<std::string> time_header = {"kernel"};
  for (const auto& w : workloads) {
    header.insert(header.end(), {"wrong", "uncertain"});
    groups.push_back({w.name, 2});
    time_header.push_back(w.name);
  }
  header.insert(header.end(), {"wrong", "uncertain"});
  groups.push_back({"all workloads", 2});
  time_header.push_back("mean");
  Workload_tables t{Text_table(header), Text_table(time_header)};
  t.soundness.set_groups(groups);
  return t;
}

/// One kernel on one workload's first `cases`: its record, and a soundness
/// violation when a certified kernel answers wrong.
template <class Case, class Measure>
Workload_measurement measure_workload(const Experiment_context& ctx, const Kernel_entry& k, const std::string& predicate,
                                      const analysis::Workload<Case>& workload, std::span<const Certified_sign> exact,
                                      std::size_t cases, bool subset, Measure measure, Json& records,
                                      Section_report& rep) {
  const std::size_t m = std::min(cases, workload.cases.size());
  const Workload_measurement r =
      measure(k.name, std::span<const Case>(workload.cases).first(m), exact.first(m), ctx.min_timing_seconds);
  Json j{{"predicate", predicate},
         {"kernel", k.label()},
         {"certified", k.certified},
         {"workload", workload.name},
         {"subset", subset}};  // true: only the first `cases` cases of the workload
  add_tally_json(j, r.tally, "cases");
  j.update(Json{{"uncertain_rate", r.tally.uncertain_rate()},
                {"ns_per_predicate", r.ns_per_predicate},
                {"timed_evaluations", r.timed_evaluations}});
  records.push_back(std::move(j));
  if (k.certified && r.tally.wrong() > 0)
    rep.failures.push_back("soundness violation: certified kernel " + k.label() + " gave " +
                           std::to_string(r.tally.wrong()) + " wrong answers on " + predicate + " workload " +
                           workload.name);
  return r;
}

template <class Case, class Measure>
void run_workloads(const Experiment_context& ctx, const std::vector<Kernel_entry>& kernels,
                   const std::string& predicate, const std::vector<analysis::Workload<Case>>& workloads,
                   Measure measure, Json& records, Section_report& rep, Headline_figures& figures) {
  std::vector<std::vector<Certified_sign>> exact;
  for (const auto& w : workloads) {
    ctx.progress(predicate + ": exact signs of workload " + w.name);
    exact.push_back(analysis::exact_signs<Case>(w.cases));
  }
  const std::size_t n = ctx.workload_size, n_slow = std::min(n, ctx.slow_kernel_cases);
  Workload_tables tables = workload_tables(workloads);
  for (const auto& k : kernels) {
    ctx.progress(predicate + ": " + k.label());
    const std::size_t used = k.slow ? n_slow : n;
    const bool subset = used < n;
    const std::string label = k.label() + (subset ? " *" : "");
    std::vector<std::string> row = {label, k.certified ? "yes" : "no", std::to_string(used)};
    std::vector<std::string> time_row = {label};
    analysis::Sign_tally all;
    double ns_sum = 0;
    for (std::size_t i = 0; i < workloads.size(); ++i) {
      const Workload_measurement r =
          measure_workload(ctx, k, predicate, workloads[i], exact[i], used, subset, measure, records, rep);
      all += r.tally;
      ns_sum += r.ns_per_predicate;
      row.insert(row.end(), {wrong_text(r.tally.wrong(), k.certified), rate_text(r.tally.uncertain_rate())});
      time_row.push_back(format_fixed(r.ns_per_predicate, 1));
    }
    const double mean_ns = workloads.empty() ? 0.0 : ns_sum / double(workloads.size());
    if (k.certified) figures.certified_wrong += all.wrong(), figures.certified_answers += all.cases;
    if (predicate == "orientation_2") figures.ns_orientation_2[k.label()] = mean_ns;
    row.insert(row.end(), {wrong_text(all.wrong(), k.certified), rate_text(all.uncertain_rate())});
    time_row.push_back(format_fixed(mean_ns, 1));
    tables.soundness.add_row(std::move(row));
    tables.time.add_row(std::move(time_row));
  }
  const std::string subset_note =
      n_slow < n ? "* slow kernel: only the first " + std::to_string(n_slow) + " cases of each workload\n" : std::string();
  rep.add_note(predicate + ", standard workloads of " + std::to_string(n) +
               " cases: wrong = definite answers that differ from the exact sign, uncertain = "
               "rate of 'uncertain' answers\n" + subset_note +
               "! = soundness violation (a certified kernel answered wrong)\n\n");
  rep.add_table(tables.soundness);
  rep.add_note(predicate +
               ", time per predicate in ns (points built beforehand; fastest pass of a loop "
               "repeated for >= " + format_g(ctx.min_timing_seconds * 1000, 3) + " ms)\n" + subset_note + "\n");
  rep.add_table(tables.time);
}

void add_headlines(const Headline_figures& f, Section_report& rep) {
  const auto wrong = [&](const char* k) {
    const auto it = f.grid_a_wrong.find(k);
    return it == f.grid_a_wrong.end() ? std::string("-") : std::to_string(it->second);
  };
  rep.add_headline("Grid a (Kettner et al.), wrong signs of " + std::to_string(grid_size * grid_size) + " cells",
                   "double " + wrong("double") + ", float " + wrong("float") + ", long-double " + wrong("long-double") +
                       ", cgal-sc " + wrong("cgal-sc"));
  rep.add_headline("Certified kernels, wrong answers on every grid and workload",
                   std::to_string(f.certified_wrong) + " of " + std::to_string(f.certified_answers));
  const auto ns = [&](const char* k) {
    const auto it = f.ns_orientation_2.find(k);
    return it == f.ns_orientation_2.end() ? std::string("-") : format_fixed(it->second, 1) + " ns";
  };
  rep.add_headline("orientation_2, mean time per predicate",
                   "double " + ns("double") + ", filtered " + ns("filtered") + ", interval " + ns("interval") +
                       ", exact " + ns("exact") + ", cgal-epick " + ns("cgal-epick"));
}

}  // namespace

Section_report kernels_section(const Experiment_context& ctx) {
  Section_report rep;
  const std::vector<Kernel_entry>& kernels = kernel_registry();
  Json kernel_list = Json::array();
  for (const auto& k : kernels)
    kernel_list.push_back(Json{{"name", k.label()},
                               {"model", k.name},
                               {"certified", k.certified},
                               {"exact_predicates", k.exact_predicates},
                               {"slow", k.slow}});
  rep.json["kernels"] = std::move(kernel_list);
  rep.json["slow_kernel_cases"] = std::min(ctx.workload_size, ctx.slow_kernel_cases);

  Headline_figures figures;
  run_grids(ctx, kernels, rep, figures);

  Json records = Json::array();
  run_workloads<analysis::Orientation_2_case>(ctx, kernels, "orientation_2",
                                              analysis::standard_workloads_2(ctx.workload_size),
                                              &measure_orientation_2, records, rep, figures);
  run_workloads<analysis::Orientation_3_case>(ctx, kernels, "orientation_3",
                                              analysis::standard_workloads_3(ctx.workload_size),
                                              &measure_orientation_3, records, rep, figures);
  rep.json["workloads"] = std::move(records);
  add_headlines(figures, rep);
  return rep;
}

}  // namespace relgeo::tool
