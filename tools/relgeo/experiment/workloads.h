// tools/relgeo/experiment/workloads.h — the predicate workloads of the
// kernels section under a kernel named at run time (instantiated for every
// kernel in dispatch_workloads.cpp only).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/analysis/sign_tally.h"

namespace relgeo::tool {

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
/// `exact`.  [dispatch_workloads.cpp]
Workload_measurement measure_orientation_2(std::string_view kernel,
                                           std::span<const analysis::Orientation_2_case> cases,
                                           std::span<const Certified_sign> exact,
                                           double min_seconds);
/// Same for orientation_3.                                    [dispatch_workloads.cpp]
Workload_measurement measure_orientation_3(std::string_view kernel,
                                           std::span<const analysis::Orientation_3_case> cases,
                                           std::span<const Certified_sign> exact,
                                           double min_seconds);

}  // namespace relgeo::tool
