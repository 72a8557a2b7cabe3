// tools/relgeo/commands/boolean/report.h — a Boolean as `relgeo boolean`
// reports it: the JSON record and the readable summary.
#pragma once

#include <optional>
#include <string>

#include "commands/boolean/facade.h"
#include "relgeo/io/json.h"

namespace relgeo::tool {

/// What the repair of the rounding did, as `boolean`, `csg` and the
/// experiment report it: {method, rounds, defects_before, moved_vertices,
/// flips, collapses, largest_change, remaining_pairs, remaining_degenerate_faces}.
io::Json rounding_repair_json(const Rounding_repair_report& r, const std::string& method);
/// The seconds of the Boolean's phases, as `boolean` and the experiment report
/// them: {check, broad_phase, narrow_phase, retriangulation, labelling,
/// assembly, rounding}.
io::Json boolean_timing_json(const Boolean_timing& t);

struct Boolean_report_input {
  std::string operation, input_a, input_b;
  const Mesh_double* a = nullptr;
  const Mesh_double* b = nullptr;
  const Boolean_run* run = nullptr;
  const Oracle_comparison* oracle = nullptr;  ///< with --oracle cgal
};

/// JSON fields: operation, kernel, kernel_model, certified, status,
/// failure, undecided_pairs, operands {a, b: file, vertices, faces, volume},
/// output {vertices, faces, creases}, validation (io::solid_report_json of
/// the output's validate_solid report; null when the Boolean failed),
/// exact_self_intersecting_pairs (exact kernel; else null), rounding_error, counts
/// {candidate_pairs, intersecting_pairs, coplanar_pairs, new_vertices,
/// split_faces, patches, unchanged_certified_faces}, time_s {check, broad_phase, narrow_phase,
/// retriangulation, labelling, assembly, total, validation}, [oracle {cgal_ok,
/// cgal_volume, cgal_faces, volume_difference, symmetric_difference_volume,
/// hausdorff}].
io::Json boolean_report_json(const Boolean_report_input& in);
/// The fields every Boolean report starts with: operation, kernel,
/// kernel_model, certified, status, failure (Boolean_run and
/// Subdivision_boolean_run alike).
template <class Run>
void put_run_header(io::Json& j, const std::string& operation, const Run& r) {
  j.update(io::Json{{"operation", operation},
                    {"kernel", r.kernel},
                    {"kernel_model", r.kernel_model},
                    {"certified", r.certified},
                    {"status", r.ok() ? "ok" : "failed"},
                    {"failure", r.failure}});
}
/// {file, vertices, faces, volume} of an operand (volume: sum of the faces' signed tetrahedra in doubles).
io::Json operand_json(const std::string& file, const Mesh_double& m);
std::string boolean_report_text(const Boolean_report_input& in);

}  // namespace relgeo::tool
