// relgeo/mesh/mesh_report.h — what check_mesh (validity.h) looks at and
// reports: plain data, for code that passes reports around without running
// the checks.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "relgeo/mesh/mesh_errors.h"

namespace relgeo {

/// What check_mesh looks at.
struct Mesh_check_options {
  /// Report boundary edges (a solid must be closed). Off for open surfaces.
  bool require_closed = true;
  /// Report vertices that no face uses.
  bool report_isolated_vertices = true;
  /// Test every face for collinear corners with the kernel's predicates.
  bool check_collinear_faces = true;
};

/// The result of check_mesh: every issue found, and what was checked.
struct Mesh_report {
  std::vector<Mesh_issue> issues;
  /// Whether self-intersections were checked (check_solid in
  /// self_intersection.h does; check_mesh does not).
  bool self_intersections_checked = false;

  bool is_valid() const { return issues.empty(); }
  std::size_t count(Mesh_defect d) const {
    return static_cast<std::size_t>(
        std::count_if(issues.begin(), issues.end(), [d](const Mesh_issue& i) { return i.defect == d; }));
  }
  bool has(Mesh_defect d) const { return count(d) > 0; }
  /// No boundary edge (meaningful when require_closed was set).
  bool is_closed() const { return !has(Mesh_defect::boundary_edge); }
  /// Every edge in at most two faces and every vertex a single fan.
  bool is_manifold() const { return !has(Mesh_defect::non_manifold_edge) && !has(Mesh_defect::non_manifold_vertex); }
  bool is_consistently_oriented() const { return !has(Mesh_defect::inconsistent_orientation); }
  bool has_degenerate_faces() const {
    return has(Mesh_defect::repeated_vertex_in_face) || has(Mesh_defect::collinear_face);
  }
  /// Empty when not checked.
  std::optional<bool> is_self_intersection_free() const {
    if (!self_intersections_checked) return std::nullopt;
    return !has(Mesh_defect::self_intersection);
  }
  /// One line: "valid" or the count of each defect.
  std::string summary() const {
    if (issues.empty()) return "valid";
    std::string s;
    for (int d = 0; d <= static_cast<int>(Mesh_defect::undecided); ++d) {
      const std::size_t c = count(static_cast<Mesh_defect>(d));
      if (c)
        s += (s.empty() ? "" : ", ") + std::to_string(c) + " " + std::string(to_string(static_cast<Mesh_defect>(d)));
    }
    return s;
  }
};

}  // namespace relgeo
