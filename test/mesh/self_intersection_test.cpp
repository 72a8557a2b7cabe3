// Self-intersection with exact predicates and check_solid.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/mesh_fixtures.h"
#include "relgeo/mesh/self_intersection.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

TEST(SelfIntersection, CleanSolidsPassEveryCheck) {
  for (const Mesh_d& m : {icosphere(2), torus(12, 8), creased_box(), bipyramid(10)}) {
    const Mesh_report r = check_solid(m);
    EXPECT_TRUE(r.is_valid()) << r.summary();
    ASSERT_TRUE(r.is_self_intersection_free().has_value());
    EXPECT_TRUE(*r.is_self_intersection_free());
  }
}

TEST(SelfIntersection, OverlappingComponentsAreFoundWithTheirFaces) {
  Mesh_d m = octahedron();
  Mesh_d t = octahedron();
  const Index off = static_cast<Index>(m.vertices.size());
  for (auto p : t.vertices) m.vertices.push_back({p.x + 0.5, p.y + 0.25, p.z + 0.125});
  for (Triangle f : t.faces) m.faces.push_back({f[0] + off, f[1] + off, f[2] + off});
  const auto pairs = self_intersections(m);
  ASSERT_FALSE(pairs.empty());
  for (const auto& [f, g] : pairs) {
    EXPECT_LT(f, 8u);  // one face from each octahedron
    EXPECT_GE(g, 8u);
  }
  const Mesh_report r = check_solid(m);
  EXPECT_EQ(r.count(Mesh_defect::self_intersection), pairs.size());
  EXPECT_FALSE(*r.is_self_intersection_free());
  EXPECT_TRUE(r.is_closed() && r.is_manifold());
}

TEST(SelfIntersection, AVertexPushedThroughTheTubeIsFound) {
  Mesh_d m = torus(8, 6);
  const Mesh_d clean = m;
  EXPECT_TRUE(self_intersections(clean).empty());
  // vertex 0 is on the outer equator at (2.7, 0, 0); move it through the
  // tube to the inner side (x = 1.3 - 0.2): it crosses the inner faces.
  m.vertices[0] = {1.1, 0, 0};
  EXPECT_FALSE(self_intersections(m).empty());
}

TEST(SelfIntersection, NonManifoldInputIsRefusedNotGuessed) {
  Mesh_d m = tetrahedron();
  m.faces.push_back({0, 1, 3});
  EXPECT_THROW((void)self_intersections(m), Invalid_mesh);
  const Mesh_report r = check_solid(m);
  EXPECT_FALSE(r.is_self_intersection_free().has_value());  // not checked: can't be
  EXPECT_FALSE(r.is_manifold());
}

}  // namespace
