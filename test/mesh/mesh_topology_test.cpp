// Mesh_topology: adjacency, rings, counts (Euler characteristic), tags and
// polygon soups on procedural meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "mesh/mesh_fixtures.h"
#include "relgeo/mesh.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

long euler(const Mesh_topology& t) {
  return long(t.number_of_vertices()) - long(t.number_of_edges()) + long(t.number_of_faces());
}

TEST(MeshTopology, ClosedMeshesHaveTheirEulerCharacteristicAndNoBoundary) {
  EXPECT_EQ(euler(Mesh_topology::build(tetrahedron())), 2);
  EXPECT_EQ(euler(Mesh_topology::build(octahedron())), 2);
  EXPECT_EQ(euler(Mesh_topology::build(icosphere(2))), 2);
  EXPECT_EQ(euler(Mesh_topology::build(torus(8, 6))), 0);
  EXPECT_EQ(euler(Mesh_topology::build(creased_box())), 2);
  for (const Mesh_d& m : {icosphere(1), torus(5, 4), creased_box(), bipyramid(9)}) {
    const Mesh_topology t = Mesh_topology::build(m);
    EXPECT_EQ(2 * t.number_of_edges(), t.number_of_halfedges());
    for (Index h = 0; h < t.number_of_halfedges(); ++h) {
      ASSERT_NE(t.opposite(h), invalid_index);
      EXPECT_EQ(t.opposite(t.opposite(h)), h);
      EXPECT_EQ(t.source(t.opposite(h)), t.target(h));
      EXPECT_EQ(t.edge(h), t.edge(t.opposite(h)));
    }
  }
}

TEST(MeshTopology, TakeOppositesMovesThemOutAndEmptiesTheTopology) {
  for (const Mesh_d& m : {icosphere(1), open_grid(3)}) {
    Mesh_topology t = Mesh_topology::build(m);
    std::vector<Index> expected(t.number_of_halfedges());
    for (Index h = 0; h < expected.size(); ++h) expected[h] = t.opposite(h);
    ASSERT_FALSE(expected.empty());
    EXPECT_EQ(std::move(t).take_opposites(), expected);
    EXPECT_EQ(t.number_of_faces(), 0u);  // NOLINT(bugprone-use-after-move): documented as left empty
    EXPECT_EQ(t.number_of_edges(), 0u);
    EXPECT_EQ(t.number_of_vertices(), 0u);
  }
}

TEST(MeshTopology, RingsAreCounterClockwiseAndComplete) {
  const Mesh_d m = icosahedron();
  const Mesh_topology t = Mesh_topology::build(m);
  for (Index v = 0; v < 12; ++v) {
    const auto ring = t.vertex_ring(v);
    ASSERT_EQ(ring.size(), 5u);
    EXPECT_EQ(t.valence(v), 5u);
    // consecutive ring vertices (and v) form a face of the mesh, in this order
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Triangle f{v, ring[i], ring[(i + 1) % ring.size()]};
      const bool found = std::any_of(m.faces.begin(), m.faces.end(), [&](const Triangle& g) {
        for (int r = 0; r < 3; ++r)
          if (g[r] == f[0] && g[(r + 1) % 3] == f[1] && g[(r + 2) % 3] == f[2]) return true;
        return false;
      });
      EXPECT_TRUE(found) << "vertex " << v << " ring position " << i;
    }
  }
  EXPECT_EQ(t.valence(Index(12 - 12 + 0)), 5u);
  const Mesh_topology b = Mesh_topology::build(bipyramid(11));
  EXPECT_EQ(b.valence(11), 11u);
  EXPECT_EQ(b.valence(12), 11u);
  EXPECT_EQ(b.valence(0), 4u);
}

TEST(MeshTopology, OpenGridHasBoundaryRingsStartingAndEndingOnTheBoundary) {
  const int n = 4;
  const Mesh_d m = open_grid(n);
  const Mesh_topology t = Mesh_topology::build(m);
  EXPECT_EQ(euler(t), 1);
  Index boundary_edges = 0;
  for (Index e = 0; e < t.number_of_edges(); ++e) boundary_edges += t.is_boundary_edge(e);
  EXPECT_EQ(boundary_edges, Index(4 * n));
  // corner (0,0): faces (0,0)-(1,0)-(1,1) and (0,0)-(1,1)-(0,1): 2 faces, 3 neighbours
  EXPECT_TRUE(t.is_boundary_vertex(0));
  const auto ring = t.vertex_ring(0);
  ASSERT_EQ(ring.size(), 3u);
  EXPECT_EQ(t.number_of_incident_faces(0), 2u);
  EXPECT_NE(t.find_edge(0, ring.front()), invalid_index);
  EXPECT_TRUE(t.is_boundary_edge(t.find_edge(0, ring.front())));
  EXPECT_TRUE(t.is_boundary_edge(t.find_edge(0, ring.back())));
  // an interior vertex has 6 neighbours and is not on the boundary
  const Index inner = Index(2 * (n + 1) + 2);
  EXPECT_FALSE(t.is_boundary_vertex(inner));
  EXPECT_EQ(t.vertex_ring(inner).size(), 6u);
}

TEST(MeshTopology, BuildThrowsTypedErrorsNamingEveryDefect) {
  Mesh_d m = tetrahedron();
  m.faces.push_back({0, 1, 3});  // edge {0,1} now has three faces; {1,3} too
  try {
    (void)Mesh_topology::build(m);
    FAIL() << "no exception";
  } catch (const Invalid_mesh& e) {
    EXPECT_EQ(e.defect(), Mesh_defect::non_manifold_edge);
    EXPECT_EQ(e.code(), Error_code::invalid_input);
    std::set<std::pair<Index, Index>> edges;
    for (const auto& i : e.issues())
      if (i.defect == Mesh_defect::non_manifold_edge) edges.insert({i.elements[0], i.elements[1]});
    EXPECT_TRUE(edges.count({0, 1}));
    EXPECT_TRUE(edges.count({1, 3}));
  }
  Mesh_d flipped = tetrahedron();
  std::swap(flipped.faces[0][1], flipped.faces[0][2]);
  try {
    (void)Mesh_topology::build(flipped);
    FAIL() << "no exception";
  } catch (const Invalid_mesh& e) {
    EXPECT_EQ(e.defect(), Mesh_defect::inconsistent_orientation);
    EXPECT_EQ(e.issues().size(), 3u);  // the three edges of the flipped face
  }
}

TEST(MeshTopology, TwoTetrahedraSharingAVertexMakeANonManifoldVertexWithTwoFans) {
  Mesh_d m = tetrahedron();
  Mesh_d t2 = tetrahedron();
  for (auto& p : t2.vertices) p.x += 3;
  const Index off = 4;
  m.vertices.insert(m.vertices.end(), t2.vertices.begin() + 1, t2.vertices.end());
  for (Triangle f : t2.faces) {
    for (Index& v : f) v = v == 0 ? 0 : v + off - 1;  // t2's vertex 0 is glued to vertex 0
    m.faces.push_back(f);
  }
  std::vector<Mesh_issue> issues;
  (void)Mesh_topology::build_checked(m.vertices.size(), m.faces, issues);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].defect, Mesh_defect::non_manifold_vertex);
  EXPECT_EQ(issues[0].elements[0], 0u);
  EXPECT_EQ(issues[0].elements[1], 2u);  // two fans
  EXPECT_THROW((void)Mesh_topology::build(m), Invalid_mesh);
}

TEST(FeatureTags, SortedUniqueNormalised) {
  Feature_tags t;
  t.add_crease(5, 2);
  t.add_crease(2, 5);
  t.add_crease(1, 9);
  t.add_corner(7);
  t.add_corner(7);
  ASSERT_EQ(t.creases().size(), 2u);
  EXPECT_EQ(t.creases()[0], (Edge{1, 9}));
  EXPECT_EQ(t.creases()[1], (Edge{2, 5}));
  EXPECT_TRUE(t.is_crease(5, 2));
  EXPECT_FALSE(t.is_crease(5, 1));
  EXPECT_TRUE(t.is_corner(7));
  EXPECT_EQ(t.corners().size(), 1u);
  EXPECT_THROW(t.add_crease(3, 3), Precondition_violation);
}

TEST(PolygonSoup, RoundTripAndTriangulationAndBadIndices) {
  const Mesh_d m = icosahedron();
  const auto polys = to_polygon_soup(m);
  const Mesh_d back = from_polygon_soup(m.vertices, polys);
  EXPECT_EQ(back, m);
  std::vector<std::vector<std::size_t>> quad{{0, 1, 2, 3}};
  std::vector<Point_3<double>> pts{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_THROW((void)from_polygon_soup(pts, quad), Invalid_input);
  const Mesh_d q = from_polygon_soup(pts, quad, {.triangulate_polygons = true});
  ASSERT_EQ(q.faces.size(), 2u);
  EXPECT_EQ(q.faces[1], (Triangle{0, 2, 3}));
  std::vector<std::vector<std::size_t>> bad{{0, 1, 7}};
  try {
    (void)from_polygon_soup(pts, bad);
    FAIL();
  } catch (const Invalid_mesh& e) {
    EXPECT_EQ(e.defect(), Mesh_defect::index_out_of_range);
    EXPECT_EQ(e.issues()[0].elements[1], 7u);
  }
}

}  // namespace
