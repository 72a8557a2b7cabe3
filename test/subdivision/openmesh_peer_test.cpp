// relgeo's Loop refinement against OpenMesh's Subdivider::Uniform::LoopT:
// same connectivity, positions within rounding (OpenMesh computes
// alpha(n) = (40 - (3 + 2 cos(2 pi / n))^2) / 64 in double; at valence 6 its
// weights are exactly 5/8 and 1/16).
#include <gtest/gtest.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <cmath>

#include "mesh/mesh_fixtures.h"
#include "relgeo/kernel.h"
#include "relgeo/subdivision.h"
#include "subdivision/peer_matching.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

struct Traits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using Om = OpenMesh::TriMesh_ArrayKernelT<Traits>;

Peer_view view(const Om& om) {
  Peer_view v;
  v.number_of_vertices = om.n_vertices();
  v.neighbours = [&om](std::size_t x) {
    std::vector<std::size_t> r;
    for (auto y : om.vv_range(om.vertex_handle(static_cast<unsigned>(x)))) r.push_back(y.idx());
    return r;
  };
  for (auto f : om.faces()) {
    std::array<std::size_t, 3> t{};
    int k = 0;
    for (auto x : om.fv_range(f)) t[k++] = x.idx();
    v.faces.push_back(t);
  }
  return v;
}

double compare_with_openmesh(const Mesh_d& m, int levels) {
  Om om;
  for (const auto& p : m.vertices) om.add_vertex(Om::Point(p.x, p.y, p.z));
  for (const Triangle& f : m.faces)
    om.add_face(om.vertex_handle(f[0]), om.vertex_handle(f[1]), om.vertex_handle(f[2]));
  Mesh_d cur = m;
  std::vector<Index> map(m.vertices.size());
  for (Index i = 0; i < map.size(); ++i) map[i] = i;
  double worst = 0;
  OpenMesh::Subdivider::Uniform::LoopT<Om, double> loop;
  for (int l = 0; l < levels; ++l) {
    const Mesh_topology t = Mesh_topology::build(cur);
    cur = loop_subdivide(cur, 1);
    loop.attach(om);
    loop(1);
    loop.detach();
    const Peer_view pv = view(om);
    map = match_step(map, t, pv);
    if (map.empty()) return INFINITY;
    expect_same_faces(map, pv, cur.faces);
    for (std::size_t x = 0; x < map.size(); ++x) {
      const auto& q = om.point(om.vertex_handle(static_cast<unsigned>(x)));
      const auto& p = cur.vertices[map[x]];
      worst = std::max({worst, std::abs(p.x - q[0]), std::abs(p.y - q[1]), std::abs(p.z - q[2])});
    }
  }
  return worst;
}

TEST(OpenMeshPeer, SmoothClosedMeshesMatchWithinRounding) {
  EXPECT_LT(compare_with_openmesh(jitter(icosphere(2), 0.05), 3), 1e-14);
  EXPECT_LT(compare_with_openmesh(torus(9, 7), 3), 1e-14);
  for (int n : {3, 4, 7, 11}) EXPECT_LT(compare_with_openmesh(bipyramid(n), 2), 1e-14) << n;
}

TEST(OpenMeshPeer, OpenMeshesUseTheSameBoundaryRules) {
  EXPECT_LT(compare_with_openmesh(open_grid(4), 3), 1e-14);
}

}  // namespace
