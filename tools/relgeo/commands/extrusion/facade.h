// tools/relgeo/commands/extrusion/facade.h — the extruded-object checker
// under a kernel and a hull algorithm named at run time (instantiated in
// dispatch.cpp only).
#pragma once

#include <string_view>

#include "relgeo/curves/contour.h"
#include "relgeo/curves/extrusion.h"

namespace relgeo::tool {

/// Runs check_extrusion under `kernel` with `algorithm` (the names of `relgeo
/// hull`; `cgal` only with CGAL kernels), timed: the fastest of runs repeated
/// until min_seconds (at least one). \throws Usage_error for bad names.
///                                                             [dispatch.cpp]
Extrusion_report run_extrusion(std::string_view algorithm, std::string_view kernel, const Bezier_contour& contour,
                               const Extrusion_options& options, double* time_s, double min_seconds = 0);

}  // namespace relgeo::tool
