// tools/relgeo/commands/extrusion/report.cpp — the extrusion command's
// options from a contour file, report and picture (no kernel instantiation:
// see dispatch.cpp).
#include "commands/extrusion/report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "cli/text.h"
#include "relgeo/error/convex_polygon.h"
#include "relgeo/io/svg_canvas.h"

namespace relgeo::tool {

Extrusion_options extrusion_options_for(const io::Contour_input& input, bool prune, std::size_t max_listed) {
  Extrusion_options options;
  options.relative_uncertainty = input.relative_uncertainty;
  options.absolute_uncertainty = input.absolute_uncertainty;
  options.rotation_error = input.projection ? input.projection->rotation_error : 0.0;
  options.prune = prune;
  options.max_listed = max_listed;
  return options;
}

namespace {

using io::Json;

std::string measure4(double v) { return measure_text(v, 4); }

std::string problem_where(const Extrusion_problem& p) {
  if (p.condition == Extrusion_condition::no_self_intersection) return "curve " + std::to_string(p.curve_a);
  return "curves " + std::to_string(p.curve_a) + ", " + std::to_string(p.curve_b);
}

Json problem_json(const Extrusion_problem& p) {
  return Json{
      {"condition", static_cast<int>(p.condition)},     {"set", p.set},
      {"curves", Json::array({p.curve_a, p.curve_b})},  {"margin", io::json_measure(p.margin)},
      {"uncertainty", io::json_measure(p.uncertainty)}, {"computation_error", io::json_measure(p.computation_error)},
      {"slack", io::json_measure(p.slack())},           {"verdict", to_string(p.verdict)}};
}

}  // namespace

Json extrusion_report_json(const io::Contour_input& in, std::string_view kernel, std::string_view algorithm,
                           const Extrusion_options& o, const Extrusion_report& r, double time_s) {
  const Bezier_contour& c = *in.contour;
  Json j;
  j["input"] = in.source;
  j["kernel"] = kernel;
  j["algorithm"] = algorithm;
  j["curves"] = c.size();
  std::size_t dmin = c[0].degree(), dmax = dmin;
  for (std::size_t m = 0; m < c.size(); ++m) dmin = std::min(dmin, c[m].degree()), dmax = std::max(dmax, c[m].degree());
  j["degrees"] = Json::array({dmin, dmax});
  j["dimension"] = in.three_d ? 3 : 2;
  if (in.projection) {
    const auto& p = *in.projection;
    j["direction"] = Json::array({io::json_coordinate(p.direction.x), io::json_coordinate(p.direction.y), io::json_coordinate(p.direction.z)});
    Json rows = Json::array();
    for (const auto& row : p.rotation) rows.push_back(Json::array({io::json_coordinate(row[0]), io::json_coordinate(row[1]), io::json_coordinate(row[2])}));
    j["rotation"] = rows;
    j["rotation_error"] = p.rotation_error;
    j["plane_heights"] = Json::array({io::json_coordinate(p.height_min), io::json_coordinate(p.height_max)});
  } else {
    j["direction"] = Json::array({0, 0, 1});
    j["rotation"] = nullptr;
    j["rotation_error"] = 0;
    j["plane_heights"] = nullptr;
  }
  j["heights"] = in.heights ? Json::array({io::json_coordinate(in.heights->first), io::json_coordinate(in.heights->second)}) : Json(nullptr);
  j["uncertainty"] = {{"relative", o.relative_uncertainty}, {"absolute", o.absolute_uncertainty}};
  j["verdict"] = to_string(r.verdict);
  j["certified"] = r.verdict == Extrusion_verdict::certified;
  Json conds = Json::array();
  for (const auto& s : r.conditions)
    conds.push_back(
        Json{{"condition", static_cast<int>(s.condition)},
             {"name", to_string(s.condition)},
             {"verdict", to_string(s.verdict)},
             {"problems", s.problems},
             {"certified", s.certified},
             {"uncertain", s.uncertain},
             {"refused", s.refused},
             {"pruned", s.pruned},
             {"min_margin", (s.problems == 0 && s.pruned == 0) ? Json(nullptr) : io::json_measure(s.min_margin)},
             {"min_margin_is_prune_bound", s.min_margin_is_prune_bound},
             {"worst", s.worst ? problem_json(*s.worst) : Json(nullptr)}});
  j["conditions"] = conds;
  j["offending_total"] = r.offending_total;
  Json off = Json::array();
  for (const auto& p : r.offending) off.push_back(problem_json(p));
  j["offending"] = off;
  j["hull"] = {{"runs", r.hull_runs},
               {"failures", r.hull_failures},
               {"non_convex", r.non_convex_hulls},
               {"predicate_calls", r.predicate_calls},
               {"uncertain_answers", r.uncertain_answers},
               {"max_backward_error", io::json_measure(r.max_hull_backward_error)}};
  j["pairs"] = {{"non_adjacent", r.non_adjacent_pairs},
                {"computed", r.pairs_computed},
                {"prune_radius", o.prune ? Json(r.prune_radius) : Json(nullptr)}};
  j["time_s"] = time_s;
  return j;
}

std::string extrusion_report_text(const io::Contour_input& in, std::string_view kernel, std::string_view algorithm,
                                  const Extrusion_options& o, const Extrusion_report& r, double time_s) {
  const Bezier_contour& c = *in.contour;
  std::string out;
  const auto kv = [&](const std::string& k, const std::string& v) {
    Key_value_text line(18);
    line.add(k, v);
    out += line.str();
  };
  kv("input", in.source + " (" + std::to_string(c.size()) + " curves" + (in.three_d ? ", 3D" : "") + ")");
  kv("kernel", std::string(kernel) + ", algorithm " + std::string(algorithm));
  kv("uncertainty", format_g(o.relative_uncertainty, 3) + " relative" +
                        (o.absolute_uncertainty > 0 ? " + " + format_g(o.absolute_uncertainty, 3) + " absolute" : ""));
  if (in.projection)
    kv("rotation", "d = " + format_g(in.projection->direction.x, 6) + ", " + format_g(in.projection->direction.y, 6) +
                       ", " + format_g(in.projection->direction.z, 6) + " -> z; error <= " +
                       format_g(in.projection->rotation_error, 3));
  kv("verdict", std::string(to_string(r.verdict)));
  Text_table t({"condition", "verdict", "problems", "certified", "uncertain", "refused", "pruned", "min margin", "worst slack"});
  t.set_left_columns(2);
  for (const auto& s : r.conditions)
    t.add_row({std::to_string(static_cast<int>(s.condition)) + " " + std::string(to_string(s.condition)),
               std::string(to_string(s.verdict)), std::to_string(s.problems), std::to_string(s.certified),
               std::to_string(s.uncertain), std::to_string(s.refused), std::to_string(s.pruned),
               (s.problems == 0 && s.pruned == 0) ? "-" : measure4(s.min_margin) + (s.min_margin_is_prune_bound ? " (>=)" : ""),
               s.worst ? measure4(s.worst->slack()) : "-"});
  out += "\n" + t.str();
  if (r.offending_total > 0) {
    out += "\nnot certified: " + std::to_string(r.offending_total) + " problem(s)" +
           (r.offending.size() < r.offending_total ? ", the " + std::to_string(r.offending.size()) + " with the smallest slack:" : ":") + "\n";
    Text_table p({"condition", "set", "where", "margin", "uncertainty", "computation error", "verdict"});
    p.set_left_columns(3);
    for (const auto& e : r.offending)
      p.add_row({std::to_string(static_cast<int>(e.condition)), std::string(e.set), problem_where(e),
                 measure4(e.margin), measure4(e.uncertainty),
                 measure4(e.computation_error), std::string(to_string(e.verdict))});
    out += p.str();
  }
  out += "\n";
  kv("hull problems", std::to_string(r.hull_runs) + " runs, " + std::to_string(r.hull_failures) + " failed, " +
                          std::to_string(r.non_convex_hulls) + " not convex, " + std::to_string(r.uncertain_answers) +
                          " uncertain answers of " + std::to_string(r.predicate_calls) +
                          " tests, largest backward error " + measure4(r.max_hull_backward_error));
  kv("condition 3 pairs", std::to_string(r.pairs_computed) + " computed exactly of " + std::to_string(r.non_adjacent_pairs) +
                              (o.prune ? ", prune radius " + format_g(r.prune_radius, 3) : std::string(", no prune")));
  kv("time", format_g(time_s * 1e3, 3) + " ms");
  return out;
}

void write_extrusion_svg(const std::string& path, const Bezier_contour& c, const Extrusion_report& r,
                         const std::string& title) {
  constexpr double size = 640;
  io::Svg_canvas svg(size, size);
  svg.set_plot_area(20, 52, size - 20, size - 60);
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  for (std::size_t m = 0; m < c.size(); ++m)
    for (const auto& p : c[m].control_points()) {
      xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
      ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
    }
  svg.fit(xmin, ymin, xmax, ymax);
  const bool detail = c.size() <= 2000;
  if (detail) {
    svg.begin_group("fill=\"#9e9e9e\" fill-opacity=\"0.18\" stroke=\"#9e9e9e\" stroke-width=\"0.6\"");
    for (std::size_t m = 0; m < c.size(); ++m) svg.polygon(exact_hull(c[m].control_points()), true, "");
    svg.end_group();
    svg.begin_group("fill=\"none\" stroke=\"#616161\" stroke-width=\"0.8\" stroke-dasharray=\"3,3\"");
    for (std::size_t m = 0; m < c.size(); ++m) svg.polygon(c[m].control_points(), false, "");
    svg.end_group();
  }
  auto sampled = [&](std::size_t m) {
    std::vector<Point_2<double>> s;
    const int k = c.size() > 2000 ? 8 : 48;
    for (int i = 0; i <= k; ++i) s.push_back(c[m](static_cast<double>(i) / k));
    return s;
  };
  svg.begin_group("fill=\"none\" stroke=\"#1565c0\" stroke-width=\"1.8\" stroke-linejoin=\"round\"");
  for (std::size_t m = 0; m < c.size(); ++m) svg.polygon(sampled(m), false, "");
  svg.end_group();
  // offending problems: highlight the curves involved
  std::set<std::pair<int, std::size_t>> marked;
  for (const auto& p : r.offending) {
    const char* colour = p.condition == Extrusion_condition::no_self_intersection ? "#d50000"
                         : p.condition == Extrusion_condition::adjacent_curves    ? "#ef6c00"
                                                                                  : "#ad1457";
    const std::string style = std::string("fill=\"none\" stroke=\"") + colour + "\" stroke-width=\"3.2\" stroke-opacity=\"0.8\"";
    for (std::size_t m : {p.curve_a, p.curve_b})
      if (marked.insert({static_cast<int>(p.condition), m}).second) svg.polygon(sampled(m), false, style);
    if (p.condition == Extrusion_condition::adjacent_curves)
      svg.circle(c[p.curve_b][0], 6, std::string("fill=\"none\" stroke=\"") + colour + "\" stroke-width=\"2\"");
  }
  if (detail)
    for (std::size_t m = 0; m < c.size(); ++m) svg.circle(c[m][0], 2.4, "fill=\"#1565c0\"");
  svg.view_text(20, 22, title, "font-size=\"15\" font-weight=\"bold\"");
  std::string line = std::to_string(c.size()) + " curves, verdict " + std::string(to_string(r.verdict)) + "; min margins";
  for (const auto& s : r.conditions) {  // appended piecewise: GCC 12 warns (-Wrestrict) on " " + std::string&&
    line += ' ';
    line += std::to_string(static_cast<int>(s.condition));
    line += ": ";
    line += (s.problems == 0 && s.pruned == 0) ? std::string("-") : measure4(s.min_margin);
  }
  svg.view_text(20, 40, line, "font-size=\"11.5\" fill=\"#333\"");
  const double y = size - 30;
  svg.view_line(24, y, 48, y, "stroke=\"#1565c0\" stroke-width=\"1.8\"");
  svg.view_text(54, y + 4, "curve", "font-size=\"12\"");
  svg.view_square(110, y, 12, "fill=\"#9e9e9e\" fill-opacity=\"0.3\" stroke=\"#9e9e9e\"");
  svg.view_text(122, y + 4, "control hull", "font-size=\"12\"");
  svg.view_line(210, y, 234, y, "stroke=\"#d50000\" stroke-width=\"3.2\"");
  svg.view_text(240, y + 4, "cond. 1 not certified", "font-size=\"12\"");
  svg.view_line(372, y, 396, y, "stroke=\"#ef6c00\" stroke-width=\"3.2\"");
  svg.view_text(402, y + 4, "cond. 2", "font-size=\"12\"");
  svg.view_line(460, y, 484, y, "stroke=\"#ad1457\" stroke-width=\"3.2\"");
  svg.view_text(490, y + 4, "cond. 3", "font-size=\"12\"");
  svg.write(path);
}

}  // namespace relgeo::tool
