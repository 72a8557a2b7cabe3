// tools/relgeo/commands/hull/facade.h — planar convex hulls under an
// algorithm and a kernel named at run time, and the error measures of a
// computed hull. run_hull instantiates every algorithm under every kernel in
// dispatch.cpp only, so `hull`, `extrusion` and the experiment compile
// without the kernels.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "relgeo/error/hull_backward_error.h"
#include "relgeo/error/hull_error.h"
#include "relgeo/hull/hull_result.h"
#include "relgeo/kernel/point.h"

namespace relgeo::tool {

/// The algorithms of `relgeo hull --algorithm`, in help/table order:
/// graham-incremental, graham-fortune, monotone-chain, cgal.
const std::vector<std::string>& hull_algorithm_names();

/// One line per algorithm for the help text.
std::string hull_algorithms_help();

/// Throws Usage_error unless `algorithm` is known and can run under `kernel`
/// (kernel validated too): `cgal` (CGAL::convex_hull_2) needs a cgal-* kernel.
void validate_hull_combination(std::string_view algorithm, std::string_view kernel);

/// What one run of a hull algorithm produced.
struct Hull_run {
  Hull_status status = Hull_status::ok;
  std::string failure;               ///< empty when ok
  std::vector<std::size_t> indices;  ///< the hull, CCW, into the input
  std::size_t predicate_calls = 0;   ///< orientation tests (not counted for `cgal`)
  bool predicate_calls_counted = true;
  std::size_t uncertain_answers = 0;
  /// graham_fortune_backward_error_bound<K>(input) for graham-fortune, else empty.
  std::optional<double> backward_error_bound;
  double time_s = 0;        ///< algorithm time of the fastest timed run (points built before)
  std::size_t timed_runs = 0;
};

/// Runs `algorithm` under `kernel` on `points` (converted with the kernel's
/// construct_point_2 first, not timed). The run is repeated until
/// `min_seconds` have passed (at least once); time_s is the fastest.
/// \throws Usage_error for a bad name or combination; relgeo::Error from the
///   algorithm (Non_finite_input).                       [dispatch.cpp]
/// `options` go to graham-fortune and monotone-chain.
Hull_run run_hull(std::string_view algorithm, std::string_view kernel,
                  std::span<const Point_2<double>> points, double min_seconds = 0,
                  const relgeo::Hull_options& options = {});

/// A run with its error measures (exact, kernel independent).
struct Hull_evaluation {
  Hull_run run;
  Hull_error error;              ///< E of eq. (3.2)
  Hull_backward_error backward;  ///< the certificate
};
Hull_evaluation evaluate_hull(std::string_view algorithm, std::string_view kernel,
                              std::span<const Point_2<double>> points, double min_seconds = 0,
                              const relgeo::Hull_options& options = {});

/// The classroom example A1 of Kettner et al. (SPEC Sec. 3.1), in insertion order.
std::vector<Point_2<double>> classroom_example_a1();

}  // namespace relgeo::tool
