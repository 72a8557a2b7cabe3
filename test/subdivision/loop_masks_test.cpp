// The stencils of loop_masks.h: they agree with the fused refinement, and the
// tangent masks are left eigenvectors of the local refinement rule (so their
// cross product is the exact limit normal).
#include <gtest/gtest.h>

#include <cmath>

#include "relgeo/kernel.h"
#include "subdivision/loop_stencil_check.h"
#include "subdivision/subdivision_fixtures.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;
using Mesh_q = Triangle_mesh<Point_3<mpq_class>>;
using Pq = Point_3<mpq_class>;

TEST(LoopStencils, RefinementFastPathEqualsTheStencilsExactly) {
  for (const Loop_options& o : {hoppe, blz, Loop_options{.vertex_weights = Loop_vertex_weights::warren}})
    for (const Mesh_d& m : {creased_box(), open_grid(3), bipyramid(7), disk(7, 3), half_fan(5), torus(4, 3)}) {
      const Mesh_q q = convert<mpq_class>(m);
      Loop_subdivider<Exact_kernel> s(o);
      expect_refinement_is_the_stencils(s, q, s.refine(q, 1));
    }
}

TEST(LoopStencils, StencilWeightsSumToOneOrZero) {
  const Mesh_q q = convert<mpq_class>(disk(9, 4));
  Loop_subdivider<Exact_kernel> s(blz);
  const Mesh_topology t = Mesh_topology::build(q);
  const Loop_features f = classify_loop_features(t, q.tags);
  const auto total = [](const Stencil<mpq_class>& st) {
    mpq_class x = 0;
    for (const auto& w : st.weights) x += w;
    return x;
  };
  for (Index v = 0; v < q.vertices.size(); ++v) {
    EXPECT_EQ(total(vertex_point_stencil(t, f, s.weights(), v)), 1);
    EXPECT_EQ(total(limit_stencil(t, f, s.weights(), v)), 1);
    const auto [t1, t2] = tangent_stencils(t, f, s.weights(), v);
    EXPECT_EQ(total(t1), 0) << v;
    EXPECT_EQ(total(t2), 0) << v;
  }
  for (Index e = 0; e < t.number_of_edges(); ++e) EXPECT_EQ(total(edge_point_stencil(t, f, s.weights(), e)), 1);
}

// The tangent stencil of v evaluated on the refined mesh equals lambda times
// its value on the control mesh (same vertex index, same sector).
struct Eigen_case {
  Mesh_d mesh;
  Index vertex;
  bool exact;  // all cosines rational
};

Pq minus(const Pq& a, const Pq& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Pq scaled(const mpq_class& s, const Pq& a) { return {s * a.x, s * a.y, s * a.z}; }
double norm_d(const Pq& a) { return std::sqrt(a.x.get_d() * a.x.get_d() + a.y.get_d() * a.y.get_d() + a.z.get_d() * a.z.get_d()); }

void check_eigen(const Mesh_d& m, Index v, const Loop_options& o, bool exact, Index sector_vertex = invalid_index) {
  Loop_subdivider<Exact_kernel> s(o);
  const Mesh_q q = convert<mpq_class>(m);
  const Mesh_q r = s.refine(q, 1);
  const Mesh_topology t0 = Mesh_topology::build(q), t1 = Mesh_topology::build(r);
  const Loop_features f0 = classify_loop_features(t0, q.tags), f1 = classify_loop_features(t1, r.tags);
  Index h0 = invalid_index, h1 = invalid_index;
  if (sector_vertex != invalid_index) {  // the sector holding edge (v, sector_vertex)
    h0 = t0.find_halfedge(v, sector_vertex);
    const Index e = t0.find_edge(v, sector_vertex);
    h1 = t1.find_halfedge(v, Index(q.vertices.size() + e));
  }
  const auto [a0, b0] = tangent_stencils(t0, f0, s.weights(), v, h0);
  const auto [a1, b1] = tangent_stencils(t1, f1, s.weights(), v, h1);
  const Pq ta0 = apply_stencil(a0, q.vertices), tb0 = apply_stencil(b0, q.vertices);
  const Pq ta1 = apply_stencil(a1, r.vertices), tb1 = apply_stencil(b1, r.vertices);
  // lambda from the first non-zero coordinate
  const auto ratio = [](const Pq& x1, const Pq& x0) { return x0.x != 0 ? x1.x / x0.x : x0.y != 0 ? x1.y / x0.y : x1.z / x0.z; };
  const mpq_class la = ratio(ta1, ta0), lb = ratio(tb1, tb0);
  const Pq ea = minus(ta1, scaled(la, ta0)), eb = minus(tb1, scaled(lb, tb0));
  if (exact) {
    EXPECT_EQ(ea, (Pq{0, 0, 0})) << "first tangent, vertex " << v;
    EXPECT_EQ(eb, (Pq{0, 0, 0})) << "second tangent, vertex " << v;
  } else {
    EXPECT_LT(norm_d(ea), 1e-60 * norm_d(ta0)) << "first tangent, vertex " << v;
    EXPECT_LT(norm_d(eb), 1e-60 * norm_d(tb0)) << "second tangent, vertex " << v;
  }
  EXPECT_GT(norm_d(ta0), 0);
  EXPECT_GT(norm_d(tb0), 0);
}

TEST(LoopTangents, SmoothMasksAreLeftEigenvectorsExactlyAtValences3_4_6) {
  check_eigen(bipyramid(3), 3, hoppe, true);  // apex of valence 3
  check_eigen(octahedron(), 0, hoppe, true);  // valence 4
  check_eigen(torus(5, 4), 0, hoppe, true);   // valence 6
  check_eigen(disk(6), 0, hoppe, true);
}

TEST(LoopTangents, SmoothMasksAtIrrationalValencesAreEigenvectorsTo256Bits) {
  for (int n : {5, 7, 8, 9, 12}) check_eigen(disk(n), 0, hoppe, false);
}

TEST(LoopTangents, CreaseMasksHoppeRules) {
  check_eigen(half_fan(1), 0, hoppe, true);
  check_eigen(half_fan(2), 0, hoppe, true);
  check_eigen(half_fan(3), 0, hoppe, true);
  check_eigen(half_fan(4), 0, hoppe, false);
  check_eigen(half_fan(6), 0, hoppe, false);  // cos(pi/6) is irrational
  for (int k : {2, 3, 4, 5}) check_eigen(disk(9, k), 0, hoppe, k == 2 || k == 3, 2);  // sector holding edge (0, 2)
}

TEST(LoopTangents, CreaseMasksBlzRules) {
  for (int k : {2, 3, 4, 5}) check_eigen(disk(9, k), 0, blz, k == 2 || k == 3, 2);
  for (int k : {2, 3, 4}) check_eigen(disk(8, k), 0, blz, false, 7);  // the other sector (8 - k faces)
}

TEST(LoopTangents, CornerMasksAreTheCreaseCurvesEndTangents) {
  Mesh_d m = creased_box();
  check_eigen(m, 0, hoppe, true, 8 + 0);  // box corner 0, sector of the side whose centre is vertex 8
}

TEST(LoopTangents, NormalFromTheTangentsPointsOutward) {
  Loop_subdivider<Exact_kernel> s;
  const Mesh_q q = convert<mpq_class>(icosphere(1));
  const Mesh_topology t = Mesh_topology::build(q);
  const Loop_features f = classify_loop_features(t, q.tags);
  for (Index v = 0; v < q.vertices.size(); ++v) {
    const auto [a, b] = tangent_stencils(t, f, s.weights(), v);
    const Pq ta = apply_stencil(a, q.vertices), tb = apply_stencil(b, q.vertices);
    const Pq n{ta.y * tb.z - ta.z * tb.y, ta.z * tb.x - ta.x * tb.z, ta.x * tb.y - ta.y * tb.x};
    const auto& p = q.vertices[v];  // sphere centred at the origin: outward = p
    EXPECT_GT(n.x * p.x + n.y * p.y + n.z * p.z, 0) << v;
  }
}

}  // namespace
