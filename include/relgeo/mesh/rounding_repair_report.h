// relgeo/mesh/rounding_repair_report.h — the options, report and index maps
// of repair_rounding (rounding_repair.h): plain data, for code that passes
// them around, such as the Boolean's options and result, without the repair.
#pragma once

#include <cstddef>
#include <vector>

#include "relgeo/mesh/face_pair.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// Options of repair_rounding.
struct Rounding_repair_options {
  /// Rounds of detection and repair at most.
  int max_rounds = 8;
  /// The largest geometric change a flip or a collapse may make, relative to
  /// the diagonal of the mesh's bounding box (vertex moves are one unit in
  /// the last place at most, whatever this is).
  double tolerance = 1e-9;
};

/// What repair_rounding found and did.
struct Rounding_repair_report {
  int rounds = 0;                  ///< rounds of repair run (0: nothing to repair)
  std::size_t defects_before = 0;  ///< crossing face pairs and degenerate faces found first
  std::size_t moved_vertices = 0;  ///< vertices moved to another neighbouring double
  std::size_t flips = 0;           ///< edges flipped under slivers
  std::size_t collapses = 0;       ///< short edges collapsed
  /// The largest change made: a vertex's move from its first position, a
  /// collapsed edge's length or a flipped sliver's height (absolute).
  double largest_change = 0;
  /// What is left (indices of the repaired mesh): face pairs that still meet
  /// beyond what they share, and degenerate faces.
  std::vector<Face_pair> remaining_pairs;
  std::vector<Index> remaining_degenerate_faces;

  bool converged() const { return remaining_pairs.empty() && remaining_degenerate_faces.empty(); }
};

/// How the repaired mesh's elements relate to the mesh before the repair
/// (for a caller that keeps data per vertex or per face).
struct Rounding_repair_maps {
  /// vertex_map[v]: the new index of vertex v (invalid_index when collapsed away).
  std::vector<Index> vertex_map;
  /// face_origin[f]: the face before the repair that face f replaces.
  std::vector<Index> face_origin;
};

}  // namespace relgeo
