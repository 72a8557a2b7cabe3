// The quality of the Boolean's retriangulation (issue 28, item 2): each split
// face is a constrained Delaunay triangulation in its plane. Checked from the
// output alone, with a test independent of the engine's: for every edge
// inside one input face (two output faces with the same provenance, not an
// intersection curve) the vertex across it lies outside the circumcircle of
// the face on this side, in 3D, with a margin. The triangulation of the
// insertion order fails that on the same cases (the test can fail), and it
// leaves needles that the nearest rounding turns over.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "boolean_chains.h"
#include "boolean_inputs.h"
#include "relgeo/boolean.h"
#include "relgeo/boolean/internal/face_triangulation.h"

namespace relgeo::test {
namespace {

using Op = Boolean_operation;
using V3 = std::array<long double, 3>;

V3 sub(const Point_3<double>& a, const Point_3<double>& b) {
  return {static_cast<long double>(a.x) - b.x, static_cast<long double>(a.y) - b.y, static_cast<long double>(a.z) - b.z};
}
using internal::cross;
using internal::dot;

// Whether q lies inside the circumcircle of (u, v, p) by more than a
// relative margin: |q - c|^2 < (1 - margin) R^2, c the circumcentre.
bool clearly_inside_circumcircle(const Point_3<double>& u, const Point_3<double>& v, const Point_3<double>& p,
                                 const Point_3<double>& q) {
  const V3 a = sub(v, u), b = sub(p, u), n = cross(a, b);
  const long double nn = dot(n, n);
  if (!(nn > 0)) return false;
  const V3 t1 = cross(b, n), t2 = cross(n, a);
  V3 c;  // circumcentre relative to u
  for (int i = 0; i < 3; ++i) c[i] = (dot(a, a) * t1[i] + dot(b, b) * t2[i]) / (2 * nn);
  const V3 qu = sub(q, u);
  const V3 d{qu[0] - c[0], qu[1] - c[1], qu[2] - c[2]};
  return dot(d, d) < (1 - 1e-6L) * dot(c, c);
}

struct Quality {
  std::size_t non_delaunay_edges = 0;  // inside an input face
  std::size_t faces = 0;
  double smallest_angle_deg = 180;
};

template <class K>
Quality quality_of(const Boolean_result<K>& r) {
  Quality q;
  const auto& m = r.mesh;
  q.faces = m.faces.size();
  std::map<std::pair<Index, Index>, std::pair<Index, int>> half;  // directed edge -> face, corner opposite
  for (Index f = 0; f < m.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) half[{m.faces[f][k], m.faces[f][(k + 1) % 3]}] = {f, (k + 2) % 3};
  const auto crease = [&](Index u, Index v) {
    const auto creases = m.tags.creases();
    const Edge e = Edge::of(u, v);
    return std::binary_search(creases.begin(), creases.end(), e);
  };
  for (const auto& [edge, face] : half) {
    const auto [u, v] = edge;
    if (u > v) continue;
    const auto twin = half.find({v, u});
    if (twin == half.end()) continue;
    const Index f = face.first, g = twin->second.first;
    if (!(r.provenance[f] == r.provenance[g]) || crease(u, v)) continue;
    const Point_3<double>& p = m.vertices[m.faces[f][face.second]];
    const Point_3<double>& o = m.vertices[m.faces[g][twin->second.second]];
    if (clearly_inside_circumcircle(m.vertices[u], m.vertices[v], p, o)) ++q.non_delaunay_edges;
  }
  for (const Triangle& t : m.faces)
    for (int k = 0; k < 3; ++k) {
      const V3 a = sub(m.vertices[t[(k + 1) % 3]], m.vertices[t[k]]), b = sub(m.vertices[t[(k + 2) % 3]], m.vertices[t[k]]);
      const double angle = static_cast<double>(std::atan2(std::sqrt(dot(cross(a, b), cross(a, b))), dot(a, b)));
      q.smallest_angle_deg = std::min(q.smallest_angle_deg, angle * 180 / 3.14159265358979323846);
    }
  return q;
}

Boolean_options retriangulation(bool delaunay) {
  Boolean_options o;
  o.delaunay_retriangulation = delaunay;
  return o;
}

struct Case {
  const char* name;
  Mesh_double a, b;
  Op op;
};

// The case (a level-4 icosphere minus a square prism through it) and
// the first step of each chain family.
std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back({"sphere_minus_prism", icosphere(4), rigidly_moved(box(-0.15, -0.15, -2, 0.3, 0.3, 4), 0.7, 0.4, {0, 0, 0}),
               Op::difference});
  for (const Chain_family f : {Chain_family::drilled_sphere, Chain_family::fused_spheres, Chain_family::slab_and_boxes}) {
    const Boolean_chain chain = make_chain(f, 1);
    c.push_back({to_string(f).data(), chain.start, chain.steps[0].second, chain.steps[0].first});
  }
  return c;
}

TEST(RetriangulationQuality, EverySplitFaceIsConstrainedDelaunay) {
  std::size_t old_violations = 0;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const auto delaunay = boolean(c.a, c.b, c.op, Filtered_exact_kernel{}, retriangulation(true));
    const auto insertion = boolean(c.a, c.b, c.op, Filtered_exact_kernel{}, retriangulation(false));
    ASSERT_TRUE(delaunay.ok()) << delaunay.failure;
    ASSERT_TRUE(insertion.ok()) << insertion.failure;
    EXPECT_TRUE(delaunay.validation.is_valid_solid()) << delaunay.validation.summary();
    // The repair may flip an edge under a sliver; none was needed here.
    EXPECT_EQ(delaunay.rounding.flips, 0u);
    EXPECT_EQ(quality_of(delaunay).non_delaunay_edges, 0u);
    old_violations += quality_of(insertion).non_delaunay_edges;
    // The same points: the flips change edges, not the vertex count.
    EXPECT_EQ(delaunay.mesh.vertices.size(), insertion.mesh.vertices.size());
  }
  // The insertion order's triangulation is not Delaunay on these cases.
  EXPECT_GT(old_violations, 0u);
}

TEST(RetriangulationQuality, TheSmallestAngleOfTheSphereMinusPrismGrows) {
  const Case c = cases().front();
  const auto delaunay = boolean(c.a, c.b, c.op, Filtered_exact_kernel{}, retriangulation(true));
  const auto insertion = boolean(c.a, c.b, c.op, Filtered_exact_kernel{}, retriangulation(false));
  ASSERT_TRUE(delaunay.ok() && insertion.ok());
  const Quality d = quality_of(delaunay), i = quality_of(insertion);
  // Measured: 0.052 degrees against 0.0080.
  EXPECT_GT(d.smallest_angle_deg, 2 * i.smallest_angle_deg) << d.smallest_angle_deg << " vs " << i.smallest_angle_deg;
  // Needles rounding turned over: found and repaired only in the old triangulation.
  EXPECT_EQ(delaunay.rounding.defects_before, 0u);
}

TEST(RetriangulationQuality, TheFlipsDoNotDependOnTheKernel) {
  // Under the exact kernel (rationals) the same flips are chosen: the choice
  // reads the points' approximations, which both kernels give to within ulps.
  const Case c = cases().front();
  const auto filtered = boolean(c.a, c.b, c.op, Filtered_exact_kernel{});
  const auto exact = boolean(c.a, c.b, c.op, Exact_kernel{}, [] {
    Boolean_options o;
    o.use_double_point_kernel = false;
    return o;
  }());
  ASSERT_TRUE(filtered.ok() && exact.ok()) << filtered.failure << exact.failure;
  EXPECT_EQ(filtered.mesh.faces.size(), exact.mesh.faces.size());
  EXPECT_EQ(quality_of(filtered).non_delaunay_edges, 0u);
}

// A face with many points: the cube's top face (two triangles) holds the
// whole circle where the sphere crosses it, dozens of points inside each
// triangle, past the 32 the triangulator finds by a scan
// (internal::Few_keys_map): its lookups then go through the hash map.
TEST(RetriangulationQuality, AFaceCrossedByManyCurvesIsConstrainedDelaunayToo) {
  const Mesh_double a = cube(0, 0, 0, 2), b = icosphere(4, {1, 1, 1.7}, 0.9);
  std::array<double, 2> volumes{};
  for (const Op op : {Op::union_of, Op::intersection}) {
    SCOPED_TRACE(to_string(op));
    const auto r = boolean(a, b, op, Filtered_exact_kernel{});
    ASSERT_TRUE(r.ok()) << r.failure;
    EXPECT_TRUE(r.validation.is_valid_solid()) << r.validation.summary();
    EXPECT_EQ(quality_of(r).non_delaunay_edges, 0u);
    std::map<Index, std::size_t> inside;  // the points inside each face of the cube
    for (const auto& at : r.vertex_locations)
      if (at[0].kind == Surface_location::Kind::face) ++inside[at[0].face];
    std::size_t most = 0;
    for (const auto& [face, n] : inside) most = std::max(most, n);
    EXPECT_GT(most, 64u) << "points inside one face of the cube";
    volumes[op == Op::union_of ? 0 : 1] = volume(r.mesh);
  }
  const double sum = volume(a) + volume(b);
  EXPECT_NEAR(volumes[0] + volumes[1], sum, 1e-12 * sum);
}

TEST(FewKeysMap, FindsEveryKeyBeforeAndAfterMovingToTheHashMap) {
  internal::Few_keys_map<Index, int> map;
  for (int round = 0; round < 2; ++round) {  // the second after clear()
    for (Index k = 0; k < 100; ++k) {
      EXPECT_EQ(map.find(3 * k + 1), nullptr);
      map.insert(3 * k + 1, static_cast<int>(k));
      for (Index j = 0; j <= k; j += 7) {
        const int* v = map.find(3 * j + 1);
        ASSERT_NE(v, nullptr) << "key " << 3 * j + 1 << " after " << k + 1 << " keys";
        EXPECT_EQ(*v, static_cast<int>(j));
      }
      EXPECT_EQ(map.find(3 * k + 2), nullptr);
    }
    map.clear();
    EXPECT_EQ(map.find(1), nullptr);
  }
}

}  // namespace
}  // namespace relgeo::test
