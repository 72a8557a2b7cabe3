// relgeo/io/solid_report_json.h — the validation report of a mesh
// (validate_solid, mesh/solid_validation.h) as JSON, for the tool's reports
// and client programs: every check with its status, count, where (the first
// listed elements) and note; topology; the volume with its bounds.
#pragma once

#include <string>

#include "relgeo/io/json.h"
#include "relgeo/mesh/solid_validation.h"

namespace relgeo::io {

/// {"status", "count", "where": [{"defect", "elements"}], "note"}.
inline Json solid_check_json(const Solid_check& c) {
  Json where = Json::array();
  for (const Mesh_issue& i : c.where) {
    Json elements = Json::array();
    for (Index e : i.elements)
      if (e != invalid_index) elements.push_back(e);
    where.push_back({{"defect", std::string(to_string(i.defect))}, {"elements", elements}});
  }
  Json j = {{"status", std::string(to_string(c.status))}, {"count", c.count}, {"where", where}};
  if (!c.note.empty()) j["note"] = c.note;
  return j;
}

/// The whole report: "valid_solid", "summary", the eleven checks by name,
/// sizes, topology and volume (null where not computed).
inline Json solid_report_json(const Solid_report& r) {
  Json j;
  j["valid_solid"] = r.is_valid_solid();
  j["summary"] = r.summary();
  j["kernel"] = r.kernel;
  j["coordinates_exact"] = r.coordinates_exact;
  Json checks;
  r.for_each_check([&](std::string_view name, const Solid_check& c) { checks[std::string(name)] = solid_check_json(c); });
  j["checks"] = checks;
  j["vertices"] = r.vertices;
  j["faces"] = r.faces;
  j["edges"] = r.edges ? Json(*r.edges) : Json(nullptr);
  j["euler_characteristic"] = r.euler_characteristic ? Json(*r.euler_characteristic) : Json(nullptr);
  j["components"] = r.components;
  j["genus"] = r.genus ? Json(*r.genus) : Json(nullptr);
  if (r.volume.computed)
    j["volume"] = {{"value", json_measure(r.volume.value)},
                   {"exact", r.volume.exact},
                   {"lower", json_measure(r.volume.lower)},
                   {"upper", json_measure(r.volume.upper)}};
  else
    j["volume"] = nullptr;
  j["candidate_pairs"] = r.candidate_pairs;
  return j;
}

}  // namespace relgeo::io
