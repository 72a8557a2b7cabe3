// tools/relgeo/kernel_runs.h — non-template entry points that run an analysis
// under a kernel chosen at run time. Each is instantiated for every kernel in
// its own translation unit (grid_eval.cpp, workload_eval.cpp), so the
// commands and the experiment sections compile without the kernels.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "relgeo/analysis/orientation_grid.h"
#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/analysis/sign_tally.h"

namespace relgeo::tool {

/// Static facts about a kernel, read from its type.
struct Kernel_info {
  std::string name;   ///< command-line name ("failsafe")
  std::string model;  ///< K::name() ("failsafe<double>")
  bool certified = false;
  bool exact_predicates = false;
  bool slow = false;  ///< the experiment uses n/10 cases
};

/// \pre name is valid (Usage_error otherwise).              [grid_eval.cpp]
Kernel_info kernel_info(std::string_view name);

/// relgeo::analysis::evaluate_orientation_grid under the named kernel. [grid_eval.cpp]
analysis::Orientation_grid_result evaluate_grid(std::string_view kernel,
                                                const analysis::Orientation_grid_triple& triple,
                                                int size);

/// One kernel on one workload: the tally against the exact signs and the
/// time per predicate.
struct Workload_measurement {
  analysis::Sign_tally tally;
  double ns_per_predicate = 0;  ///< wall time per predicate of the fastest timed pass
  std::size_t timed_evaluations = 0;  ///< evaluations timed (passes x cases)
};

/// Evaluates the named kernel's orientation_2 on every case (points built
/// first, not timed), repeating the timed loop until `min_seconds` have passed
/// (at least once; the fastest pass counts), and tallies the answers against
/// `exact`.  [workload_eval.cpp]
Workload_measurement measure_orientation_2(std::string_view kernel,
                                           std::span<const analysis::Orientation_2_case> cases,
                                           std::span<const Certified_sign> exact,
                                           double min_seconds);
/// Same for orientation_3.                                    [workload_eval.cpp]
Workload_measurement measure_orientation_3(std::string_view kernel,
                                           std::span<const analysis::Orientation_3_case> cases,
                                           std::span<const Certified_sign> exact,
                                           double min_seconds);

}  // namespace relgeo::tool
