// Bad input to Loop subdivision: each case a typed error or a documented
// handling.
#include <gtest/gtest.h>

#include <limits>

#include "relgeo/kernel.h"
#include "relgeo/mesh.h"
#include "subdivision/subdivision_fixtures.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

template <class F>
Mesh_defect defect_of(F&& f) {
  try {
    f();
  } catch (const Invalid_mesh& e) {
    return e.defect();
  }
  ADD_FAILURE() << "no Invalid_mesh thrown";
  return Mesh_defect::undecided;
}

TEST(LoopBadInput, NanAndInfinityAreNonFiniteInput) {
  Mesh_d m = icosphere(1);
  m.vertices[7].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)loop_subdivide(m, 1), Non_finite_input);
  EXPECT_THROW((void)loop_limit_mesh(m, 2), Non_finite_input);
  m.vertices[7].y = -std::numeric_limits<double>::infinity();
  try {
    (void)loop_subdivide(m, 1);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Error_code::non_finite_coordinate);
    EXPECT_NE(std::string(e.what()).find("vertex 7"), std::string::npos);
  }
  Triangle_mesh<Point_3<Interval>> iv = convert<Interval>(tetrahedron());
  iv.vertices[2].x = Interval(0, std::numeric_limits<double>::infinity());
  EXPECT_THROW((void)loop_subdivide(iv, 1), Non_finite_input);
}

TEST(LoopBadInput, TwoFacesSharingTwoEdgesAreRefusedEverywhere) {
  // A tetrahedron (faces 0-3) next to a two-face pillow on vertices 4, 5, 6:
  // a closed, oriented, edge-manifold mesh whose refinement would not be.
  Mesh_d m = tetrahedron();
  const Index base = static_cast<Index>(m.vertices.size());
  m.vertices.push_back({3, 0, 0}), m.vertices.push_back({4, 0, 0}), m.vertices.push_back({3, 1, 0});
  m.faces.push_back({base, base + 1, base + 2});
  m.faces.push_back({base, base + 2, base + 1});
  for (auto refuse : {+[](const Mesh_d& x) { (void)loop_subdivide(x, 1); },
                      +[](const Mesh_d& x) { (void)loop_limit_mesh(x, 1); },
                      +[](const Mesh_d& x) { (void)Loop_limit_surface<Filtered_exact_kernel>(x); }}) {
    try {
      refuse(m);
      ADD_FAILURE() << "accepted";
    } catch (const Invalid_input& e) {
      EXPECT_EQ(e.code(), Error_code::invalid_input);
      EXPECT_NE(std::string(e.what()).find("faces 4 and 5 share two edges"), std::string::npos) << e.what();
    }
  }
  m.faces.pop_back(), m.faces.pop_back(), m.vertices.resize(base);
  EXPECT_EQ(loop_subdivide(m, 1).faces.size(), 16u);  // the tetrahedron alone is fine
}

TEST(LoopBadInput, NonManifoldEdgesAndVerticesAndMisorientationAreNamed) {
  Mesh_d m = tetrahedron();
  m.faces.push_back({0, 1, 3});
  EXPECT_EQ(defect_of([&] { (void)loop_subdivide(m, 1); }), Mesh_defect::non_manifold_edge);
  Mesh_d two = tetrahedron();
  Mesh_d t2 = tetrahedron();
  for (auto& p : t2.vertices) p.x += 3;
  two.vertices.insert(two.vertices.end(), t2.vertices.begin() + 1, t2.vertices.end());
  for (Triangle f : t2.faces) {
    for (Index& v : f) v = v == 0 ? 0 : v + 3;
    two.faces.push_back(f);
  }
  EXPECT_EQ(defect_of([&] { (void)loop_subdivide(two, 1); }), Mesh_defect::non_manifold_vertex);
  Mesh_d flipped = octahedron();
  std::swap(flipped.faces[3][0], flipped.faces[3][1]);
  EXPECT_EQ(defect_of([&] { (void)loop_limit_mesh(flipped, 1); }), Mesh_defect::inconsistent_orientation);
}

TEST(LoopBadInput, DegenerateFacesRepeatedIndexIsRefusedCollinearIsRefined) {
  Mesh_d m = tetrahedron();
  m.faces[1] = {0, 2, 2};
  EXPECT_EQ(defect_of([&] { (void)loop_subdivide(m, 1); }), Mesh_defect::repeated_vertex_in_face);
  Mesh_d out = tetrahedron();
  out.faces[1] = {0, 2, 9};
  EXPECT_EQ(defect_of([&] { (void)loop_subdivide(out, 1); }), Mesh_defect::index_out_of_range);
  // a geometrically degenerate (collinear) face is a valid combinatorial
  // input: refined like any other (check_mesh reports it)
  Mesh_d flat = tetrahedron();
  flat.vertices[3] = {0, 0, -1};  // the midpoint of vertices 1 and 2: face (1, 3, 2) is flat
  EXPECT_EQ(check_mesh(flat).count(Mesh_defect::collinear_face), 1u);
  EXPECT_NO_THROW((void)loop_subdivide(flat, 2));
}

TEST(LoopBadInput, IsolatedVerticesAreKeptFixed) {
  Mesh_d m = octahedron();
  m.vertices.push_back({5, 5, 5});
  const Mesh_d r = loop_subdivide(m, 2);
  EXPECT_EQ(r.vertices[6], (Point_3<double>{5, 5, 5}));
  EXPECT_EQ(r.faces.size(), 16u * 8);
  EXPECT_EQ(loop_limit_mesh(m, 1).vertices[6], (Point_3<double>{5, 5, 5}));
}

TEST(LoopBadInput, InvalidTagsAreRefused) {
  Mesh_d m = octahedron();
  m.tags.add_crease(0, 1);  // vertices 0 and 1 are opposite: not an edge
  EXPECT_EQ(defect_of([&] { (void)loop_subdivide(m, 1); }), Mesh_defect::invalid_tag);
  Mesh_d c = octahedron();
  c.tags.add_corner(40);
  EXPECT_EQ(defect_of([&] { (void)loop_subdivide(c, 1); }), Mesh_defect::invalid_tag);
}

TEST(LoopBadInput, OpenMeshesUseTheBoundaryRules) {
  // boundary vertex: 1/8, 3/4, 1/8 of its boundary neighbours; boundary edge 1/2, 1/2
  const Mesh_d g = open_grid(2);
  const Mesh_d r = loop_subdivide(g, 1);
  const Mesh_topology t = Mesh_topology::build(g);
  const Index v = 1;  // (0, 1): on the boundary x = 0, neighbours (0,0) and (0,2) on it
  const auto& p = g.vertices;
  EXPECT_DOUBLE_EQ(r.vertices[v].z, 0.75 * p[1].z + 0.125 * (p[0].z + p[2].z));
  const Index e = t.find_edge(0, 1);
  EXPECT_TRUE(t.is_boundary_edge(e));
  EXPECT_DOUBLE_EQ(r.vertices[g.vertices.size() + e].z, 0.5 * (p[0].z + p[1].z));
}

TEST(LoopBadInput, EmptyMeshAndZeroLevels) {
  const Mesh_d empty;
  EXPECT_EQ(loop_subdivide(empty, 3), empty);
  const Mesh_d m = bipyramid(5);
  EXPECT_EQ(loop_subdivide(m, 0), m);
}

}  // namespace
