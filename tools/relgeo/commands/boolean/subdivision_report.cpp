// tools/relgeo/commands/boolean/subdivision_report.cpp
#include "commands/boolean/subdivision_report.h"

#include <sstream>

#include "cli/text.h"
#include "commands/boolean/report.h"
#include "relgeo/io/solid_report_json.h"

namespace relgeo::tool {

namespace {

std::string distance_text(const Surface_distance& d) {
  if (!d.measured()) return "not measured";
  return measure_text(d.hausdorff(), 3) + " (limit -> polyhedral " + measure_text(d.limit_to_polyhedral, 3) +
         ", polyhedral -> limit " + measure_text(d.polyhedral_to_limit, 3) + ", mean " + measure_text(d.mean, 3) +
         "; " + std::to_string(d.samples) + " samples)";
}

}  // namespace

io::Json surface_distance_json(const Surface_distance& d) {
  return {{"limit_to_polyhedral", io::json_measure(d.limit_to_polyhedral)},
          {"polyhedral_to_limit", io::json_measure(d.polyhedral_to_limit)},
          {"hausdorff", d.measured() ? io::json_measure(d.hausdorff()) : io::Json(nullptr)},
          {"mean", io::json_measure(d.mean)},
          {"samples", d.samples}};
}

io::Json subdivision_validation_json(const Subdivision_validation& v) {
  io::Json checks;
  v.for_each_check([&](const char* name, const Solid_check& c) { checks[name] = io::solid_check_json(c); });
  io::Json pairs = io::Json::array();
  for (const auto& [f, g] : v.undecided_pairs) pairs.push_back({f, g});
  return {{"certified", v.is_certified()},
          {"has_no_defect", v.has_no_defect()},
          {"summary", v.summary()},
          {"checks", checks},
          {"vertices", v.vertices},
          {"faces", v.faces},
          {"candidate_pairs", v.candidate_pairs},
          {"separated_pairs", v.separated_pairs},
          {"adjacent_pairs", v.adjacent_pairs},
          {"certified_adjacent_pairs", v.certified_adjacent_pairs},
          {"certified_regions", v.certified_regions},
          {"undecided_pairs", pairs}};
}

io::Json subdivision_boolean_counts_json(const Subdivision_boolean_counts& c) {
  return {{"curve_vertices", c.curve_vertices},
          {"curve_edges", c.curve_edges},
          {"bad_faces", {c.bad_faces[0], c.bad_faces[1]}},
          {"fitted_vertices", c.fitted_vertices}};
}

io::Json subdivision_boolean_distance_json(const Subdivision_boolean_output& r) {
  return {{"subdivision_to_polyhedral", surface_distance_json(r.distance_to_polyhedral)},
          {"subdivision_to_polyhedral_fitted", surface_distance_json(r.distance_to_polyhedral_fitted)}};
}

io::Json subdivision_boolean_timing_json(const Subdivision_boolean_timing& t) {
  return {
      {"limit_meshes", t.limit_meshes}, {"boolean", t.boolean},       {"mapping", t.mapping}, {"fitting", t.fitting},
      {"distance", t.distance},         {"validation", t.validation}, {"layer", t.layer()},   {"total", t.total()}};
}

io::Json subdivision_boolean_report_json(const Subdivision_boolean_report_input& in) {
  const Subdivision_boolean_run& r = *in.run;
  io::Json polyhedral = boolean_report_json({in.operation, in.input_a, in.input_b, in.a, in.b, &r.polyhedral, nullptr});
  for (const char* key : {"operation", "kernel", "kernel_model", "certified", "operands", "exact_self_intersecting_pairs"})
    polyhedral.erase(key);
  io::Json j;
  put_run_header(j, in.operation, r);
  j.update(io::Json{{"level", r.level},
                    {"fitted", r.fitted},
                    {"operands", {{"a", operand_json(in.input_a, *in.a)}, {"b", operand_json(in.input_b, *in.b)}}},
                    {"output",
                     {{"vertices", r.control.vertices.size()},
                      {"faces", r.control.faces.size()},
                      {"creases", r.control.tags.creases().size()},
                      {"corners", r.control.tags.corners().size()},
                      {"curve_vertices", r.curve_vertices.size()}}},
                    {"counts", subdivision_boolean_counts_json(r.counts)},
                    {"distance", subdivision_boolean_distance_json(r)},
                    {"validation", r.ok() ? subdivision_validation_json(r.validation) : io::Json(nullptr)},
                    {"polyhedral", polyhedral},
                    {"time_s", subdivision_boolean_timing_json(r.time)}});
  return j;
}

std::string subdivision_boolean_report_text(const Subdivision_boolean_report_input& in) {
  const Subdivision_boolean_run& r = *in.run;
  Key_value_text s(19);
  s.add("operation", in.operation + " of the Loop solids " + in.input_a + " (" + std::to_string(in.a->faces.size()) +
                         " faces) and " + in.input_b + " (" + std::to_string(in.b->faces.size()) + " faces)");
  s.add("level", std::to_string(r.level));
  s.add("kernel", r.kernel + (r.certified ? " (certified)" : " (naive: answers may be wrong)"));
  s.add("status", r.ok() ? "ok" : "failed: " + r.failure);
  s.add("control mesh", std::to_string(r.control.vertices.size()) + " vertices, " +
                            std::to_string(r.control.faces.size()) + " faces, " +
                            std::to_string(r.control.tags.creases().size()) + " crease edges, " +
                            std::to_string(r.control.tags.corners().size()) + " corners");
  s.add("curves", std::to_string(r.counts.curve_vertices) + " vertices, " + std::to_string(r.counts.curve_edges) +
                      " edges; control faces crossed badly: " + std::to_string(r.counts.bad_faces[0]) + " of A, " +
                      std::to_string(r.counts.bad_faces[1]) + " of B");
  s.add("distance", distance_text(r.distance_to_polyhedral));
  if (r.distance_to_polyhedral_fitted.measured() || r.counts.fitted_vertices)
    s.add("distance fitted", distance_text(r.distance_to_polyhedral_fitted) + "; " + std::to_string(r.counts.fitted_vertices) +
                                 " control vertices moved, " + (r.fitted ? "fitted mesh kept" : "not closer: unfitted mesh kept"));
  if (r.ok()) {
    const Subdivision_validation& v = r.validation;
    s.add("validation", v.summary());
    s.add("face pairs", std::to_string(v.candidate_pairs) + " candidates, " + std::to_string(v.separated_pairs) +
                            " separated, " + std::to_string(v.adjacent_pairs) + " adjacent (" + std::to_string(v.certified_adjacent_pairs) + " certified), " +
                            std::to_string(v.separated_pieces.count) + " far pairs undecided");
  }
  if (r.polyhedral.ok())
    s.add("polyhedral", std::to_string(r.polyhedral.mesh.faces.size()) + " faces (the Boolean of the limit meshes), " +
                            r.polyhedral.validation.summary());
  const Subdivision_boolean_timing& t = r.time;
  s.add("time", format_fixed(t.total(), 4) + " s (limit meshes " + format_fixed(t.limit_meshes, 4) + ", boolean " +
                    format_fixed(t.boolean, 4) + ", mapping " + format_fixed(t.mapping, 4) + ", fitting " +
                    format_fixed(t.fitting, 4) + ", distance " + format_fixed(t.distance, 4) + ", validation " +
                    format_fixed(t.validation, 4) + ")");
  return s.str();
}

}  // namespace relgeo::tool
