// tools/relgeo/commands/subdivide/report.cpp
#include "commands/subdivide/report.h"

namespace relgeo::tool {

io::Json bound_json(const Bound_summary& b) {
  return io::Json{{"method", b.method},
                  {"is_bound", b.is_bound},
                  {"min_lower", b.min_lower},
                  {"max_upper", b.max_upper},
                  {"mean_width", b.mean_width},
                  {"mean_tightness", b.mean_tightness},
                  {"max_tightness", b.max_tightness},
                  {"tightness_faces", b.tightness_faces},
                  {"samples_outside", b.samples_outside}};
}

}  // namespace relgeo::tool
