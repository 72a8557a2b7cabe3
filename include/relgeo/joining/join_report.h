// relgeo/joining/join_report.h — what a joining run reports: per face the
// errors before and after (thesis Sec. 4.2), the Whitney data and its
// guarantees, the certified checks of the result in (u,v), and for the
// whole mesh its conformity, watertightness, angles and the time per step.
// Plain aggregates (no dependency); joining/join_report_json.h prints them.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace relgeo {

/// Error measures of one mesh patch over its face (Patch_errors, reduced to
/// the figures a report needs).
struct Join_errors {
  double absolute = 0;       ///< sup |eta| over the vertices
  double normal_vector = 0;  ///< largest slope between two corners of a triangle
};

/// Certified orientation counts in (u,v) (Orientation_report's figures).
struct Join_orientation {
  std::size_t positive = 0, flipped = 0, degenerate = 0, undecided = 0;
};

/// One face's part of a joining run.
struct Join_face_report {
  std::size_t input_vertices = 0, input_triangles = 0;
  std::size_t central_triangles = 0;      ///< kept from the input
  std::size_t removed_triangles = 0;      ///< peripheral, outside dR, too close, invalid, non-manifold
  std::size_t external_triangles = 0;     ///< of the Ruppert triangulation of the external region
  std::size_t boundary_samples = 0;       ///< sigma: vertices of dR (the Whitney data)
  std::size_t output_vertices = 0, output_triangles = 0;  ///< this face's part of the result
  Join_errors before;                     ///< the input mesh over its projection
  Join_errors after;                      ///< the result's height field (uv, Whitney heights)
  Join_errors after_reprojected;          ///< the result's vertices projected again onto the face
  double boundary_max_abs_height = 0;     ///< M = max |e| on dR
  double lipschitz_constant = 0;          ///< L used by the Whitney extension
  double data_lipschitz_constant = 0;     ///< L*: largest slope between two dR samples
  double max_deviation = 0;               ///< largest |a^ - a| (certified)
  std::size_t whitney_fallbacks = 0, whitney_uncertified = 0;
  std::size_t edges_above_lipschitz = 0;  ///< triangle edges of the result steeper than L (deviation-sized excess only)
  Join_orientation orientation_before, orientation_after;  ///< certified, in (u,v)
  std::size_t overlaps_after = 0, overlaps_undecided_after = 0;
  double min_angle_external = 0;          ///< degrees, in (u,v)
  /// The guarantees of the thesis, checked on the result: |a| <= M,
  /// normal-vector error <= L (up to the certified deviation), no flipped,
  /// degenerate or overlapping triangle in (u,v).
  bool guarantees_hold = false;
};

/// A joining run.
struct Join_report {
  std::string method;  ///< "whitney", "naive-midpoint" or "occt-sewing"
  std::string kernel;  ///< the kernel of the certified checks
  std::vector<Join_face_report> faces;
  std::size_t vertices = 0, triangles = 0;
  std::size_t edges_with_curve = 0;    ///< case 1 (thesis Sec. 4.3.2)
  std::size_t edges_with_median = 0;   ///< case 2, two meshes (Sec. 4.3.3)
  std::size_t free_edges = 0;          ///< case 2, one mesh: its own boundary
  std::size_t conformity_rounds = 0;   ///< remeshing rounds until shared edges matched
  std::size_t boundary_edges = 0;      ///< of the result (on free edges only, when watertight)
  std::size_t seam_boundary_edges = 0; ///< boundary edges on shared edges (0: watertight seams)
  std::size_t non_manifold_edges = 0, inconsistent_orientations = 0;
  std::size_t flipped_triangles = 0;   ///< over all faces, certified in (u,v)
  double min_angle_3d = 0;             ///< degrees
  bool conforming = false;             ///< edge-manifold, consistently oriented, no T-junction on a seam
  bool watertight_seams = false;
  bool guarantees_hold = false;        ///< every face's guarantees_hold
  std::vector<std::pair<std::string, double>> seconds;  ///< time per step
  double total_seconds = 0;
};

}  // namespace relgeo
