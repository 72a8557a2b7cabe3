// tools/relgeo/commands/csg/report.cpp — the JSON record of a CSG evaluation
// (`relgeo csg --format json`, the Python module's csg()).
#include "commands/boolean/report.h"

#include <string>

#include "commands/csg/facade.h"

namespace relgeo::tool {

io::Json csg_report_json(const std::string& tree, const std::string& kernel, const std::string& rounding,
                         const Csg_result& r, double total_seconds, Csg_intermediates intermediates) {
  // The double kernel is not certified: its Booleans round to nearest.
  const std::string method = kernel == "double" ? "nearest" : rounding;
  io::Json steps = io::Json::array();
  for (const Csg_step& s : r.steps) {
    steps.push_back({{"node", s.node},
                     {"operation", std::string(to_string(s.operation))},
                     {"ok", s.ok},
                     {"failure", s.failure},
                     {"faces", s.faces},
                     {"volume", io::json_measure(s.volume)},
                     {"validation", s.validation},
                     {"rounding", rounding_repair_json(s.rounding, method)},
                     {"coordinate_bits", s.coordinate_bits},
                     {"seconds", s.seconds}});
  }
  const bool exact = intermediates == Csg_intermediates::exact;
  // Rounded intermediates: the last step made the output (and validated it);
  // exact ones: the root's one rounding did.
  const std::string validation = exact ? r.validation : (r.steps.empty() ? "" : r.steps.back().validation);
  const Rounding_repair_report& rounding_of_output =
      exact || r.steps.empty() ? r.rounding : r.steps.back().rounding;
  return io::Json{{"tree", tree},
                  {"kernel", kernel},
                  {"intermediates", std::string(to_string(intermediates))},
                  {"status", r.ok() ? "ok" : "failed"},
                  {"failure", r.failure},
                  {"steps", steps},
                  {"output",
                   {{"vertices", r.mesh.vertices.size()},
                    {"faces", r.mesh.faces.size()},
                    {"volume", io::json_measure(r.steps.empty() ? 0.0 : r.steps.back().volume)},
                    {"rounding", rounding_repair_json(rounding_of_output, method)},
                    {"validation", validation}}},
                  {"seconds", r.seconds},
                  {"total_seconds", total_seconds}};
}

}  // namespace relgeo::tool
