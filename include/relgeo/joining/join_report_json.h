// relgeo/joining/join_report_json.h — joining reports as JSON documents of
// relgeo/io (link relgeo::io): field names are the members' names, in their
// order (join_report.h documents them); measures follow io::json_measure
// (infinite ones as "inf", NaN as null).
#pragma once

#include "relgeo/io/json.h"
#include "relgeo/joining/join_report.h"

namespace relgeo {

inline io::Json to_json(const Join_errors& e) {
  return {{"absolute", io::json_measure(e.absolute)}, {"normal_vector", io::json_measure(e.normal_vector)}};
}
inline io::Json to_json(const Join_orientation& o) {
  return {{"positive", o.positive}, {"flipped", o.flipped}, {"degenerate", o.degenerate}, {"undecided", o.undecided}};
}

inline io::Json to_json(const Join_face_report& f) {
  using io::json_measure;
  return {{"input_vertices", f.input_vertices},
          {"input_triangles", f.input_triangles},
          {"central_triangles", f.central_triangles},
          {"removed_triangles", f.removed_triangles},
          {"external_triangles", f.external_triangles},
          {"boundary_samples", f.boundary_samples},
          {"output_vertices", f.output_vertices},
          {"output_triangles", f.output_triangles},
          {"before", to_json(f.before)},
          {"after", to_json(f.after)},
          {"after_reprojected", to_json(f.after_reprojected)},
          {"boundary_max_abs_height", json_measure(f.boundary_max_abs_height)},
          {"lipschitz_constant", json_measure(f.lipschitz_constant)},
          {"data_lipschitz_constant", json_measure(f.data_lipschitz_constant)},
          {"max_deviation", json_measure(f.max_deviation)},
          {"whitney_fallbacks", f.whitney_fallbacks},
          {"whitney_uncertified", f.whitney_uncertified},
          {"edges_above_lipschitz", f.edges_above_lipschitz},
          {"orientation_before", to_json(f.orientation_before)},
          {"orientation_after", to_json(f.orientation_after)},
          {"overlaps_after", f.overlaps_after},
          {"overlaps_undecided_after", f.overlaps_undecided_after},
          {"min_angle_external", json_measure(f.min_angle_external)},
          {"guarantees_hold", f.guarantees_hold}};
}

inline io::Json to_json(const Join_report& r) {
  io::Json faces = io::Json::array();
  for (const auto& f : r.faces) faces.push_back(to_json(f));
  io::Json seconds = io::Json::object();
  for (const auto& [step, s] : r.seconds) seconds[step] = s;
  return {{"method", r.method},
          {"kernel", r.kernel},
          {"faces", faces},
          {"vertices", r.vertices},
          {"triangles", r.triangles},
          {"edges_with_curve", r.edges_with_curve},
          {"edges_with_median", r.edges_with_median},
          {"free_edges", r.free_edges},
          {"conformity_rounds", r.conformity_rounds},
          {"boundary_edges", r.boundary_edges},
          {"seam_boundary_edges", r.seam_boundary_edges},
          {"non_manifold_edges", r.non_manifold_edges},
          {"inconsistent_orientations", r.inconsistent_orientations},
          {"flipped_triangles", r.flipped_triangles},
          {"min_angle_3d", io::json_measure(r.min_angle_3d)},
          {"conforming", r.conforming},
          {"watertight_seams", r.watertight_seams},
          {"guarantees_hold", r.guarantees_hold},
          {"seconds", seconds},
          {"total_seconds", r.total_seconds}};
}

}  // namespace relgeo
