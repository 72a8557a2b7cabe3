// check_mesh: one test per defect, each located; valid meshes give an empty
// report; the default kernels decide collinearity exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mesh/mesh_fixtures.h"
#include "relgeo/mesh.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

TEST(CheckMesh, ValidClosedMeshesHaveEmptyReports) {
  for (const Mesh_d& m : {tetrahedron(), icosphere(2), torus(7, 5), creased_box(), bipyramid(12)}) {
    const Mesh_report r = check_mesh(m);
    EXPECT_TRUE(r.is_valid()) << r.summary();
    EXPECT_TRUE(r.is_closed() && r.is_manifold() && r.is_consistently_oriented());
    EXPECT_FALSE(r.has_degenerate_faces());
    EXPECT_FALSE(r.is_self_intersection_free().has_value());  // not checked here
    EXPECT_EQ(r.summary(), "valid");
  }
  EXPECT_TRUE(check_mesh(convert<mpq_class>(icosphere(1))).is_valid());
}

TEST(CheckMesh, OpenMeshReportsEachBoundaryEdgeUnlessOpenSurfacesAreAllowed) {
  const Mesh_d m = open_grid(3);
  const Mesh_report r = check_mesh(m);
  EXPECT_EQ(r.count(Mesh_defect::boundary_edge), 12u);
  EXPECT_FALSE(r.is_closed());
  EXPECT_TRUE(r.is_manifold());
  EXPECT_TRUE(check_mesh(m, {.require_closed = false}).is_valid());
}

TEST(CheckMesh, NonFiniteCoordinatesAreReportedWithTheirVertex) {
  Mesh_d m = octahedron();
  m.vertices[3].y = std::numeric_limits<double>::quiet_NaN();
  m.vertices[5].z = std::numeric_limits<double>::infinity();
  const Mesh_report r = check_mesh(m);
  ASSERT_EQ(r.count(Mesh_defect::non_finite_coordinate), 2u);
  EXPECT_EQ(r.issues[0], (Mesh_issue{Mesh_defect::non_finite_coordinate, {3, invalid_index}}));
  EXPECT_EQ(r.issues[1], (Mesh_issue{Mesh_defect::non_finite_coordinate, {5, invalid_index}}));
}

TEST(CheckMesh, DegenerateFacesRepeatedIndexAndExactlyCollinear) {
  Mesh_d m = tetrahedron();
  m.faces.push_back({1, 1, 2});
  const Mesh_report r = check_mesh(m, {.require_closed = false});
  EXPECT_EQ(r.count(Mesh_defect::repeated_vertex_in_face), 1u);
  EXPECT_TRUE(r.has_degenerate_faces());
  // collinear, and almost collinear (1 ulp off): exact predicates tell them apart
  Mesh_d c;
  c.vertices = {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {0.5, 0.5, std::nextafter(0.5, 1.0)}};
  c.faces = {{0, 1, 2}, {0, 1, 3}};
  const Mesh_report rc = check_mesh(c, {.require_closed = false});
  ASSERT_EQ(rc.count(Mesh_defect::collinear_face), 1u);
  EXPECT_EQ(rc.issues.back().elements[0], 0u);
  // the same in exact rationals, and under intervals (where 1 ulp is decided too)
  EXPECT_EQ(check_mesh(convert<mpq_class>(c), {.require_closed = false}).count(Mesh_defect::collinear_face), 1u);
  const Mesh_report ri = check_mesh(convert<Interval>(c), {.require_closed = false});
  EXPECT_EQ(ri.count(Mesh_defect::collinear_face), 1u);
  EXPECT_EQ(ri.count(Mesh_defect::undecided), 0u);
}

TEST(CheckMesh, IsolatedVerticesOutOfRangeIndicesAndBadTags) {
  Mesh_d m = tetrahedron();
  m.vertices.push_back({9, 9, 9});
  m.tags.add_crease(0, 4);  // vertex 4 is in no face: not an edge
  m.tags.add_corner(17);
  Mesh_report r = check_mesh(m);
  EXPECT_EQ(r.count(Mesh_defect::isolated_vertex), 1u);
  EXPECT_EQ(r.count(Mesh_defect::invalid_tag), 2u);
  EXPECT_FALSE(check_mesh(m, {.report_isolated_vertices = false}).has(Mesh_defect::isolated_vertex));
  m.faces.push_back({0, 2, 99});
  r = check_mesh(m, {.require_closed = false});
  ASSERT_EQ(r.count(Mesh_defect::index_out_of_range), 1u);
  EXPECT_THROW(require_valid_mesh(m), Invalid_mesh);
  EXPECT_NO_THROW(require_valid_mesh(tetrahedron()));
}

TEST(CheckMesh, NonManifoldAndMisorientedMeshesAreNamedNotCalledOpen) {
  Mesh_d m = tetrahedron();
  m.faces.push_back({0, 1, 3});
  Mesh_report r = check_mesh(m);
  EXPECT_FALSE(r.is_manifold());
  EXPECT_GE(r.count(Mesh_defect::non_manifold_edge), 1u);
  Mesh_d f = tetrahedron();
  std::swap(f.faces[2][0], f.faces[2][1]);
  r = check_mesh(f);
  EXPECT_FALSE(r.is_consistently_oriented());
  EXPECT_EQ(r.count(Mesh_defect::inconsistent_orientation), 3u);
  EXPECT_EQ(r.count(Mesh_defect::boundary_edge), 0u) << r.summary();
}

}  // namespace
