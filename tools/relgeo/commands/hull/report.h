// tools/relgeo/hull_report.h — a computed hull as the tool reports it: the
// JSON record of `relgeo hull` (SPEC Sec. 8; also the rows of the experiment's
// hull section) and the readable text summary.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "hull_runs.h"
#include "json_output.h"
#include "kernel_runs.h"

namespace relgeo::tool {

/// An error measure as JSON: the number, or the string "inf" when infinite.
Json error_json(double v);
/// An error measure as text: "0", "inf" or 3 significant digits.
std::string error_text(double v);
/// A duration in s as text with a unit (ns, us, ms, s).
std::string duration_text(double seconds);

/// The JSON record: algorithm, kernel, kernel_model, certified, n, status,
/// failure, hull_indices, hull, convex, error, backward_error,
/// backward_error_bound, coordinate_bound, moved_points, worst_point,
/// uncertain_answers, predicate_calls, time_s. `with_hull` = false leaves out
/// hull_indices and hull (large experiment inputs).
Json hull_report_json(std::string_view algorithm, const Kernel_info& kernel,
                      std::span<const Point_2<double>> input, const Hull_evaluation& e,
                      bool with_hull = true);

/// The readable summary of `relgeo hull --format text` (hull vertices listed
/// up to `max_listed`).
std::string hull_report_text(std::string_view algorithm, const Kernel_info& kernel,
                             std::string_view input_name, std::span<const Point_2<double>> input,
                             const Hull_evaluation& e, std::size_t max_listed = 50);

}  // namespace relgeo::tool
