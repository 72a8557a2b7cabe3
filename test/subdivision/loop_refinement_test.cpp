// Loop refinement: combinatorial invariants, agreement across kernels, the
// fused limit mesh, and the exactness of limit positions under refinement.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "relgeo/kernel.h"
#include "relgeo/mesh.h"
#include "subdivision/subdivision_fixtures.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;
using Mesh_q = Triangle_mesh<Point_3<mpq_class>>;

std::vector<Mesh_d> corpus() {
  return {tetrahedron(), octahedron(), icosphere(1), torus(6, 5), creased_box(), open_grid(3),
          bipyramid(3), bipyramid(7), bipyramid(12), disk(7, 3), half_fan(5)};
}

TEST(LoopRefinement, CountsEulerCharacteristicClosednessAndValences) {
  for (const Mesh_d& m : corpus()) {
    Mesh_d cur = m;
    for (int level = 1; level <= 3; ++level) {
      const Mesh_topology t = Mesh_topology::build(cur);
      const Mesh_d next = loop_subdivide(cur, 1);
      const Mesh_topology tn = Mesh_topology::build(next);
      EXPECT_EQ(next.vertices.size(), cur.vertices.size() + t.number_of_edges());
      EXPECT_EQ(next.faces.size(), 4 * cur.faces.size());
      EXPECT_EQ(tn.number_of_edges(), 2 * t.number_of_edges() + 3 * t.number_of_faces());
      const auto chi = [](const Mesh_topology& x) {
        return long(x.number_of_vertices()) - long(x.number_of_edges()) + long(x.number_of_faces());
      };
      EXPECT_EQ(chi(tn), chi(t));
      const Mesh_report r0 = check_mesh(cur, {.check_collinear_faces = false});
      const Mesh_report r1 = check_mesh(next, {.check_collinear_faces = false});
      EXPECT_EQ(r1.is_closed(), r0.is_closed());
      EXPECT_TRUE(r1.is_manifold() && r1.is_consistently_oriented());
      EXPECT_EQ(r1.count(Mesh_defect::boundary_edge), 2 * r0.count(Mesh_defect::boundary_edge));
      // old vertices keep their valence; new ones have 6 (interior) or 4 (boundary)
      for (Index v = 0; v < cur.vertices.size(); ++v) EXPECT_EQ(tn.valence(v), t.valence(v));
      for (Index v = Index(cur.vertices.size()); v < next.vertices.size(); ++v)
        EXPECT_EQ(tn.valence(v), tn.is_boundary_vertex(v) ? 4u : 6u);
      cur = next;
    }
  }
}

TEST(LoopRefinement, DerivedTopologyEqualsTheBuiltOne) {
  // Mesh_topology::refined (used from level 2 on) against a fresh build of
  // the refined faces: the same opposites, edges, walk starts and rings.
  for (const Mesh_d& m : corpus()) {
    const Mesh_topology t = Mesh_topology::build(m);
    const Mesh_d r = loop_subdivide(m, 1);
    const Mesh_topology d = Mesh_topology::refined(t, r.faces), b = Mesh_topology::build(r);
    ASSERT_EQ(d.number_of_edges(), b.number_of_edges());
    for (Index h = 0; h < b.number_of_halfedges(); ++h) {
      EXPECT_EQ(d.opposite(h), b.opposite(h)) << h;
      EXPECT_EQ(d.edge(h), b.edge(h)) << h;
      const Index ph = Mesh_topology::parent_halfedge(h);
      if (ph != invalid_index) {  // a half of a parent edge: shares one endpoint with it
        const Index s = d.source(h), e = d.target(h);
        EXPECT_TRUE(s == t.source(ph) || e == t.target(ph)) << h;
      }
    }
    for (Index v = 0; v < b.number_of_vertices(); ++v) {
      EXPECT_EQ(d.vertex_halfedge(v), b.vertex_halfedge(v)) << v;
      EXPECT_EQ(d.vertex_ring(v), b.vertex_ring(v)) << v;
    }
    // and the features derived from the parent's
    const Loop_features pf = classify_loop_features(t, m.tags);
    const Loop_features df = refined_loop_features(t, pf, d), bf = classify_loop_features(b, r.tags);
    EXPECT_EQ(df.edge_is_crease, bf.edge_is_crease);
    EXPECT_EQ(df.edge_is_tagged, bf.edge_is_tagged);
    EXPECT_EQ(df.vertex_kind, bf.vertex_kind);
  }
}

TEST(LoopRefinement, TagsFollowTheirEdgesAndCreasesOfTheBoxStayOnItsEdges) {
  const Mesh_q box = convert<mpq_class>(creased_box());
  const Mesh_q r = loop_subdivide(box, 3);
  EXPECT_EQ(r.tags.creases().size(), 12u * 8);  // 12 box edges, each split 3 times
  EXPECT_EQ(r.tags.corners().size(), 8u);
  // Every vertex on a tagged crease lies exactly on a box edge: two of its
  // coordinates are 0 or 2 (crease rules use crease neighbours only).
  std::vector<char> on_crease(r.vertices.size(), 0);
  for (const Edge& e : r.tags.creases()) on_crease[e.a] = on_crease[e.b] = 1;
  for (Index v = 0; v < r.vertices.size(); ++v) {
    if (!on_crease[v]) continue;
    const auto& p = r.vertices[v];
    int extreme = 0;
    for (const mpq_class* c : {&p.x, &p.y, &p.z}) extreme += (*c == 0 || *c == 2);
    EXPECT_GE(extreme, 2) << v;
  }
  for (Index v = 0; v < 8; ++v) EXPECT_EQ(r.vertices[v], box.vertices[v]);  // corners fixed
}

TEST(LoopRefinement, PlanarOpenMeshesStayPlanarAndTheirBoundaryStaysOnTheBoundaryLine) {
  Mesh_d g = open_grid(4);
  for (auto& p : g.vertices) p.z = 0;
  for (Index c : {0u, 4u, 20u, 24u}) g.tags.add_corner(c);  // else the boundary curve rounds the corners
  const auto r = loop_subdivide(convert<mpq_class>(g), 2);
  for (const auto& p : r.vertices) {
    EXPECT_EQ(p.z, 0);
    EXPECT_TRUE(p.x >= 0 && p.x <= 4 && p.y >= 0 && p.y <= 4);
  }
  const Mesh_topology t = Mesh_topology::build(r);
  for (Index v = 0; v < r.vertices.size(); ++v)
    if (t.is_boundary_vertex(v)) {
      const auto& p = r.vertices[v];
      EXPECT_TRUE(p.x == 0 || p.x == 4 || p.y == 0 || p.y == 4) << v;
    }
}

// The same refinement under every kernel: floating kernels within rounding
// of the exact result, intervals enclosing it (valences 3, 4, 6 and creases:
// all weights rational, so the exact kernel computes Loop's true surface).
template <class K>
Triangle_mesh<typename K::Point_3> refine_as(const Mesh_d& m, unsigned levels, const Loop_options& o) {
  Triangle_mesh<typename K::Point_3> c;
  const auto cp = K().construct_point_3_object();
  for (const auto& p : m.vertices) c.vertices.push_back(cp(p.x, p.y, p.z));
  c.faces = m.faces;
  c.tags = m.tags;
  return Loop_subdivider<K>(o).refine(c, levels);
}

TEST(LoopRefinement, EveryKernelAgreesWithTheExactOne) {
  double worst_float_all = 0;
  for (const Mesh_d& m : {tetrahedron(), octahedron(), torus(5, 4), creased_box(), open_grid(3)}) {
    const Mesh_q exact = refine_as<Exact_kernel>(m, 3, hoppe);
    const auto naive = refine_as<Naive_kernel<double>>(m, 3, hoppe);
    const auto failsafe = refine_as<Failsafe_kernel<double>>(m, 3, hoppe);
    const auto filtered = refine_as<Filtered_exact_kernel>(m, 3, hoppe);
    const auto interval = refine_as<Interval_kernel>(m, 3, hoppe);
    const auto mpfr = refine_as<Mpfr_kernel<113>>(m, 3, hoppe);
    const auto lfloat = refine_as<Naive_kernel<float>>(m, 3, hoppe);
    ASSERT_EQ(naive.faces, exact.faces);
    EXPECT_EQ(naive.vertices, failsafe.vertices);  // same constructions, bit for bit
    EXPECT_EQ(naive.vertices, filtered.vertices);
    double worst = 0, worst_mpfr = 0, worst_float = 0;
    for (std::size_t v = 0; v < exact.vertices.size(); ++v) {
      const auto& e = exact.vertices[v];
      for (int c = 0; c < 3; ++c) {
        const mpq_class& ec = c == 0 ? e.x : c == 1 ? e.y : e.z;
        const double n = c == 0 ? naive.vertices[v].x : c == 1 ? naive.vertices[v].y : naive.vertices[v].z;
        worst = std::max(worst, std::abs(mpq_class(ec - n).get_d()));
        const Interval& iv = c == 0 ? interval.vertices[v].x : c == 1 ? interval.vertices[v].y : interval.vertices[v].z;
        EXPECT_TRUE(mpq_class(iv.inf()) <= ec && ec <= mpq_class(iv.sup())) << "vertex " << v;
        const auto& mp = c == 0 ? mpfr.vertices[v].x : c == 1 ? mpfr.vertices[v].y : mpfr.vertices[v].z;
        worst_mpfr = std::max(worst_mpfr, std::abs(mpq_class(ec - mpq_class(mp.to_double())).get_d()));
        const float f = c == 0 ? lfloat.vertices[v].x : c == 1 ? lfloat.vertices[v].y : lfloat.vertices[v].z;
        worst_float = std::max(worst_float, std::abs(mpq_class(ec - f).get_d()));
      }
    }
    EXPECT_LT(worst, 1e-14);
    EXPECT_LT(worst_mpfr, 1e-15);  // the double rounding of the comparison dominates
    EXPECT_LT(worst_float, 1e-5);
    worst_float_all = std::max(worst_float_all, worst_float);
  }
  EXPECT_GT(worst_float_all, 0);  // float really is less precise: the comparison can tell
}

template <class P>
void expect_same_points(const std::vector<P>& a, const std::vector<P>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << "vertex " << i;
}

TEST(LoopLimitMesh, FusedLimitMeshEqualsLimitPositionsOfTheRefinedMeshExactly) {
  for (const Loop_options& o : {hoppe, warren, blz})
    for (const Mesh_d& m : {creased_box(), open_grid(3), bipyramid(5), torus(4, 4), disk(7, 3), half_fan(5)}) {
      Loop_subdivider<Exact_kernel> s(o);
      const Mesh_q q = convert<mpq_class>(m);
      for (unsigned k : {0u, 1u, 2u}) {
        const Mesh_q lim = s.limit_mesh(q, k);
        const Mesh_q ref = s.refine(q, k);
        EXPECT_EQ(lim.faces, ref.faces);
        EXPECT_EQ(lim.tags, ref.tags);
        expect_same_points(lim.vertices, s.limit_positions(ref));
      }
    }
}

TEST(LoopLimitMesh, DoubleLimitMeshIsWithinRoundingOfTheExactOne) {
  const Mesh_d m = jitter(icosphere(2), 0.05);
  const auto ld = loop_limit_mesh(m, 2);
  const auto lq = loop_limit_mesh(convert<mpq_class>(m), 2);
  double worst = 0;
  for (std::size_t v = 0; v < ld.vertices.size(); ++v)
    worst = std::max({worst, std::abs(mpq_class(lq.vertices[v].x - ld.vertices[v].x).get_d()),
                      std::abs(mpq_class(lq.vertices[v].y - ld.vertices[v].y).get_d()),
                      std::abs(mpq_class(lq.vertices[v].z - ld.vertices[v].z).get_d())});
  // valence 5 uses beta within 2^-256 of Loop's in the exact kernel and the
  // correctly rounded double in the double kernel: both are far below 1e-14
  EXPECT_LT(worst, 1e-14);
}

// Limit positions are a property of the surface, not of the level: refining
// must not move them. Exactly, under the exact kernel, whenever the limit
// mask is the exact eigenvector of the rule applied (see loop_masks.h):
// smooth vertices whose edges follow the standard rule, crease and corner
// vertices.
TEST(LoopLimitMesh, RefiningDoesNotMoveLimitPositionsAtAnyValence) {
  for (const Loop_options& o : {hoppe, warren})
    for (const Mesh_d& m : {bipyramid(3), bipyramid(4), bipyramid(5), bipyramid(8), bipyramid(12), torus(5, 4),
                            creased_box(), open_grid(3), half_fan(4), jitter(icosphere(1), 0.1)}) {
      Loop_subdivider<Exact_kernel> s(o);
      const Mesh_q q = convert<mpq_class>(m);
      const auto before = s.limit_positions(q);
      const auto after = s.limit_positions(s.refine(q, 1));
      for (std::size_t v = 0; v < before.size(); ++v) EXPECT_EQ(before[v], after[v]) << "vertex " << v;
    }
}

TEST(LoopLimitMesh, BlzCreaseAndCornerLimitPositionsAreInvariantToo) {
  Loop_subdivider<Exact_kernel> s(blz);
  for (const Mesh_d& m : {creased_box(), disk(8, 3), open_grid(3)}) {
    const Mesh_q q = convert<mpq_class>(m);
    const Mesh_topology t = Mesh_topology::build(q);
    const Loop_features f = classify_loop_features(t, q.tags);
    const auto before = s.limit_positions(q);
    const auto after = s.limit_positions(s.refine(q, 1));
    int checked = 0;
    for (Index v = 0; v < before.size(); ++v) {
      bool next_to_special = false;
      for (Index p : t.vertex_ring(v)) next_to_special |= f.is_special(p);
      if (f.is_special(v) || !next_to_special) {
        EXPECT_EQ(before[v], after[v]) << "vertex " << v;
        ++checked;
      }
    }
    EXPECT_GT(checked, 0);
  }
}

}  // namespace
