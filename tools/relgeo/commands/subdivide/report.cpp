// tools/relgeo/commands/subdivide/report.cpp
#include "commands/subdivide/report.h"

namespace relgeo::tool {

io::Json bound_json(const Bound_summary& b) {
  io::Json j;
  j["method"] = b.method;
  j["is_bound"] = b.is_bound;
  j["min_lower"] = b.min_lower;
  j["max_upper"] = b.max_upper;
  j["mean_width"] = b.mean_width;
  j["mean_tightness"] = b.mean_tightness;
  j["max_tightness"] = b.max_tightness;
  j["tightness_faces"] = b.tightness_faces;
  j["samples_outside"] = b.samples_outside;
  return j;
}

}  // namespace relgeo::tool
