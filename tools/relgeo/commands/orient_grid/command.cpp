// tools/relgeo/commands/orient_grid/command.cpp — `relgeo orient-grid`: one
// kernel (--kernel), or the standard kernels side by side (the default).
#include "commands/orient_grid/command.h"

#include <filesystem>
#include <ostream>

#include "commands/orient_grid/facade.h"
#include "commands/orient_grid/picture.h"
#include "commands/orient_grid/report.h"
#include "kernels/registry.h"
#include "relgeo/analysis/predicate_workloads.h"

namespace relgeo::tool {

namespace {

using io::Json;

/// p, q, r from --triple or --p --q --r; none given: triple a.
analysis::Orientation_grid_triple triple_from(const Orient_grid_options& o, std::string& triple_name) {
  const bool any_point = !o.p.empty() || !o.q.empty() || !o.r.empty();
  triple_name = o.triple.empty() && !any_point ? "a" : o.triple;
  if (!triple_name.empty()) {
    if (any_point) throw Usage_error("--triple excludes --p, --q and --r");
    for (const auto& t : analysis::kettner_grid_triples())
      if (t.name == triple_name) return t;
    throw Usage_error("--triple: '" + triple_name + "' is not one of a, b, c");
  }
  for (const auto& [value, flag] : {std::pair{&o.p, "--p"}, {&o.q, "--q"}, {&o.r, "--r"}})
    if (value->empty()) throw Usage_error(std::string("missing ") + flag + " X,Y (or give --triple a|b|c)");
  const auto [px, py] = parse_point_2(o.p, "--p");
  const auto [qx, qy] = parse_point_2(o.q, "--q");
  const auto [rx, ry] = parse_point_2(o.r, "--r");
  return {"custom", px, py, qx, qy, rx, ry};
}

/// One kernel's grid.
struct Grid_run {
  const Kernel_entry* kernel;
  analysis::Orientation_grid_result grid;
  std::string png;
  bool violation() const { return kernel->certified && grid.tally.wrong() > 0; }  // a certified kernel was wrong
};

/// --png FILE for kernel k: FILE itself for one kernel, FILE_<kernel>.ext for several.
std::string png_path(const std::string& png, const Kernel_entry& k, bool several) {
  if (png.empty() || !several) return png;
  const std::filesystem::path p(png);
  return (p.parent_path() / (p.stem().string() + "_" + k.label() + p.extension().string())).string();
}

void add_points_json(Json& j, const analysis::Orientation_grid_triple& t, const std::string& triple_name) {
  if (!triple_name.empty()) j["triple"] = triple_name;
  j["p"] = io::json_point(t.px, t.py);
  j["q"] = io::json_point(t.qx, t.qy);
  j["r"] = io::json_point(t.rx, t.ry);
}

void add_points_text(Key_value_text& kv, const analysis::Orientation_grid_triple& t, const std::string& triple_name,
                     int size) {
  if (!triple_name.empty()) kv.add("triple", triple_name);
  kv.add("p", format_point_17(t.px, t.py));
  kv.add("q", format_point_17(t.qx, t.qy));
  kv.add("r", format_point_17(t.rx, t.ry));
  kv.add("grid", std::to_string(size) + " x " + std::to_string(size) + " cells, p(X,Y) = p + (X, Y) * 2^-53");
}

Json kernel_json(const Grid_run& g) {
  return Json{{"kernel", g.kernel->label()}, {"kernel_model", g.kernel->name}, {"certified", g.kernel->certified}};
}

/// The report of one kernel (the format of `--kernel K`).
void report_one(const Orient_grid_options& o, const analysis::Orientation_grid_triple& t, const std::string& triple_name,
                const Grid_run& g, std::ostream& out) {
  const analysis::Sign_tally& s = g.grid.tally;
  if (o.format == Format::json) {
    Json j = kernel_json(g);
    add_points_json(j, t, triple_name);
    j["size"] = g.grid.size;
    add_tally_json(j, s, "cells");
    j["status"] = g.violation() ? "failed" : "ok";
    j["failure"] = g.violation() ? Json("soundness-violation") : Json(nullptr);
    if (!g.png.empty()) j["png"] = g.png;
    out << io::dump_json(j) << '\n';
    return;
  }
  const Kernel_entry& k = *g.kernel;
  Key_value_text kv(17);
  kv.add("kernel", k.label() + " (" + k.name + (k.certified ? ", certified)" : ", not certified)"));
  add_points_text(kv, t, triple_name, g.grid.size);
  kv.add("cells", std::to_string(s.cases));
  kv.add("correct", std::to_string(s.correct));
  kv.add("wrong", std::to_string(s.wrong()));
  kv.add("  plus_to_zero", std::to_string(s.plus_to_zero));
  kv.add("  minus_to_zero", std::to_string(s.minus_to_zero));
  kv.add("  zero_to_sign", std::to_string(s.zero_to_sign));
  kv.add("  inversions", std::to_string(s.inversions));
  kv.add("uncertain", std::to_string(s.uncertain));
  if (!g.png.empty()) kv.add("png", g.png);
  kv.add("status", g.violation() ? "FAILED: soundness violation (a certified kernel gave wrong answers)" : "ok");
  out << kv.str();
}

/// The report of several kernels: one record (row) per kernel.
void report_many(const Orient_grid_options& o, const analysis::Orientation_grid_triple& t,
                 const std::string& triple_name, const std::vector<Grid_run>& runs, bool failed, std::ostream& out) {
  const int size = runs.front().grid.size;
  if (o.format == Format::json) {
    Json j;
    add_points_json(j, t, triple_name);
    j["size"] = size;
    j["cells"] = runs.front().grid.tally.cases;
    Json rows = Json::array();
    for (const Grid_run& g : runs) {
      Json r = kernel_json(g);
      add_tally_json(r, g.grid.tally, "cells");
      r["status"] = g.violation() ? "failed" : "ok";
      if (!g.png.empty()) r["png"] = g.png;
      rows.push_back(std::move(r));
    }
    j["kernels"] = std::move(rows);
    j["status"] = failed ? "failed" : "ok";
    j["failure"] = failed ? Json("soundness-violation") : Json(nullptr);
    out << io::dump_json(j) << '\n';
    return;
  }
  Key_value_text kv(17);
  add_points_text(kv, t, triple_name, size);
  kv.add("cells", std::to_string(runs.front().grid.tally.cases) + " per kernel");
  std::vector<std::string> header = {"kernel", "model", "certified"};
  for (auto& h : tally_header()) header.push_back(h);
  Text_table tab(header);
  tab.set_left_columns(2);
  for (const Grid_run& g : runs) {
    std::vector<std::string> row = {g.kernel->label(), g.kernel->name, g.kernel->certified ? "yes" : "no"};
    for (auto& c : tally_cells(g.grid.tally, g.kernel->certified)) row.push_back(std::move(c));
    tab.add_row(std::move(row));
  }
  out << kv.str() << '\n' << tab.str() << '\n';
  for (const Grid_run& g : runs)
    if (!g.png.empty()) out << "png              " << g.png << '\n';
  out << "status           " << (failed ? "FAILED: soundness violation (a certified kernel gave wrong answers)" : "ok")
      << "\n(one kernel in detail: --kernel NAME; ! = a certified kernel answered wrong)\n";
}

}  // namespace

std::vector<std::string> standard_grid_kernels() {
  std::vector<std::string> names;
  for (const auto& k : kernel_registry())
    if (!k.cgal && k.mpfr_bits == 0) names.push_back(k.label());
  return names;
}

int run_orient_grid(const Orient_grid_options& o, Streams io) {
  const std::vector<std::string> names = o.kernel.empty() ? standard_grid_kernels() : std::vector{o.kernel};
  std::vector<const Kernel_entry*> kernels;
  for (const auto& n : names) kernels.push_back(&find_kernel(n));
  if (o.size < 1 || o.size > 4096) throw Usage_error("--size must be in [1, 4096]");
  if (o.scale < 1 || o.scale > 16) throw Usage_error("--scale must be in [1, 16]");
  std::string triple_name;
  const analysis::Orientation_grid_triple triple = triple_from(o, triple_name);

  std::vector<Grid_run> runs;
  bool failed = false;
  for (const Kernel_entry* k : kernels) {
    Grid_run g{k, evaluate_grid(k->name, triple, o.size), png_path(o.png, *k, kernels.size() > 1)};
    if (!g.png.empty()) io::write_png(g.png, orientation_grid_image(g.grid.answers, g.grid.exact, g.grid.size, o.scale));
    failed = failed || g.violation();
    runs.push_back(std::move(g));
  }
  if (runs.size() == 1) report_one(o, triple, triple_name, runs.front(), io.out);
  else report_many(o, triple, triple_name, runs, failed, io.out);
  for (const Grid_run& g : runs)
    if (g.violation())
      io.err << "relgeo: failure: certified kernel '" << g.kernel->label() << "' gave " << g.grid.tally.wrong()
             << " wrong answers on the grid\n";
  return failed ? exit_failure : exit_success;
}

}  // namespace relgeo::tool
