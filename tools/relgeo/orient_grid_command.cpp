// tools/relgeo/orient_grid_command.cpp — `relgeo orient-grid`.
#include <ostream>

#include "commands.h"
#include "json_output.h"
#include "kernel_names.h"
#include "kernel_runs.h"
#include "png_writer.h"
#include "relgeo/analysis/predicate_workloads.h"

namespace relgeo::tool {

namespace {

analysis::Orientation_grid_triple triple_from(const Orient_grid_options& o) {
  const bool any_point = !o.p.empty() || !o.q.empty() || !o.r.empty();
  if (!o.triple.empty()) {
    if (any_point) throw Usage_error("--triple excludes --p, --q and --r");
    for (const auto& t : analysis::kettner_grid_triples())
      if (t.name == o.triple) return t;
    throw Usage_error("--triple: '" + o.triple + "' is not one of a, b, c");
  }
  for (const auto& [value, flag] : {std::pair{&o.p, "--p"}, {&o.q, "--q"}, {&o.r, "--r"}})
    if (value->empty())
      throw Usage_error(std::string("missing ") + flag + " X,Y (or give --triple a|b|c)");
  const auto [px, py] = parse_point_2(o.p, "--p");
  const auto [qx, qy] = parse_point_2(o.q, "--q");
  const auto [rx, ry] = parse_point_2(o.r, "--r");
  return {"custom", px, py, qx, qy, rx, ry};
}

}  // namespace

int run_orient_grid(const Orient_grid_options& o, std::ostream& out, std::ostream& err) {
  validate_kernel_name(o.kernel);
  if (o.size < 1 || o.size > 4096) throw Usage_error("--size must be in [1, 4096]");
  if (o.scale < 1 || o.scale > 16) throw Usage_error("--scale must be in [1, 16]");
  const analysis::Orientation_grid_triple triple = triple_from(o);
  const Kernel_info info = kernel_info(o.kernel);
  const analysis::Orientation_grid_result g = evaluate_grid(o.kernel, triple, o.size);
  const analysis::Sign_tally& t = g.tally;

  if (!o.png.empty()) write_png(o.png, orientation_grid_image(g.answers, g.exact, g.size, o.scale));

  // A certified kernel must never give a wrong definite answer.
  const bool violation = info.certified && t.wrong() > 0;

  if (o.format == Format::json) {
    Json j;
    j["kernel"] = info.name;
    j["kernel_model"] = info.model;
    j["certified"] = info.certified;
    if (!o.triple.empty()) j["triple"] = o.triple;
    j["p"] = json_point(triple.px, triple.py);
    j["q"] = json_point(triple.qx, triple.qy);
    j["r"] = json_point(triple.rx, triple.ry);
    j["size"] = g.size;
    j["cells"] = t.cases;
    j["wrong"] = t.wrong();
    j["plus_to_zero"] = t.plus_to_zero;
    j["minus_to_zero"] = t.minus_to_zero;
    j["zero_to_sign"] = t.zero_to_sign;
    j["inversions"] = t.inversions;
    j["uncertain"] = t.uncertain;
    j["correct"] = t.correct;
    j["status"] = violation ? "failed" : "ok";
    j["failure"] = violation ? Json("soundness-violation") : Json(nullptr);
    if (!o.png.empty()) j["png"] = o.png;
    out << dump_json(j) << '\n';
  } else {
    std::string text;
    auto kv = [&](const std::string& k, const std::string& v) {
      text += k + std::string(k.size() < 17 ? 17 - k.size() : 1, ' ') + v + "\n";
    };
    kv("kernel", info.name + " (" + info.model + (info.certified ? ", certified)" : ", not certified)"));
    if (!o.triple.empty()) kv("triple", o.triple);
    kv("p", format_point_17(triple.px, triple.py));
    kv("q", format_point_17(triple.qx, triple.qy));
    kv("r", format_point_17(triple.rx, triple.ry));
    kv("grid", std::to_string(g.size) + " x " + std::to_string(g.size) + " cells, p(X,Y) = p + (X, Y) * 2^-53");
    kv("cells", std::to_string(t.cases));
    kv("correct", std::to_string(t.correct));
    kv("wrong", std::to_string(t.wrong()));
    kv("  plus_to_zero", std::to_string(t.plus_to_zero));
    kv("  minus_to_zero", std::to_string(t.minus_to_zero));
    kv("  zero_to_sign", std::to_string(t.zero_to_sign));
    kv("  inversions", std::to_string(t.inversions));
    kv("uncertain", std::to_string(t.uncertain));
    if (!o.png.empty()) kv("png", o.png);
    kv("status", violation ? "FAILED: soundness violation (a certified kernel gave wrong answers)" : "ok");
    out << text;
  }
  if (violation) {
    err << "relgeo: failure: certified kernel '" << info.name << "' gave " << t.wrong()
        << " wrong answers on the grid\n";
    return exit_failure;
  }
  return exit_success;
}

}  // namespace relgeo::tool
