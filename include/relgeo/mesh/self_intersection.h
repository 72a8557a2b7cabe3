// relgeo/mesh/self_intersection.h — self-intersection test with exact
// predicates (CGAL Polygon_mesh_processing over Epick), and check_solid: every
// check of check_mesh plus this one.
//
// Needs CGAL (link relgeo::cgal). Heavy to compile (PMP + box intersection,
// ~15 s): include it only in the translation units that need it.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iterator>
#include <utility>
#include <vector>

#include "relgeo/mesh/internal/point_access.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/mesh/validity.h"

namespace relgeo {

/// \brief The pairs of faces (f < g) that intersect other than in a shared
/// vertex or a shared edge.
///
/// Decided with exact predicates (CGAL::Epick, through
/// Polygon_mesh_processing::self_intersections) on the double coordinates of
/// the points: exact for double input; other coordinates are first rounded to
/// double (coordinate_to_double), which a certificate must state.
/// \pre The mesh is edge- and vertex-manifold with finite coordinates
/// (\throws Invalid_mesh otherwise: CGAL's half-edge mesh cannot hold it).
template <class P>
std::vector<std::pair<Index, Index>> self_intersections(const Triangle_mesh<P>& m) {
  using SM = CGAL::Surface_mesh<CGAL::Epick::Point_3>;
  using A = internal::Point_access<P>;
  (void)Mesh_topology::build(m);  // throws Invalid_mesh for non-manifold input
  SM sm;
  std::vector<SM::Vertex_index> vs;
  vs.reserve(m.vertices.size());
  for (const P& p : m.vertices) {
    if (!internal::point_is_finite(p))
      throw Invalid_mesh("self_intersections", {{Mesh_defect::non_finite_coordinate,
                                                 {static_cast<Index>(vs.size()), invalid_index}}});
    vs.push_back(sm.add_vertex(CGAL::Epick::Point_3(internal::coordinate_to_double(A::x(p)),
                                                    internal::coordinate_to_double(A::y(p)),
                                                    internal::coordinate_to_double(A::z(p)))));
  }
  for (Index f = 0; f < m.faces.size(); ++f) {
    const auto& t = m.faces[f];
    if (sm.add_face(vs[t[0]], vs[t[1]], vs[t[2]]) == SM::null_face())
      throw Invalid_mesh("self_intersections", {{Mesh_defect::non_manifold_vertex, {t[0], invalid_index}}});
  }
  std::vector<std::pair<SM::Face_index, SM::Face_index>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(sm, std::back_inserter(pairs));
  std::vector<std::pair<Index, Index>> out;
  for (const auto& [f, g] : pairs)
    out.emplace_back(std::min<Index>(f.idx(), g.idx()), std::max<Index>(f.idx(), g.idx()));
  std::sort(out.begin(), out.end());
  return out;
}

/// check_mesh plus the self-intersection test (run only when the mesh is
/// manifold with finite coordinates; otherwise self_intersections_checked
/// stays false). A valid report certifies a closed (when required), 2-manifold,
/// consistently oriented, non-degenerate, self-intersection-free triangle
/// mesh: the boundary of a solid (thesis Sec. 5.4.2).
template <class K = void, class P>
Mesh_report check_solid(const Triangle_mesh<P>& m, const Mesh_check_options& options = {}) {
  Mesh_report r = check_mesh<K>(m, options);
  const bool can = !r.has(Mesh_defect::index_out_of_range) && !r.has(Mesh_defect::repeated_vertex_in_face) &&
                   r.is_manifold() && r.is_consistently_oriented() &&
                   !r.has(Mesh_defect::non_finite_coordinate);
  if (!can) return r;
  for (const auto& [f, g] : self_intersections(m)) r.issues.push_back({Mesh_defect::self_intersection, {f, g}});
  r.self_intersections_checked = true;
  return r;
}

}  // namespace relgeo
