// tools/relgeo/commands/boolean/subdivision_report.h — a Boolean of two Loop
// subdivision solids as `relgeo boolean --levels K` reports it, and the parts
// the experiment's subdivision-boolean section shares.
#pragma once

#include <string>

#include "commands/boolean/subdivision_facade.h"
#include "relgeo/io/json.h"

namespace relgeo::tool {

struct Subdivision_boolean_report_input {
  std::string operation, input_a, input_b;
  const Mesh_double* a = nullptr;
  const Mesh_double* b = nullptr;
  const Subdivision_boolean_run* run = nullptr;
};

/// {limit_to_polyhedral, polyhedral_to_limit, hausdorff, mean, samples}
/// (null figures when not measured).
io::Json surface_distance_json(const Surface_distance& d);
/// {certified, has_no_defect, summary, checks {name: {status, count, where,
/// note}}, vertices, faces, candidate_pairs, separated_pairs,
/// adjacent_pairs, certified_adjacent_pairs, certified_regions, undecided_pairs [[f, g], ...]}.
io::Json subdivision_validation_json(const Subdivision_validation& v);
/// {curve_vertices, curve_edges, bad_faces [A, B], fitted_vertices}.
io::Json subdivision_boolean_counts_json(const Subdivision_boolean_counts& c);
/// {subdivision_to_polyhedral, subdivision_to_polyhedral_fitted} (surface_distance_json each).
io::Json subdivision_boolean_distance_json(const Subdivision_boolean_output& r);
/// {limit_meshes, boolean, mapping, fitting, distance, validation, layer, total} in seconds.
io::Json subdivision_boolean_timing_json(const Subdivision_boolean_timing& t);

/// JSON fields: operation, kernel, kernel_model, certified, status, failure,
/// level, fitted, operands {a, b}, output {vertices, faces, creases, corners,
/// curve_vertices}, counts {curve_vertices, curve_edges, bad_faces [A, B],
/// fitted_vertices}, distance {subdivision_to_polyhedral,
/// subdivision_to_polyhedral_fitted}, validation (subdivision_validation_json),
/// polyhedral (the plain Boolean's report of the two limit meshes without
/// operation and operands), time_s {limit_meshes, boolean, mapping, fitting,
/// distance, validation, layer, total}.
io::Json subdivision_boolean_report_json(const Subdivision_boolean_report_input& in);
std::string subdivision_boolean_report_text(const Subdivision_boolean_report_input& in);

}  // namespace relgeo::tool
