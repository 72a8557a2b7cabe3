// relgeo/joining/domain_mesh.h — the result type of mesh_domain
// (domain_mesher.h, which needs CGAL): triangulated regions of the (u,v)
// plane with the provenance of every vertex. No dependency.
#pragma once

#include <cstddef>
#include <vector>

#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// Options of mesh_domain.
struct Domain_mesh_options {
  /// CGAL's shape bound B = sin^2 of the smallest angle aimed at [0.125:
  /// 20.7 degrees, Ruppert's guarantee for input angles of 60 degrees or more].
  double shape_bound = 0.125;
  /// Longest edge allowed (0: no size bound) [0].
  double max_edge_length = 0;
};

/// Where a vertex of a domain mesh comes from: input point `index` of loop
/// `loop`, or (loop = -1) a Steiner point; a Steiner point on an input
/// segment records it (segment_loop, segment = index of its first point, t in
/// (0,1) along it); a Steiner point inside the region has segment_loop = -1.
struct Domain_vertex {
  Point_2<double> uv;
  int loop = -1;
  std::size_t index = 0;
  int segment_loop = -1;
  std::size_t segment = 0;
  double t = 0;
  bool is_input() const { return loop >= 0; }
  bool is_on_segment() const { return loop < 0 && segment_loop >= 0; }
};

/// A triangulated region: vertices with provenance, counter-clockwise
/// triangles, and the smallest angle (degrees).
struct Domain_mesh {
  std::vector<Domain_vertex> vertices;
  std::vector<Triangle> triangles;
  double min_angle_degrees = 0;
};

}  // namespace relgeo
