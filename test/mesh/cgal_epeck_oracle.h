// test/mesh/cgal_epeck_oracle.h — what CGAL over Epeck says about a triangle
// mesh as the boundary of a solid: the oracle of solid_validation_cgal_test.
// The Epeck and Polygon_mesh_processing instantiations live in
// cgal_epeck_oracle.cpp alone (slow to compile), behind plain data.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "relgeo/kernel/point.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo_test {

/// CGAL's answers for one mesh (Surface_mesh<Epeck::Point_3> built from the
/// same vertices and faces, face f as Face_index(f)).
struct Cgal_solid_verdict {
  /// Surface_mesh holds the mesh (false: non-manifold input; nothing else
  /// is filled).
  bool representable = false;
  bool closed = false;           ///< CGAL::is_closed
  bool self_intersects = false;  ///< PMP::does_self_intersect (degenerate faces count)
  /// PMP::self_intersections without (f, f) entries (degenerate faces), as
  /// sorted pairs f < g.
  std::vector<relgeo::Face_pair> pairs;
  /// Only for closed, vertex-manifold meshes without self-intersection or
  /// isolated vertices (what CGAL's tests assume): PMP::is_outward_oriented
  /// (decides from the extreme vertex: the component holding it).
  std::optional<bool> outward_oriented;
  /// Under the same conditions: the volume_connected_components decomposition has only valid volumes and
  /// every component is outward exactly at even nesting levels.
  std::optional<bool> bounds_outward_volume;
  /// Only for closed meshes: PMP::volume, exactly ("num/den").
  std::string volume;

  /// What CGAL accepts as the boundary of a solid (not one with pinched or
  /// isolated vertices: its orientation tests are not run there).
  bool valid_solid() const {
    return representable && closed && !self_intersects && outward_oriented.value_or(false) &&
           bounds_outward_volume.value_or(false);
  }
};

/// CGAL's verdict on m. `pairs_only`: fill `representable` and `pairs` only.
Cgal_solid_verdict cgal_epeck_verdict(const relgeo::Triangle_mesh<relgeo::Point_3<double>>& m,
                                      bool pairs_only = false);

}  // namespace relgeo_test
