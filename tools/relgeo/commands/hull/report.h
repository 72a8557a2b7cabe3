// tools/relgeo/commands/hull/report.h — a computed hull as the tool reports it: the
// JSON record of `relgeo hull` (SPEC Sec. 8; also the rows of the experiment's
// hull section) and the readable text summary.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "cli/text.h"
#include "commands/hull/facade.h"
#include "kernels/registry.h"
#include "relgeo/io/json.h"

namespace relgeo::tool {

/// The JSON record: algorithm, kernel, kernel_model, certified, n, status,
/// failure, hull_indices, hull, convex, error, backward_error,
/// backward_error_bound, coordinate_bound, moved_points, worst_point,
/// uncertain_answers, predicate_calls, time_s. `with_hull` = false leaves out
/// hull_indices and hull (large experiment inputs).
io::Json hull_report_json(std::string_view algorithm, const Kernel_entry& kernel,
                      std::span<const Point_2<double>> input, const Hull_evaluation& e,
                      bool with_hull = true);

/// The readable summary of `relgeo hull --format text` (hull vertices listed
/// up to `max_listed`).
std::string hull_report_text(std::string_view algorithm, const Kernel_entry& kernel,
                             std::string_view input_name, std::span<const Point_2<double>> input,
                             const Hull_evaluation& e, std::size_t max_listed = 50);

}  // namespace relgeo::tool
