// tools/relgeo/commands/join/facade.cpp — what `relgeo join` and the Python
// module's join() share around run_join_tool: the options' usage errors, the
// library's typed errors with the step they belong to, the JSON record.
#include "commands/join/facade.h"

#include <string>

#include "kernels/registry.h"
#include "relgeo/joining/joining_errors.h"

namespace relgeo::tool {

namespace {

using io::Json;

Json summary_json(const Join_report& r) {
  return Json{
      {"absolute_error_before", io::json_measure(largest(r, [](const auto& f) { return f.before.absolute; }))},
      {"absolute_error_after", io::json_measure(largest(r, [](const auto& f) { return f.after.absolute; }))},
      {"normal_vector_error_before",
       io::json_measure(largest(r, [](const auto& f) { return f.before.normal_vector; }))},
      {"normal_vector_error_after", io::json_measure(largest(r, [](const auto& f) { return f.after.normal_vector; }))},
      {"flipped_before", total(r, [](const auto& f) { return f.orientation_before.flipped; })},
      {"flipped_after", total(r, [](const auto& f) { return f.orientation_after.flipped; })},
      {"overlaps_after", total(r, [](const auto& f) { return f.overlaps_after; })}};
}

}  // namespace

void validate_join_options(const Join_tool_options& o) {
  if (o.surface.empty())
    throw Usage_error("no surface file: give it as 'relgeo join SURFACE --mesh A.off ...' or --surface FILE");
  if (o.meshes.empty()) throw Usage_error("no mesh: give one --mesh FILE per face of the surface model, in face order");
  if (o.method != "whitney" && o.method != "naive" && o.method != "occt")
    throw Usage_error("--method must be whitney, naive or occt (got '" + o.method + "')");
  validate_join_kernel(o.kernel);
  if (!(o.max_absolute_error >= 0)) throw Usage_error("--max-absolute-error must be a number >= 0");
  if (!(o.max_normal_error >= 0)) throw Usage_error("--max-normal-error must be a number >= 0");
  if (o.layers < 1 || o.layers > 8) throw Usage_error("--layers must be in 1..8");
  if (o.min_angle != 0 && !(o.min_angle > 0 && o.min_angle <= 30))
    throw Usage_error("--min-angle must be in (0, 30] degrees (Ruppert's refinement terminates up to about 30)");
  if (!(o.slope_margin >= 0 && o.slope_margin <= 1)) throw Usage_error("--slope-margin must be in [0, 1]");
  if (!(o.extrapolation >= 0 && o.extrapolation <= 0.5)) throw Usage_error("--extrapolation must be in [0, 0.5]");
}

Join_tool_result run_join_explained(const Join_tool_options& o, const std::string& output, bool pictures) {
  try {
    return run_join_tool(o, output, pictures);
  } catch (const Projection_error& e) {
    throw Projection_error(
        e.failure(), "a mesh does not project onto its face (" + std::string(to_string(e.failure())) + "): " + e.what(),
        e.index());
  } catch (const Joining_input_error& e) {
    throw Joining_input_error(std::string("the meshes do not fit the surface model: ") + e.what());
  }
}

io::Json join_report_json(const Join_tool_options& o, const std::string& output, const Join_tool_result& res) {
  Json j{{"command", "join"},
         {"kernel", find_kernel(o.kernel).label()},
         {"kernel_model", res.kernel_model},
         {"surface", o.surface},
         {"meshes", o.meshes},
         {"curves", o.curves},
         {"output", output},
         {"summary", summary_json(res.report)},
         {"criteria",
          {{"max_absolute_error", io::json_measure(o.max_absolute_error)},
           {"max_normal_error", io::json_measure(o.max_normal_error)}}}};
  for (const auto& [key, value] : res.json.items())
    if (!j.contains(key)) j[key] = value;
  return j;
}

}  // namespace relgeo::tool
