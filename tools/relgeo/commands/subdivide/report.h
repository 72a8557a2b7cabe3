// tools/relgeo/commands/subdivide/report.h — the subdivision measures as the
// tool reports them (subdivide and the experiment's subdivision section).
#pragma once

#include "commands/subdivide/facade.h"
#include "relgeo/io/json.h"

namespace relgeo::tool {

/// One bound method's summary: method, is_bound, min_lower, max_upper,
/// mean_width, mean_tightness, max_tightness, tightness_faces, samples_outside.
io::Json bound_json(const Bound_summary& b);

}  // namespace relgeo::tool
