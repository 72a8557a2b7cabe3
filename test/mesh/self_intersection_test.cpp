// Self-intersection with exact predicates and check_solid.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "mesh/mesh_fixtures.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/internal/embedded_stars.h"

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

// ---- the embedded-star certificate (mesh/internal/embedded_stars.h) --------

std::vector<unsigned char> embedded_stars(const Mesh_d& m) {
  const Filtered_exact_kernel k;
  const internal::Kernel_points<Filtered_exact_kernel, Point_3<double>> point(m.vertices, k);
  const auto projected = internal::projected_orientations(k, point, m.faces);
  return internal::embedded_star_flags(k, point, m.faces, projected, internal::degenerate_face_flags(projected),
                                       Mesh_topology::build(m));
}

// Apex 0 at the origin over a link of five points 144 degrees apart (a
// pentagram seen from above, at heights z), and apex 6 below: every face
// around apex 0 projects counterclockwise, yet the link winds twice around
// it, so the projection covers the plane twice and the faces may cross.
Mesh_d pentagram_suspension(const std::array<double, 5>& z) {
  Mesh_d m;
  m.vertices.push_back({0, 0, 0});
  for (int j = 0; j < 5; ++j) {
    const double a = 4 * std::numbers::pi * j / 5;
    m.vertices.push_back({std::cos(a), std::sin(a), z[static_cast<std::size_t>(j)]});
  }
  m.vertices.push_back({0.1, 0.05, -8});
  for (Index j = 0; j < 5; ++j) {
    const Index p = 1 + j, q = 1 + (j + 1) % 5;
    m.faces.push_back({0, p, q});
    m.faces.push_back({6, q, p});
  }
  return m;
}

TEST(EmbeddedStars, EveryVertexOfSmoothSolidsIsCertified) {
  for (const Mesh_d& m : {icosphere(3), torus(12, 8)}) {
    const auto flags = embedded_stars(m);
    ASSERT_EQ(flags.size(), m.vertices.size());
    EXPECT_EQ(std::count(flags.begin(), flags.end(), 1), static_cast<long>(m.vertices.size()));
  }
}

TEST(EmbeddedStars, BoundaryVerticesAreNeverCertified) {
  Mesh_d m = icosphere(2);
  const Triangle removed = m.faces.back();
  m.faces.pop_back();
  const auto flags = embedded_stars(m);
  for (Index v : removed) EXPECT_EQ(flags[v], 0) << v;
  EXPECT_GT(std::count(flags.begin(), flags.end(), 1), 0);
}

TEST(EmbeddedStars, AStarWhoseLinkWindsTwiceIsNotCertified) {
  const Mesh_d m = pentagram_suspension({0.1, 0.3, -0.2, 0.4, 0.0});
  const Mesh_report r = check_mesh(m);
  ASSERT_TRUE(r.is_valid()) << r.summary();  // a closed, oriented manifold
  const auto flags = embedded_stars(m);
  EXPECT_EQ(flags[0], 0);
  EXPECT_EQ(flags[6], 0);
}

// check_solid (which uses the certificate) reports exactly the pairs of the
// pairwise test (which does not) on suspensions of random heights, some of
// which make two faces around the twice-wound apex cross: a certificate
// that accepted a winding number of 2 would miss those.
TEST(EmbeddedStars, CheckSolidFindsThePairwiseTestsPairs) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> height(-4, 4);
  int crossing_at_apex = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::array<double, 5> z;
    for (double& x : z) x = 0.25 * height(rng);
    const Mesh_d m = pentagram_suspension(z);
    std::vector<std::pair<Index, Index>> reported;
    const Mesh_report r = check_solid(m);
    ASSERT_TRUE(r.self_intersections_checked) << r.summary();
    for (const Mesh_issue& i : r.issues)
      if (i.defect == Mesh_defect::self_intersection) reported.emplace_back(i.elements[0], i.elements[1]);
    std::vector<std::pair<Index, Index>> pairwise;
    for (const Face_pair& p : find_self_intersections(m).pairs) {
      pairwise.emplace_back(p.first, p.second);
      const auto around_apex = [&](Index f) { return m.faces[f][0] == 0; };
      crossing_at_apex += around_apex(p.first) && around_apex(p.second);
    }
    std::sort(reported.begin(), reported.end());
    EXPECT_EQ(reported, pairwise) << "trial " << trial;
  }
  EXPECT_GT(crossing_at_apex, 0);  // the hard case occurred
}

}  // namespace
