// fuzz/loop_input.h — which meshes Loop subdivision must accept, decided in
// the harnesses from check_mesh and the topology, independently of the
// subdivider's own checks: the oracle of the subdivision harnesses.
#pragma once

#include <cmath>

#include "relgeo/kernel/point.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/mesh/validity.h"

namespace relgeo::fuzz {

/// The topological checks Loop subdivision needs (no geometry: collinear
/// faces are refined like any other, open meshes are allowed).
inline Mesh_report loop_topology_report(const Triangle_mesh<Point_3<double>>& m) {
  return check_mesh(m, Mesh_check_options{.require_closed = false, .report_isolated_vertices = false,
                                          .check_collinear_faces = false});
}

/// What Loop subdivision requires: no topological defect or invalid tag,
/// finite coordinates, and no two faces sharing two edges.
inline bool loop_acceptable(const Triangle_mesh<Point_3<double>>& m) {
  if (!loop_topology_report(m).is_valid()) return false;
  for (const auto& p : m.vertices)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  const Mesh_topology t = Mesh_topology::build(m);
  for (Index f = 0; f < t.number_of_faces(); ++f)
    for (Index i = 0; i < 3; ++i) {
      const Index a = t.opposite(3 * f + i), b = t.opposite(3 * f + (i + 1) % 3);
      if (a != invalid_index && b != invalid_index && a / 3 == b / 3) return false;
    }
  return true;
}

}  // namespace relgeo::fuzz
