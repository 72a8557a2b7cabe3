// tools/relgeo/commands/hull/report.cpp — a computed hull as the tool
// reports it: JSON record and readable summary.
#include "commands/hull/report.h"

#include <cmath>

namespace relgeo::tool {

using io::Json;


Json hull_report_json(std::string_view algorithm, const Kernel_entry& kernel,
                      std::span<const Point_2<double>> input, const Hull_evaluation& e,
                      bool with_hull) {
  const Hull_run& r = e.run;
  Json j;
  j["algorithm"] = algorithm;
  j["kernel"] = kernel.label();
  j["kernel_model"] = kernel.name;
  j["certified"] = kernel.certified;
  j["n"] = input.size();
  j["status"] = r.status == Hull_status::ok ? "ok" : "failed";
  j["failure"] = r.status == Hull_status::ok ? Json(nullptr) : Json(r.failure);
  j["hull_size"] = r.indices.size();
  if (with_hull) {
    j["hull_indices"] = r.indices;
    Json hull = Json::array();
    for (std::size_t i : r.indices) hull.push_back(io::json_point(input[i].x, input[i].y));
    j["hull"] = std::move(hull);
  }
  j["convex"] = e.error.convex;
  j["error"] = io::json_measure(e.error.value);
  j["backward_error"] = io::json_measure(e.backward.value);
  j["backward_error_bound"] =
      r.backward_error_bound ? io::json_measure(*r.backward_error_bound) : Json(nullptr);
  j["coordinate_bound"] = io::json_coordinate(e.error.coordinate_bound);
  j["moved_points"] = e.backward.moved_points.size();
  j["worst_point"] = e.backward.worst_point ? Json(*e.backward.worst_point) : Json(nullptr);
  j["uncertain_answers"] = r.uncertain_answers;
  j["predicate_calls"] = r.predicate_calls_counted ? Json(r.predicate_calls) : Json(nullptr);
  j["time_s"] = r.time_s;
  return j;
}

std::string hull_report_text(std::string_view algorithm, const Kernel_entry& kernel,
                             std::string_view input_name, std::span<const Point_2<double>> input,
                             const Hull_evaluation& e, std::size_t max_listed) {
  const Hull_run& r = e.run;
  Key_value_text text(17);
  const auto kv = [&](const std::string& k, const std::string& v) { text.add(k, v); };
  kv("algorithm", std::string(algorithm));
  kv("kernel", kernel.label() + " (" + kernel.name +
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
  kv("error E", measure_text(e.error.value) + "  (eq. 3.2: Hausdorff distance to the exact hull / M, M = " +
                    format_g(e.error.coordinate_bound, 17) + ")");
  std::string back = measure_text(e.backward.value);
  if (!std::isinf(e.backward.value)) {
    back += "  (" + std::to_string(e.backward.moved_points.size()) +
            " input point(s) outside the hull move onto it";
    if (e.backward.worst_point) back += ", farthest: point " + std::to_string(*e.backward.worst_point);
    back += ")";
  }
  kv("backward error", back);
  kv("a-priori bound", r.backward_error_bound ? measure_text(*r.backward_error_bound)
                                              : std::string(algorithm == "graham-fortune"
                                                                ? "none (the kernel gives no guarantee)"
                                                                : "none (graham-fortune only)"));
  kv("uncertain", std::to_string(r.uncertain_answers) + " answers" +
                      (r.predicate_calls_counted
                           ? " of " + std::to_string(r.predicate_calls) + " orientation tests"
                           : std::string(" (orientation tests not counted for cgal)")));
  kv("time", duration_text(r.time_s) + " (algorithm only)");
  return text.str();
}

}  // namespace relgeo::tool
