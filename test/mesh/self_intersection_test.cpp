// Self-intersection with exact predicates and check_solid.
#include "relgeo/mesh/self_intersection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include "mesh/mesh_fixtures.h"
#include "relgeo/mesh/internal/embedded_stars.h"
#include "relgeo/mesh/internal/projected_patches.h"

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

// star_embedded (the certificate from one vertex's star, without the
// mesh's topology: the rounding repair's) agrees with embedded_star_flags
// on every vertex: of smooth solids, of suspensions whose apex winds twice,
// of a sphere with a hole (boundary vertices: the star's link is a path),
// and of tori with noisy vertices (stars with folded faces).
TEST(EmbeddedStars, TheOneVertexTestAgreesWithTheWholeMeshes) {
  std::vector<Mesh_d> meshes{icosphere(3), torus(12, 8)};
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> height(-4, 4);
  for (int trial = 0; trial < 40; ++trial) {
    std::array<double, 5> z;
    for (double& x : z) x = 0.25 * height(rng);
    meshes.push_back(pentagram_suspension(z));
  }
  Mesh_d holed = icosphere(2);
  holed.faces.erase(holed.faces.begin() + 7);
  meshes.push_back(holed);
  std::normal_distribution<double> noise(0, 0.02);
  for (int trial = 0; trial < 4; ++trial) {
    Mesh_d noisy = torus(24, 16);
    for (auto& p : noisy.vertices) p.x += noise(rng), p.y += noise(rng), p.z += noise(rng);
    meshes.push_back(noisy);
  }
  long certified = 0, refused = 0;
  for (const Mesh_d& m : meshes) {
    const Filtered_exact_kernel k;
    const auto flags = embedded_stars(m);
    std::vector<std::vector<Index>> star(m.vertices.size());
    for (Index f = 0; f < m.faces.size(); ++f)
      for (Index v : m.faces[f]) star[v].push_back(f);
    const auto every_plane = internal::projected_orientations(k, m.vertices, m.faces);
    const auto projected = [&](Index f) { return every_plane[f]; };
    for (Index v = 0; v < m.vertices.size(); ++v) {
      const bool one = internal::star_embedded(k, m.vertices, m.faces, v, std::span<const Index>(star[v]), projected);
      EXPECT_EQ(one, flags[v] != 0) << "vertex " << v;
      (one ? certified : refused) += 1;
    }
  }
  // Both answers occurred: among the refused, the suspensions' apices, the
  // hole's rim and the folds of the noisy tori.
  EXPECT_GT(certified, 1000);
  EXPECT_GT(refused, 40);
}

// ---- the projected-patch certificate (mesh/internal/projected_patches.h) ---

std::vector<std::uint16_t> projected_patches(const Mesh_d& m) {
  const Filtered_exact_kernel k;
  const internal::Kernel_points<Filtered_exact_kernel, Point_3<double>> point(m.vertices, k);
  const auto projected = internal::projected_orientations(k, point, m.faces);
  return internal::projected_patches(k, point, m.faces, projected, internal::degenerate_face_flags(projected),
                                     Mesh_topology::build(m));
}

// The pairs check_solid (with every certificate) reports, sorted.
std::vector<std::pair<Index, Index>> check_solid_pairs(const Mesh_d& m) {
  const Mesh_report r = check_solid(m);
  EXPECT_TRUE(r.self_intersections_checked) << r.summary();
  std::vector<std::pair<Index, Index>> reported;
  for (const Mesh_issue& i : r.issues)
    if (i.defect == Mesh_defect::self_intersection) reported.emplace_back(i.elements[0], i.elements[1]);
  std::sort(reported.begin(), reported.end());
  return reported;
}
// The pairs of the pairwise test (no topology: no certificate).
std::vector<std::pair<Index, Index>> pairwise_pairs(const Mesh_d& m) {
  std::vector<std::pair<Index, Index>> out;
  for (const Face_pair& p : find_self_intersections(m).pairs) out.emplace_back(p.first, p.second);
  return out;
}

// An open sheet over the annulus 1 <= r <= 2 that turns 1.3 times around
// the z axis (n_r x n_theta quads, each cut in two, counterclockwise from
// above) at height z(r, theta) = rise theta / 2 pi + tilt (theta / 2 pi)
// (r - 1.5). Every face's normal points mostly up, so one patch would hold
// them all; its last 0.3 turn lies over its first, so the projection is not
// one to one. rise 0 and tilt != 0: the two layers cross along r = 1.5.
Mesh_d spiral_sheet(double rise, double tilt, int n_r = 8, int n_theta = 160) {
  Mesh_d m;
  const double turn = 2 * std::numbers::pi, span = 1.3 * turn;
  for (int j = 0; j <= n_theta; ++j)
    for (int i = 0; i <= n_r; ++i) {
      const double r = 1 + double(i) / n_r, theta = span * j / n_theta;
      m.vertices.push_back(
          {r * std::cos(theta), r * std::sin(theta), rise * theta / turn + tilt * (theta / turn) * (r - 1.5)});
    }
  const auto v = [&](int i, int j) { return static_cast<Index>(j * (n_r + 1) + i); };
  for (int j = 0; j < n_theta; ++j)
    for (int i = 0; i < n_r; ++i) {
      m.faces.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
      m.faces.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  return m;
}

TEST(ProjectedPatches, CoverSmoothSolidsAndCutTheSearch) {
  for (const Mesh_d& m : {icosphere(4), torus(64, 32)}) {
    const auto patch = projected_patches(m);
    const auto in_patches = std::count_if(patch.begin(), patch.end(), [](std::uint16_t p) { return p != 0; });
    EXPECT_GT(in_patches, static_cast<long>(0.8 * m.faces.size()));
    const Face_bvh bvh(m);
    const Mesh_topology t = Mesh_topology::build(m);
    const Self_intersections certified = internal::find_self_intersections(m, Filtered_exact_kernel{}, bvh, 1, &t);
    const Self_intersections pairwise = internal::find_self_intersections(m, Filtered_exact_kernel{}, bvh, 1);
    EXPECT_TRUE(certified.is_certainly_free() && pairwise.is_certainly_free());
    EXPECT_LT(4 * certified.candidate_pairs, pairwise.candidate_pairs);  // the search left the patches out
  }
}

// The hard case: two layers of one sheet, every face pointing up, cross.
// A certificate that grouped faces by their normal without the boundary
// loop's test would put both layers in one patch and miss every crossing.
TEST(ProjectedPatches, ASheetThatCoversItsProjectionTwiceIsTestedPairByPair) {
  const Mesh_d m = spiral_sheet(0.0, 0.4);
  const auto pairwise = pairwise_pairs(m);
  ASSERT_FALSE(pairwise.empty());  // the layers cross
  EXPECT_EQ(check_solid_pairs(m), pairwise);
  const auto patch = projected_patches(m);
  for (const auto& [f, g] : pairwise) EXPECT_TRUE(patch[f] == 0 || patch[f] != patch[g]) << f << " " << g;
  // Pieces of the sheet are certified (the test does not give up on it).
  EXPECT_GT(std::count_if(patch.begin(), patch.end(), [](std::uint16_t p) { return p != 0; }), 0);
}

TEST(ProjectedPatches, ASheetThatCoversItsProjectionTwiceWithoutCrossingIsFree) {
  const Mesh_d m = spiral_sheet(0.5, 0.0);
  EXPECT_TRUE(pairwise_pairs(m).empty());
  EXPECT_TRUE(check_solid_pairs(m).empty());
}

// check_solid reports the pairwise test's pairs on solids whose vertices
// were pushed at random (some through the surface), patches or not.
TEST(ProjectedPatches, CheckSolidFindsThePairwiseTestsPairsOnDentedSolids) {
  std::mt19937 rng(11);
  int with_crossings = 0;
  for (int trial = 0; trial < 12; ++trial) {
    Mesh_d m = trial % 2 ? icosphere(3) : torus(24, 12);
    std::uniform_int_distribution<Index> vertex(0, static_cast<Index>(m.vertices.size() - 1));
    std::uniform_real_distribution<double> push(-1.5, 1.5);
    for (int d = 0; d < 3; ++d) {
      Point_3<double>& p = m.vertices[vertex(rng)];
      const double s = push(rng);
      p = {p.x * (1 + s), p.y * (1 + s), p.z * (1 + s)};
    }
    const auto pairwise = pairwise_pairs(m);
    with_crossings += !pairwise.empty();
    EXPECT_EQ(check_solid_pairs(m), pairwise) << "trial " << trial;
  }
  EXPECT_GT(with_crossings, 0);
}

// ---- the caller's certificates (Certified_faces: the Boolean's output) ----

// The certified search finds every pair the pairwise test finds but those
// of two faces of one group, whatever the groups and the thread count: on
// a soup of random triangles crossing each other often, the open faces'
// hierarchy meets every pair with an open face (its self search and the
// certified faces' queries), and the cross pairs (from the caller's list
// only) are all tested, each candidate once.
TEST(CertifiedFaces, TheSearchLeavesOutOnlyThePairsWithinOneGroup) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> at(0, 4), offset(-0.6, 0.6);
  std::uniform_int_distribution<int> group_of(0, 2);
  Mesh_d m;
  for (Index f = 0; f < 600; ++f) {
    const Point_3<double> c{at(rng), at(rng), at(rng)};
    for (int i = 0; i < 3; ++i) m.vertices.push_back({c.x + offset(rng), c.y + offset(rng), c.z + offset(rng)});
    m.faces.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  }
  const std::vector<Face_pair> all = find_self_intersections(m).pairs;
  const Filtered_exact_kernel k;
  const internal::Kernel_points<Filtered_exact_kernel, Point_3<double>> point(m.vertices, k);
  const std::vector<unsigned char> skip(m.faces.size(), 0);
  const Face_bvh bvh(m);
  for (int trial = 0; trial < 4; ++trial) {
    internal::Certified_faces certified;
    for (std::size_t f = 0; f < m.faces.size(); ++f)
      certified.group.push_back(static_cast<std::uint8_t>(trial == 0 ? 1 + f % 2 : group_of(rng)));
    const auto& group = certified.group;
    bvh.for_each_overlapping_pair([&](Index f, Index g) {
      if (group[f] && group[g] && group[f] != group[g])
        certified.cross_pairs.push_back({std::min(f, g), std::max(f, g)});
    });
    std::vector<Face_pair> expected;
    for (const Face_pair& p : all)
      if (!(group[p.first] && group[p.first] == group[p.second])) expected.push_back(p);
    ASSERT_FALSE(expected.empty());
    std::size_t with_open_face = 0;  // candidate pairs besides the cross pairs
    bvh.for_each_overlapping_pair([&](Index f, Index g) { with_open_face += !group[f] || !group[g]; });
    for (const int threads : {1, 2}) {
      Self_intersections found;
      internal::find_self_intersections(k, m, point, skip, certified, threads, found);
      EXPECT_EQ(found.pairs, expected) << "trial " << trial << ", " << threads << " threads";
      EXPECT_EQ(found.candidate_pairs, with_open_face + certified.cross_pairs.size()) << "trial " << trial;
      EXPECT_TRUE(found.undecided.empty());
    }
  }
}

}  // namespace
