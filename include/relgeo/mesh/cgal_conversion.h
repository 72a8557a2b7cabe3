// relgeo/mesh/cgal_conversion.h — CGAL::Surface_mesh and any CGAL FaceGraph
// in and out, with the feature tags as property maps.
//
// Needs CGAL (link relgeo::cgal). Tags travel as the Surface_mesh property
// maps "e:relgeo_crease" (bool per edge) and "v:relgeo_corner" (bool per
// vertex).
#pragma once

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// \brief A CGAL::Surface_mesh<SM_point> holding the mesh; vertex i and face f
/// of the result are Vertex_index(i) and Face_index(f). Coordinates are
/// copied when the number types agree, otherwise converted through double.
/// Tags are stored in the "e:relgeo_crease" / "v:relgeo_corner" maps.
/// \throws Invalid_mesh when Surface_mesh refuses a face (non-manifold input,
/// bad index).
template <class SM_point, class P>
CGAL::Surface_mesh<SM_point> to_surface_mesh(const Triangle_mesh<P>& m) {
  using SM = CGAL::Surface_mesh<SM_point>;
  using A = internal::Point_access<P>;
  using B = internal::Point_access<SM_point>;
  SM sm;
  sm.reserve(static_cast<typename SM::size_type>(m.vertices.size()),
             static_cast<typename SM::size_type>(3 * m.faces.size() / 2 + 3),
             static_cast<typename SM::size_type>(m.faces.size()));
  for (const P& p : m.vertices) {
    if constexpr (std::is_same_v<typename A::FT, typename B::FT>)
      sm.add_vertex(B::make(A::x(p), A::y(p), A::z(p)));
    else
      sm.add_vertex(SM_point(internal::coordinate_to_double(A::x(p)), internal::coordinate_to_double(A::y(p)),
                             internal::coordinate_to_double(A::z(p))));
  }
  for (Index f = 0; f < m.faces.size(); ++f) {
    const Triangle& t = m.faces[f];
    const bool in_range = t[0] < m.vertices.size() && t[1] < m.vertices.size() && t[2] < m.vertices.size();
    if (!in_range || sm.add_face(typename SM::Vertex_index(t[0]), typename SM::Vertex_index(t[1]),
                                 typename SM::Vertex_index(t[2])) == SM::null_face())
      throw Invalid_mesh("to_surface_mesh", {{in_range ? Mesh_defect::non_manifold_edge : Mesh_defect::index_out_of_range,
                                              {f, invalid_index}}});
  }
  if (!m.tags.empty()) {
    auto crease = sm.template add_property_map<typename SM::Edge_index, bool>("e:relgeo_crease", false).first;
    auto corner = sm.template add_property_map<typename SM::Vertex_index, bool>("v:relgeo_corner", false).first;
    for (const Edge& e : m.tags.creases()) {
      const auto h = sm.halfedge(typename SM::Vertex_index(e.a), typename SM::Vertex_index(e.b));
      if (h == SM::null_halfedge())
        throw Invalid_mesh("to_surface_mesh", {{Mesh_defect::invalid_tag, {e.a, e.b}}});
      crease[sm.edge(h)] = true;
    }
    for (Index v : m.tags.corners()) corner[typename SM::Vertex_index(v)] = true;
  }
  return sm;
}

/// \brief A Triangle_mesh from any CGAL FaceListGraph with a vertex point map
/// (Surface_mesh, Polyhedron_3, OpenMesh through CGAL's adapter ...). Vertices
/// are numbered in the order of vertices(g). \throws Invalid_input for a face
/// that is not a triangle.
template <class P, class FaceGraph, class VertexPointMap>
Triangle_mesh<P> from_face_graph(const FaceGraph& g, VertexPointMap vpm) {
  using GT = boost::graph_traits<FaceGraph>;
  using A = internal::Point_access<P>;
  Triangle_mesh<P> m;
  auto vim = CGAL::get_initialized_vertex_index_map(g);
  std::vector<typename GT::vertex_descriptor> by_index(num_vertices(g));
  for (auto v : vertices(g)) by_index[get(vim, v)] = v;
  for (auto v : by_index) {
    const auto& q = get(vpm, v);
    using QA = internal::Point_access<std::remove_cvref_t<decltype(q)>>;
    if constexpr (std::is_same_v<typename QA::FT, typename A::FT>)
      m.vertices.push_back(A::make(QA::x(q), QA::y(q), QA::z(q)));
    else
      m.vertices.push_back(A::make(typename A::FT(internal::coordinate_to_double(QA::x(q))),
                                   typename A::FT(internal::coordinate_to_double(QA::y(q))),
                                   typename A::FT(internal::coordinate_to_double(QA::z(q)))));
  }
  for (auto f : faces(g)) {
    std::vector<Index> c;
    for (auto v : CGAL::vertices_around_face(halfedge(f, g), g)) c.push_back(static_cast<Index>(get(vim, v)));
    if (c.size() != 3)
      throw Invalid_input("from_face_graph: a face has " + std::to_string(c.size()) + " vertices");
    m.faces.push_back({c[0], c[1], c[2]});
  }
  return m;
}

/// A Triangle_mesh from a Surface_mesh, reading the relgeo tag maps when
/// present. Removed elements are skipped (indices are compacted).
template <class P, class SM_point>
Triangle_mesh<P> from_surface_mesh(const CGAL::Surface_mesh<SM_point>& sm) {
  using SM = CGAL::Surface_mesh<SM_point>;
  Triangle_mesh<P> m = from_face_graph<P>(sm, sm.points());
  auto vim = CGAL::get_initialized_vertex_index_map(sm);
  if (auto [crease, found] = sm.template property_map<typename SM::Edge_index, bool>("e:relgeo_crease"); found) {
    std::vector<Edge> creases;
    for (auto e : sm.edges())
      if (crease[e])
        creases.push_back(Edge::of(static_cast<Index>(get(vim, sm.vertex(e, 0))),
                                   static_cast<Index>(get(vim, sm.vertex(e, 1)))));
    m.tags.set_creases(std::move(creases));
  }
  if (auto [corner, found] = sm.template property_map<typename SM::Vertex_index, bool>("v:relgeo_corner"); found) {
    std::vector<Index> corners;
    for (auto v : sm.vertices())
      if (corner[v]) corners.push_back(static_cast<Index>(get(vim, v)));
    m.tags.set_corners(std::move(corners));
  }
  return m;
}

}  // namespace relgeo
