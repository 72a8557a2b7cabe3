// test/boolean/limit_embedding_test.cpp — the adjacent_pieces check of the
// subdivision-solid validation (boolean/internal/limit_embedding.h):
// neighbouring limit pieces are certified to meet only where their faces
// meet on regular surfaces, a real fold between neighbours is never
// certified (while the far-piece test passes on it), and what needs an
// extraordinary vertex stays undecided and is named.
#include <gtest/gtest.h>

#include <algorithm>
#include <queue>
#include <random>
#include <vector>

#include "relgeo/boolean/subdivision_validation.h"
#include "relgeo/kernel.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/shapes.h"
#include "relgeo/subdivision/loop_subdivision.h"

namespace relgeo::test {
namespace {

using Mesh = Triangle_mesh<Point_3<double>>;

// Pairs of a fine limit mesh that certainly cross (exact predicates): the
// independent evidence that a limit surface folds.
std::size_t crossing_pairs_at_level(const Mesh& control, unsigned level = 4) {
  const Mesh limit = Loop_subdivider<Filtered_exact_kernel>().limit_mesh(control, level);
  return find_self_intersections(limit, Filtered_exact_kernel{}, Self_intersection_options{}).pairs.size();
}

// The torus with vertex 0 moved by s times its step to vertex 12 (the next
// ring): the control net folds over itself for s > 1.
Mesh torus_with_vertex_pushed(double s) {
  Mesh m = torus(3, 1, 24, 12);
  const auto p = m.vertices[0], q = m.vertices[12];
  m.vertices[0] = {p.x + s * (q.x - p.x), p.y + s * (q.y - p.y), p.z + s * (q.z - p.z)};
  return m;
}

TEST(LimitEmbedding, RegularTorusIsCertifiedWholly) {
  const Mesh m = torus(3, 1, 24, 12);  // every vertex of valence 6
  const Subdivision_validation v = validate_subdivision_solid(m);
  EXPECT_EQ(v.adjacent_pieces.status, Check_status::pass) << v.adjacent_pieces.note;
  EXPECT_TRUE(v.is_certified()) << v.summary();
  EXPECT_EQ(v.certified_regions, m.vertices.size());
  EXPECT_GT(v.adjacent_pairs, 10 * m.faces.size());
}

// A coarse torus: no influence region is a graph at the control level (the
// Jacobian changes sign over 8 x 6 faces), one level of refinement is.
TEST(LimitEmbedding, CoarseTorusIsCertifiedThroughRefinement) {
  const Mesh m = torus(3, 1, 8, 6);
  const Subdivision_validation refined = validate_subdivision_solid(m);
  EXPECT_EQ(refined.certified_regions, 0u);
  EXPECT_EQ(refined.adjacent_pieces.status, Check_status::pass) << refined.adjacent_pieces.note;
  const Subdivision_validation control_level_only = validate_subdivision_solid(m, {}, {.refinement_levels = 0});
  EXPECT_EQ(control_level_only.adjacent_pieces.status, Check_status::undecided);
  EXPECT_EQ(control_level_only.adjacent_pieces.count, control_level_only.adjacent_pairs + m.faces.size());
}

// The hard case: a fold between neighbouring pieces. A fine limit mesh
// crosses itself, the far-piece test passes all the same (what the report
// certified before this check existed), and the neighbouring pieces are not
// certified; the same torus pushed less is embedded and certified.
TEST(LimitEmbedding, FoldBetweenNeighboursIsNeverCertified) {
  const Mesh folded = torus_with_vertex_pushed(2.0);
  ASSERT_GT(crossing_pairs_at_level(folded), 0u);
  const Subdivision_validation v = validate_subdivision_solid(folded);
  EXPECT_EQ(v.separated_pieces.status, Check_status::pass) << v.summary();
  EXPECT_EQ(v.adjacent_pieces.status, Check_status::undecided);
  EXPECT_FALSE(v.is_certified());
  EXPECT_TRUE(v.has_no_defect());  // undecided, not a proven intersection
  // The undecided pieces are next to the moved vertex (its 3-ring).
  const Mesh_topology t = Mesh_topology::build(folded);
  std::vector<int> ring(folded.vertices.size(), -1);
  std::queue<Index> q;
  ring[0] = 0, q.push(0);
  while (!q.empty()) {
    const Index a = q.front();
    q.pop();
    for (Index b : t.vertex_ring(a))
      if (ring[b] < 0) ring[b] = ring[a] + 1, q.push(b);
  }
  for (const Mesh_issue& i : v.adjacent_pieces.where)
    for (Index f : i.elements)
      if (f != invalid_index) {
        const auto& face = folded.faces[f];
        EXPECT_LE(std::min({ring[face[0]], ring[face[1]], ring[face[2]]}), 3) << "face " << f;
      }
  const Mesh pushed_less = torus_with_vertex_pushed(1.5);
  EXPECT_EQ(crossing_pairs_at_level(pushed_less), 0u);
  EXPECT_TRUE(validate_subdivision_solid(pushed_less).is_certified());
}

// Soundness on random bumpy tori: whenever the check certifies, a fine
// limit mesh (level 3) does not cross itself (measured: 7 of 12 certified,
// 3 crossing); and the noise is large enough that some
// surfaces fold (the implication is tested, not assumed).
TEST(LimitEmbedding, CertifiedRandomSurfacesHaveNoCrossingLimitMesh) {
  std::mt19937 rng(20261126);
  std::normal_distribution<double> noise(0.0, 0.3);
  int certified = 0, crossing = 0;
  for (int trial = 0; trial < 12; ++trial) {
    Mesh m = torus(3, 1, 16, 8);
    for (auto& p : m.vertices) p = {p.x + noise(rng), p.y + noise(rng), p.z + noise(rng)};
    const Subdivision_validation v = validate_subdivision_solid(m);
    const std::size_t crossings = crossing_pairs_at_level(m, 3);
    crossing += crossings > 0;
    if (v.is_certified()) {
      ++certified;
      EXPECT_EQ(crossings, 0u) << "trial " << trial;
    }
    EXPECT_TRUE(v.has_no_defect()) << v.summary();
  }
  EXPECT_GT(certified, 0);
  EXPECT_GT(crossing, 0);
}

// Extraordinary vertices (valence 5 on a Loop sphere) have no Bezier net:
// the pieces around them stay undecided, never pass, and pieces away from
// them are certified.
TEST(LimitEmbedding, ExtraordinaryVerticesStayUndecidedAndNamed) {
  const Mesh m = icosphere(3);  // 12 vertices of valence 5
  const Subdivision_validation v = validate_subdivision_solid(m, {}, {.max_listed = 1'000'000});
  EXPECT_EQ(v.adjacent_pieces.status, Check_status::undecided);
  EXPECT_GT(v.certified_regions, 0u);
  EXPECT_LT(v.adjacent_pieces.count, v.adjacent_pairs);
  ASSERT_EQ(v.adjacent_pieces.where.size(), v.adjacent_pieces.count);
  const Mesh_topology t = Mesh_topology::build(m);
  std::vector<char> near_extraordinary(m.faces.size(), 0);
  // Faces whose 2-ring region holds a face at an extraordinary vertex.
  std::vector<int> ring(m.vertices.size(), -1);
  std::queue<Index> q;
  for (Index a = 0; a < m.vertices.size(); ++a)
    if (t.valence(a) != 6) ring[a] = 0, q.push(a);
  while (!q.empty()) {
    const Index a = q.front();
    q.pop();
    for (Index b : t.vertex_ring(a))
      if (ring[b] < 0) ring[b] = ring[a] + 1, q.push(b);
  }
  std::size_t far_faces = 0;
  for (Index f = 0; f < m.faces.size(); ++f) {
    const int d = std::min({ring[m.faces[f][0]], ring[m.faces[f][1]], ring[m.faces[f][2]]});
    far_faces += d > 3;
    for (const Mesh_issue& i : v.adjacent_pieces.where) {
      if (i.elements[0] == f && i.elements[1] == invalid_index) {
        EXPECT_LE(d, 3) << "piece " << f;
      }
    }
  }
  EXPECT_GT(far_faces, 0u);
}

}  // namespace
}  // namespace relgeo::test
