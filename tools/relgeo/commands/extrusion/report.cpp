// tools/relgeo/extrusion_common.cpp — the extrusion command's input format,
// report and picture (no kernel instantiation: see extrusion_eval.cpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "extrusion_runs.h"
#include "linear_curves_commands.h"
#include "relgeo/error/convex_polygon.h"
#include "svg_writer.h"
#include "tool_common.h"

namespace relgeo::tool {

namespace {

double number(const Json& j, const std::string& what) {
  if (!j.is_number()) throw Usage_error(what + ": expected a number, got " + j.dump());
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw Usage_error(what + ": not a finite number");
  return v;
}

/// [x, y] or [x, y, z]; `dim` fixed by the first point (0: not yet).
Point_3<double> point(const Json& j, const std::string& what, int& dim) {
  if (!j.is_array() || (j.size() != 2 && j.size() != 3))
    throw Usage_error(what + ": expected [x, y] or [x, y, z], got " + j.dump());
  const int d = static_cast<int>(j.size());
  if (dim == 0) dim = d;
  if (d != dim)
    throw Usage_error(what + ": " + std::to_string(d) + " coordinates, but earlier points have " + std::to_string(dim));
  return {number(j[0], what), number(j[1], what), d == 3 ? number(j[2], what) : 0.0};
}

std::string problem_where(const Extrusion_problem& p) {
  if (p.condition == Extrusion_condition::no_self_intersection) return "curve " + std::to_string(p.curve_a);
  return "curves " + std::to_string(p.curve_a) + ", " + std::to_string(p.curve_b);
}

Json problem_json(const Extrusion_problem& p) {
  Json j;
  j["condition"] = static_cast<int>(p.condition);
  j["set"] = p.set;
  j["curves"] = Json::array({p.curve_a, p.curve_b});
  j["margin"] = extrusion_measure_json(p.margin);
  j["uncertainty"] = extrusion_measure_json(p.uncertainty);
  j["computation_error"] = extrusion_measure_json(p.computation_error);
  j["slack"] = extrusion_measure_json(p.slack());
  j["verdict"] = to_string(p.verdict);
  return j;
}

}  // namespace

Json extrusion_measure_json(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}
std::string extrusion_measure_text(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (v == 0) return "0";
  return format_g(v, 4);
}

std::string extrusion_help_footer() {
  return "Input (--input FILE, '-' for standard input): a JSON object with\n"
         "  \"degree\": v and \"points\": [[x, y], ...]   a closed chain of M v points: curve m has\n"
         "                                           the control points m v .. m v + v (mod M v)\n"
         "  or \"curves\": [[[x, y], ...], ...]          each curve's control points; the last point of\n"
         "                                           curve m must equal the first of curve m+1 (mod M)\n"
         "  points may be [x, y, z] (3D): then \"direction\": [dx, dy, dz] is required; the points\n"
         "  must lie on one plane orthogonal to d (within the uncertainty) and are rotated by the Q\n"
         "  carrying d to the z axis (Rodrigues); the rotation's rounding error enters the verdict.\n"
         "  optional: \"heights\": [l1, l2] (l1 < l2), \"uncertainty\": relative (default 1e-3: a\n"
         "  point R may be off by 1e-3 ||R||), \"absolute_uncertainty\" (default 0), \"name\".\n"
         "--uncertainty / --absolute-uncertainty override the file.\n"
         "\nConditions (thesis Sec. 3.4.1), each a planar convex-hull problem under --kernel and\n"
         "--algorithm, its margin the exact distance rounded down:\n"
         "  1 no-self-intersection  0 not in conv(q), q = {R_{i+1} - R_i}; margin dist(0, conv q)\n"
         "  2 adjacent-curves       0 not in conv(Q') nor conv(Q'') of each adjacent pair\n"
         "  3 disjoint-curves       disjoint control hulls of non-adjacent curves; margin: their separation\n"
         "Margins are signed (<= 0: violated). A problem is certified when margin > uncertainty +\n"
         "computation error (rounding of the differences, the hull algorithm's backward-error\n"
         "certificate, the rotation), refused when the condition fails for the stored data,\n"
         "uncertain otherwise. Condition 3 uses a sweep over bounding boxes (--no-prune: all pairs).\n"
         "\nJSON fields: input, name, kernel, algorithm, curves, degrees, dimension, direction,\n"
         "rotation, rotation_error, plane_heights, heights, uncertainty {relative, absolute},\n"
         "verdict (certified|uncertain|refused), certified, conditions [{condition, name, verdict,\n"
         "problems, certified, uncertain, refused, pruned, min_margin, min_margin_is_prune_bound,\n"
         "worst}], offending_total, offending [{condition, set, curves, margin, uncertainty,\n"
         "computation_error, slack, verdict}] (smallest slack first, at most --max-listed), hull\n"
         "{runs, failures, non_convex, predicate_calls, uncertain_answers, max_backward_error}, pairs\n"
         "{non_adjacent, computed, prune_radius}, time_s, [svg].\n"
         "SVG: curves blue, control polygons dashed, control hulls grey; offending curves red\n"
         "(condition 1), orange (2), magenta (3); y up.\n"
         "Exit codes: 0 checked (whatever the verdict); 1 a hull algorithm failed (e.g.\n"
         "graham-incremental's non-termination; the verdict is then at best uncertain); 2 bad input.\n";
}

Extrusion_input parse_extrusion_input(const std::string& text, const std::string& source,
                                      std::optional<double> relative, std::optional<double> absolute) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const std::exception& e) {
    throw Usage_error(source + ": not JSON: " + e.what());
  }
  if (!j.is_object()) throw Usage_error(source + ": expected a JSON object");
  static const std::set<std::string> known = {"degree", "points", "curves", "direction", "heights",
                                              "uncertainty", "absolute_uncertainty", "name", "comment"};
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!known.count(it.key())) throw Usage_error(source + ": unknown field \"" + it.key() + "\"");
  Extrusion_input in;
  in.source = source;
  const std::string at = source + ": ";
  if (j.contains("uncertainty")) {
    in.relative_uncertainty = number(j["uncertainty"], at + "uncertainty");
    if (in.relative_uncertainty < 0) throw Usage_error(at + "uncertainty must be >= 0");
  }
  if (j.contains("absolute_uncertainty")) {
    in.absolute_uncertainty = number(j["absolute_uncertainty"], at + "absolute_uncertainty");
    if (in.absolute_uncertainty < 0) throw Usage_error(at + "absolute_uncertainty must be >= 0");
  }
  if (relative) in.relative_uncertainty = *relative;
  if (absolute) in.absolute_uncertainty = *absolute;
  if (j.contains("heights")) {
    const Json& h = j["heights"];
    if (!h.is_array() || h.size() != 2) throw Usage_error(at + "heights: expected [l1, l2]");
    const double l1 = number(h[0], at + "heights"), l2 = number(h[1], at + "heights");
    if (!(l1 < l2)) throw Usage_error(at + "heights: l1 < l2 required");
    in.heights = std::pair{l1, l2};
  }
  // ---- the control points, curve by curve -------------------------------------
  const bool has_points = j.contains("points"), has_curves = j.contains("curves");
  if (has_points == has_curves) throw Usage_error(at + "give either \"points\" (with \"degree\") or \"curves\"");
  int dim = 0;
  std::vector<std::vector<Point_3<double>>> curves;
  if (has_points) {
    if (!j.contains("degree") || !j["degree"].is_number_integer())
      throw Usage_error(at + "\"points\" needs an integer \"degree\"");
    const long long v = j["degree"].get<long long>();
    if (v < 1) throw Usage_error(at + "degree " + std::to_string(v) + ": the degree must be at least 1");
    const Json& pts = j["points"];
    if (!pts.is_array() || pts.empty()) throw Usage_error(at + "points: expected a non-empty array of points");
    std::vector<Point_3<double>> chain;
    for (std::size_t i = 0; i < pts.size(); ++i) chain.push_back(point(pts[i], at + "points[" + std::to_string(i) + "]", dim));
    const auto deg = static_cast<std::size_t>(v);
    if (chain.size() % deg != 0)
      throw Usage_error(at + std::to_string(chain.size()) + " points do not form a closed chain of degree-" +
                        std::to_string(deg) + " curves (need a multiple of " + std::to_string(deg) + ")");
    for (std::size_t m = 0; m < chain.size() / deg; ++m) {
      curves.emplace_back();
      for (std::size_t i = 0; i <= deg; ++i) curves.back().push_back(chain[(m * deg + i) % chain.size()]);
    }
  } else {
    if (j.contains("degree")) throw Usage_error(at + "\"degree\" goes with \"points\", not with \"curves\"");
    const Json& cs = j["curves"];
    if (!cs.is_array() || cs.empty()) throw Usage_error(at + "curves: expected a non-empty array of curves");
    for (std::size_t m = 0; m < cs.size(); ++m) {
      const std::string w = at + "curves[" + std::to_string(m) + "]";
      if (!cs[m].is_array()) throw Usage_error(w + ": expected an array of control points");
      if (cs[m].size() < 2)
        throw Usage_error(w + ": degree " + std::to_string(static_cast<long>(cs[m].size()) - 1) +
                          "; a curve needs at least 2 control points (degree >= 1)");
      curves.emplace_back();
      for (std::size_t i = 0; i < cs[m].size(); ++i)
        curves.back().push_back(point(cs[m][i], w + "[" + std::to_string(i) + "]", dim));
    }
    for (std::size_t m = 0; m < curves.size(); ++m) {
      const auto& a = curves[m].back();
      const auto& b = curves[(m + 1) % curves.size()].front();
      if (!(a == b))
        throw Usage_error(at + "the contour is not closed: curve " + std::to_string(m) + " ends at " +
                          format_point_17(a.x, a.y) + (dim == 3 ? " (z " + format_17(a.z) + ")" : "") +
                          " but curve " + std::to_string((m + 1) % curves.size()) + " starts at " +
                          format_point_17(b.x, b.y) + (dim == 3 ? " (z " + format_17(b.z) + ")" : ""));
    }
  }
  // ---- direction and projection ---------------------------------------------------
  in.three_d = dim == 3;
  std::vector<std::vector<Point_2<double>>> planar(curves.size());
  std::vector<std::vector<double>> scales(curves.size());
  if (in.three_d) {
    if (!j.contains("direction")) throw Usage_error(at + "3D points need \"direction\": [dx, dy, dz]");
    const Json& d = j["direction"];
    if (!d.is_array() || d.size() != 3) throw Usage_error(at + "direction: expected [dx, dy, dz]");
    const Point_3<double> dir{number(d[0], at + "direction"), number(d[1], at + "direction"),
                              number(d[2], at + "direction")};
    std::vector<Point_3<double>> all;
    for (const auto& c : curves) all.insert(all.end(), c.begin(), c.end());
    try {
      in.projection = project_along(all, dir);
    } catch (const Invalid_input& e) {
      throw Usage_error(at + e.what());
    }
    const Plane_projection& p = *in.projection;
    double max_norm = 0;
    for (double n : p.norms) max_norm = std::max(max_norm, n);
    const double tolerance = in.relative_uncertainty * max_norm + in.absolute_uncertainty;
    if (p.height_max - p.height_min > tolerance)
      throw Usage_error(at + "the points are not on one plane orthogonal to the direction: d.x ranges over [" +
                        format_g(p.height_min, 17) + ", " + format_g(p.height_max, 17) + "], more than the " +
                        "uncertainty " + format_g(tolerance, 3) + " allows");
    std::size_t k = 0;
    for (std::size_t m = 0; m < curves.size(); ++m)
      for (std::size_t i = 0; i < curves[m].size(); ++i, ++k) {
        planar[m].push_back(p.points[k]);
        scales[m].push_back(p.norms[k]);
      }
  } else {
    if (j.contains("direction")) {
      const Json& d = j["direction"];
      if (!d.is_array() || d.size() != 3) throw Usage_error(at + "direction: expected [dx, dy, dz]");
      if (number(d[0], at + "direction") != 0 || number(d[1], at + "direction") != 0 ||
          number(d[2], at + "direction") == 0)
        throw Usage_error(at + "2D points lie in the xy plane: the direction must be (0, 0, +-1); give 3D points for another direction");
    }
    for (std::size_t m = 0; m < curves.size(); ++m)
      for (const auto& p : curves[m]) planar[m].push_back({p.x, p.y});
  }
  try {
    in.contour = Bezier_contour::from_curves(planar);
  } catch (const Invalid_input& e) {
    throw Usage_error(at + e.what());
  }
  if (in.three_d) in.contour->set_scales(scales);
  return in;
}

Json extrusion_report_json(const Extrusion_input& in, std::string_view kernel, std::string_view algorithm,
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
    j["direction"] = Json::array({json_coordinate(p.direction.x), json_coordinate(p.direction.y), json_coordinate(p.direction.z)});
    Json rows = Json::array();
    for (const auto& row : p.rotation) rows.push_back(Json::array({json_coordinate(row[0]), json_coordinate(row[1]), json_coordinate(row[2])}));
    j["rotation"] = rows;
    j["rotation_error"] = p.rotation_error;
    j["plane_heights"] = Json::array({json_coordinate(p.height_min), json_coordinate(p.height_max)});
  } else {
    j["direction"] = Json::array({0, 0, 1});
    j["rotation"] = nullptr;
    j["rotation_error"] = 0;
    j["plane_heights"] = nullptr;
  }
  j["heights"] = in.heights ? Json::array({json_coordinate(in.heights->first), json_coordinate(in.heights->second)}) : Json(nullptr);
  j["uncertainty"] = {{"relative", o.relative_uncertainty}, {"absolute", o.absolute_uncertainty}};
  j["verdict"] = to_string(r.verdict);
  j["certified"] = r.verdict == Extrusion_verdict::certified;
  Json conds = Json::array();
  for (const auto& s : r.conditions) {
    Json cj;
    cj["condition"] = static_cast<int>(s.condition);
    cj["name"] = to_string(s.condition);
    cj["verdict"] = to_string(s.verdict);
    cj["problems"] = s.problems;
    cj["certified"] = s.certified;
    cj["uncertain"] = s.uncertain;
    cj["refused"] = s.refused;
    cj["pruned"] = s.pruned;
    cj["min_margin"] = (s.problems == 0 && s.pruned == 0) ? Json(nullptr) : extrusion_measure_json(s.min_margin);
    cj["min_margin_is_prune_bound"] = s.min_margin_is_prune_bound;
    cj["worst"] = s.worst ? problem_json(*s.worst) : Json(nullptr);
    conds.push_back(cj);
  }
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
               {"max_backward_error", extrusion_measure_json(r.max_hull_backward_error)}};
  j["pairs"] = {{"non_adjacent", r.non_adjacent_pairs},
                {"computed", r.pairs_computed},
                {"prune_radius", o.prune ? Json(r.prune_radius) : Json(nullptr)}};
  j["time_s"] = time_s;
  return j;
}

std::string extrusion_report_text(const Extrusion_input& in, std::string_view kernel, std::string_view algorithm,
                                  const Extrusion_options& o, const Extrusion_report& r, double time_s) {
  const Bezier_contour& c = *in.contour;
  std::string out;
  auto kv = [&](const std::string& k, const std::string& v) {
    out += k + std::string(k.size() < 18 ? 18 - k.size() : 1, ' ') + v + "\n";
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
               (s.problems == 0 && s.pruned == 0) ? "-" : extrusion_measure_text(s.min_margin) + (s.min_margin_is_prune_bound ? " (>=)" : ""),
               s.worst ? extrusion_measure_text(s.worst->slack()) : "-"});
  out += "\n" + t.str();
  if (r.offending_total > 0) {
    out += "\nnot certified: " + std::to_string(r.offending_total) + " problem(s)" +
           (r.offending.size() < r.offending_total ? ", the " + std::to_string(r.offending.size()) + " with the smallest slack:" : ":") + "\n";
    Text_table p({"condition", "set", "where", "margin", "uncertainty", "computation error", "verdict"});
    p.set_left_columns(3);
    for (const auto& e : r.offending)
      p.add_row({std::to_string(static_cast<int>(e.condition)), std::string(e.set), problem_where(e),
                 extrusion_measure_text(e.margin), extrusion_measure_text(e.uncertainty),
                 extrusion_measure_text(e.computation_error), std::string(to_string(e.verdict))});
    out += p.str();
  }
  out += "\n";
  kv("hull problems", std::to_string(r.hull_runs) + " runs, " + std::to_string(r.hull_failures) + " failed, " +
                          std::to_string(r.non_convex_hulls) + " not convex, " + std::to_string(r.uncertain_answers) +
                          " uncertain answers of " + std::to_string(r.predicate_calls) +
                          " tests, largest backward error " + extrusion_measure_text(r.max_hull_backward_error));
  kv("condition 3 pairs", std::to_string(r.pairs_computed) + " computed exactly of " + std::to_string(r.non_adjacent_pairs) +
                              (o.prune ? ", prune radius " + format_g(r.prune_radius, 3) : std::string(", no prune")));
  kv("time", format_g(time_s * 1e3, 3) + " ms");
  return out;
}

void write_extrusion_svg(const std::string& path, const Bezier_contour& c, const Extrusion_report& r,
                         const std::string& title) {
  constexpr double size = 640;
  Svg_canvas svg(size, size);
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
    line += (s.problems == 0 && s.pruned == 0) ? std::string("-") : extrusion_measure_text(s.min_margin);
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
