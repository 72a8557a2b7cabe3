// tools/relgeo/hull_common.cpp — what the `hull` command and the experiment's
// hull section share, except the per-kernel instantiations (hull_eval.cpp):
// algorithm names, the error measures, the SVG picture, the JSON/text report.
#include <algorithm>
#include <cmath>
#include <limits>

#include "hull_report.h"
#include "hull_runs.h"
#include "kernel_names.h"
#include "relgeo/error/convex_polygon.h"
#include "svg_writer.h"
#include "tool_common.h"

namespace relgeo::tool {

// ---- names -------------------------------------------------------------------

const std::vector<std::string>& hull_algorithm_names() {
  static const std::vector<std::string> names = {"graham-incremental", "graham-fortune",
                                                 "monotone-chain", "cgal"};
  return names;
}

std::string hull_algorithms_help() {
  return "Algorithms (--algorithm):\n"
         "  graham-incremental  relgeo::graham_incremental: the incremental hull of Kettner et al.\n"
         "                      (unstable; non-termination is detected and reported, exit 1)\n"
         "  graham-fortune      relgeo::graham_fortune: Fortune's stable Graham scan, with an\n"
         "                      a-priori backward-error bound\n"
         "  monotone-chain      relgeo::monotone_chain: Andrew's monotone chain\n"
         "  cgal                CGAL::convex_hull_2 through relgeo::cgal_convex_hull (only with\n"
         "                      the kernels cgal-sc, cgal-epick, cgal-epeck); CGAL needs exact\n"
         "                      predicates: under cgal-sc it runs in a child process, and a crash\n"
         "                      (seen: SIGSEGV) is reported as status failed (exit 1)\n";
}

void validate_hull_combination(std::string_view algorithm, std::string_view kernel) {
  const auto& names = hull_algorithm_names();
  if (std::find(names.begin(), names.end(), algorithm) == names.end()) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw Usage_error("unknown algorithm '" + std::string(algorithm) + "'; algorithms: " + list);
  }
  validate_kernel_name(kernel);
  if (algorithm == "cgal" && !kernel.starts_with("cgal-"))
    throw Usage_error("algorithm 'cgal' (CGAL::convex_hull_2) needs a CGAL kernel (cgal-sc, "
                      "cgal-epick or cgal-epeck), not '" + std::string(kernel) + "'");
}

// ---- measures ----------------------------------------------------------------

Hull_evaluation evaluate_hull(std::string_view algorithm, std::string_view kernel,
                              std::span<const Point_2<double>> points, double min_seconds,
                              const relgeo::Hull_options& options) {
  Hull_evaluation e;
  e.run = run_hull(algorithm, kernel, points, min_seconds, options);
  e.error = hull_error(points, e.run.indices);
  e.backward = hull_backward_error(points, e.run.indices);
  return e;
}

std::vector<Point_2<double>> classroom_example_a1() {
  return {{7.3000000000000194, 7.3000000000000167}, {24.000000000000068, 24.000000000000071},
          {24.00000000000005, 24.000000000000053},  {0.50000000000001621, 0.50000000000001243},
          {8, 4}, {4, 9}, {15, 27}, {26, 25}, {19, 11}};
}

// ---- report ------------------------------------------------------------------

Json error_json(double v) {
  if (std::isinf(v)) return "inf";
  return v;
}

std::string error_text(double v) {
  if (std::isinf(v)) return "inf";
  if (v == 0) return "0";
  return format_g(v, 3);
}

std::string duration_text(double s) {
  if (s < 1e-6) return format_g(s * 1e9, 3) + " ns";
  if (s < 1e-3) return format_g(s * 1e6, 3) + " us";
  if (s < 1) return format_g(s * 1e3, 3) + " ms";
  return format_g(s, 3) + " s";
}

Json hull_report_json(std::string_view algorithm, const Kernel_info& kernel,
                      std::span<const Point_2<double>> input, const Hull_evaluation& e,
                      bool with_hull) {
  const Hull_run& r = e.run;
  Json j;
  j["algorithm"] = algorithm;
  j["kernel"] = kernel.name;
  j["kernel_model"] = kernel.model;
  j["certified"] = kernel.certified;
  j["n"] = input.size();
  j["status"] = r.status == Hull_status::ok ? "ok" : "failed";
  j["failure"] = r.status == Hull_status::ok ? Json(nullptr) : Json(r.failure);
  j["hull_size"] = r.indices.size();
  if (with_hull) {
    j["hull_indices"] = r.indices;
    Json hull = Json::array();
    for (std::size_t i : r.indices) hull.push_back(json_point(input[i].x, input[i].y));
    j["hull"] = std::move(hull);
  }
  j["convex"] = e.error.convex;
  j["error"] = error_json(e.error.value);
  j["backward_error"] = error_json(e.backward.value);
  j["backward_error_bound"] =
      r.backward_error_bound ? error_json(*r.backward_error_bound) : Json(nullptr);
  j["coordinate_bound"] = json_coordinate(e.error.coordinate_bound);
  j["moved_points"] = e.backward.moved_points.size();
  j["worst_point"] = e.backward.worst_point ? Json(*e.backward.worst_point) : Json(nullptr);
  j["uncertain_answers"] = r.uncertain_answers;
  j["predicate_calls"] = r.predicate_calls_counted ? Json(r.predicate_calls) : Json(nullptr);
  j["time_s"] = r.time_s;
  return j;
}

std::string hull_report_text(std::string_view algorithm, const Kernel_info& kernel,
                             std::string_view input_name, std::span<const Point_2<double>> input,
                             const Hull_evaluation& e, std::size_t max_listed) {
  const Hull_run& r = e.run;
  std::string text;
  auto kv = [&](const std::string& k, const std::string& v) {
    text += k + std::string(k.size() < 17 ? 17 - k.size() : 1, ' ') + v + "\n";
  };
  kv("algorithm", std::string(algorithm));
  kv("kernel", kernel.name + " (" + kernel.model +
                   (kernel.exact_predicates ? ", exact predicates)"
                    : kernel.certified      ? ", certified)"
                                            : ", not certified)"));
  kv("input", std::string(input_name) + " (" + std::to_string(input.size()) +
                  (input.size() == 1 ? " point)" : " points)"));
  kv("status", r.status == Hull_status::ok ? "ok" : "FAILED: " + r.failure);
  std::string idx;
  for (std::size_t i = 0; i < r.indices.size() && i < max_listed; ++i) {
    if (i) idx += ' ';
    idx += std::to_string(r.indices[i]);
  }
  if (r.indices.size() > max_listed) idx += " ...";
  std::string hull_line = std::to_string(r.indices.size()) + (r.indices.size() == 1 ? " vertex" : " vertices");
  if (!r.indices.empty()) {
    hull_line += ": ";
    hull_line += idx;
  }
  kv("hull", hull_line);
  for (std::size_t i = 0; i < r.indices.size() && i < max_listed; ++i) {
    const auto& p = input[r.indices[i]];
    kv("", std::to_string(r.indices[i]) + "  " + format_point_17(p.x, p.y));
  }
  kv("convex", e.error.convex ? "yes (a simple, strictly convex, counterclockwise polygon; exact check)"
                              : "NO (the polygon, in the order returned, is not simple, strictly convex and counterclockwise)");
  kv("error E", error_text(e.error.value) + "  (eq. 3.2: Hausdorff distance to the exact hull / M, M = " +
                    format_g(e.error.coordinate_bound, 17) + ")");
  std::string back = error_text(e.backward.value);
  if (!std::isinf(e.backward.value)) {
    back += "  (" + std::to_string(e.backward.moved_points.size()) +
            " input point(s) outside the hull move onto it";
    if (e.backward.worst_point) back += ", farthest: point " + std::to_string(*e.backward.worst_point);
    back += ")";
  }
  kv("backward error", back);
  kv("a-priori bound", r.backward_error_bound ? error_text(*r.backward_error_bound)
                                              : std::string(algorithm == "graham-fortune"
                                                                ? "none (the kernel gives no guarantee)"
                                                                : "none (graham-fortune only)"));
  kv("uncertain", std::to_string(r.uncertain_answers) + " answers" +
                      (r.predicate_calls_counted
                           ? " of " + std::to_string(r.predicate_calls) + " orientation tests"
                           : std::string(" (orientation tests not counted for cgal)")));
  kv("time", duration_text(r.time_s) + " (algorithm only)");
  return text;
}

// ---- picture -------------------------------------------------------------------

void write_hull_svg(const std::string& path, std::span<const Point_2<double>> points,
                    const Hull_evaluation& e, const std::string& title) {
  constexpr double size = 600;
  constexpr std::size_t max_drawn = 100000;
  Svg_canvas svg(size, size);
  svg.set_plot_area(20, 52, size - 20, size - 100);
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  for (const auto& p : points) {
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
    ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  }
  if (points.empty()) xmin = ymin = 0, xmax = ymax = 1;
  svg.fit(xmin, ymin, xmax, ymax);

  const std::vector<Point_2<double>> exact = exact_hull(points);
  std::vector<Point_2<double>> computed;
  for (std::size_t i : e.run.indices) computed.push_back(points[i]);

  // exact hull: wide, light green, dashed; computed hull: blue
  svg.polygon(exact, true,
              "fill=\"#e8f5e9\" stroke=\"#2e7d32\" stroke-width=\"5\" stroke-opacity=\"0.45\" "
              "stroke-dasharray=\"10,6\" stroke-linejoin=\"round\"");
  svg.polygon(computed, true,
              "fill=\"none\" stroke=\"#1565c0\" stroke-width=\"1.6\" stroke-linejoin=\"round\"");
  if (points.size() <= max_drawn) {
    svg.begin_group("fill=\"#424242\"");
    for (const auto& p : points) svg.circle(p, 1.6, "");
    svg.end_group();
  }
  for (const auto& p : computed) svg.circle(p, 2.6, "fill=\"#1565c0\"");
  // computed hull vertices that are not vertices of the exact hull
  auto less = [](const Point_2<double>& a, const Point_2<double>& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  };
  std::vector<Point_2<double>> exact_sorted = exact;
  std::sort(exact_sorted.begin(), exact_sorted.end(), less);
  std::size_t not_vertices = 0;
  for (const auto& p : computed)
    if (!std::binary_search(exact_sorted.begin(), exact_sorted.end(), p, less)) {
      svg.square(p, 9, "fill=\"none\" stroke=\"#ef6c00\" stroke-width=\"2\"");
      ++not_vertices;
    }
  // lost points: input points outside the computed hull
  for (std::size_t i : e.backward.moved_points)
    svg.circle(points[i], 7, "fill=\"none\" stroke=\"#d50000\" stroke-width=\"2.2\"");

  // title
  svg.view_text(20, 22, title, "font-size=\"15\" font-weight=\"bold\"");
  const bool hull_inf = std::isinf(e.backward.value);
  svg.view_text(20, 40,
                std::to_string(points.size()) + " points, |hull| = " + std::to_string(computed.size()) +
                    ", exact |hull| = " + std::to_string(exact.size()) + ", E = " +
                    error_text(e.error.value) + ", backward error = " +
                    error_text(e.backward.value) +
                    (e.run.status == Hull_status::ok ? "" : ", FAILED: " + e.run.failure),
                "font-size=\"11.5\" fill=\"#333\"");
  // legend (rows at the bottom)
  const double y1 = size - 76, y2 = size - 56, y3 = size - 36, y4 = size - 12;
  svg.view_circle(28, y1, 1.6, "fill=\"#424242\"");
  svg.view_text(38, y1 + 4, points.size() <= max_drawn ? "input point" : "input points (too many: not drawn)",
                "font-size=\"12\"");
  svg.view_line(250, y1, 280, y1, "stroke=\"#1565c0\" stroke-width=\"1.6\"");
  svg.view_circle(265, y1, 2.6, "fill=\"#1565c0\"");
  svg.view_text(288, y1 + 4, "computed hull", "font-size=\"12\"");
  svg.view_line(420, y1, 450, y1,
                "stroke=\"#2e7d32\" stroke-width=\"5\" stroke-opacity=\"0.45\" stroke-dasharray=\"10,6\"");
  svg.view_text(458, y1 + 4, "exact hull", "font-size=\"12\"");
  svg.view_circle(28, y2, 7, "fill=\"none\" stroke=\"#d50000\" stroke-width=\"2.2\"");
  svg.view_text(42, y2 + 4,
                "lost point: input point outside the computed hull (" +
                    (hull_inf ? std::string("n/a: hull not convex")
                              : std::to_string(e.backward.moved_points.size())) + ")",
                "font-size=\"12\"");
  svg.view_square(28, y3, 9, "fill=\"none\" stroke=\"#ef6c00\" stroke-width=\"2\"");
  svg.view_text(42, y3 + 4,
                "computed hull vertex that is not a vertex of the exact hull (" +
                    std::to_string(not_vertices) + ")",
                "font-size=\"12\"");
  svg.view_text(20, y4, "y up; x in [" + format_g(xmin, 6) + ", " + format_g(xmax, 6) + "], y in [" +
                            format_g(ymin, 6) + ", " + format_g(ymax, 6) + "]; marks not to scale",
                "font-size=\"10.5\" fill=\"#555\"");
  svg.write(path);
}

}  // namespace relgeo::tool
