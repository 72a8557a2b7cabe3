// relgeo's Loop refinement against CGAL::Subdivision_method_3::Loop_subdivision:
// same connectivity, positions within rounding in double, and identical
// positions under exact rationals where the weights coincide (CGAL's
// Loop_mask_3 computes beta(n) from std::cos in double except at valence 6).
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <cmath>
#include <filesystem>

#include "mesh/mesh_fixtures.h"
#include "relgeo/kernel.h"
#include "relgeo/mesh/cgal_conversion.h"
#include "relgeo/mesh/mesh_io.h"
#include "relgeo/subdivision.h"
#include "subdivision/peer_matching.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

template <class SM>
Peer_view view(const SM& sm) {
  Peer_view v;
  v.number_of_vertices = sm.number_of_vertices();
  v.neighbours = [&sm](std::size_t x) {
    std::vector<std::size_t> r;
    for (auto h : CGAL::halfedges_around_target(sm.halfedge(typename SM::Vertex_index(x)), sm))
      r.push_back(sm.source(h).idx());
    return r;
  };
  for (auto f : sm.faces()) {
    std::array<std::size_t, 3> t{};
    int k = 0;
    for (auto x : CGAL::vertices_around_face(sm.halfedge(f), sm)) t[k++] = x.idx();
    v.faces.push_back(t);
  }
  return v;
}

// Refines both `levels` times, one level at a time; returns the largest
// coordinate difference (relative to the bounding box) and checks the
// connectivity at each level. `same` compares one coordinate pair.
template <class Kernel, class CgalK, class Diff>
double compare_with_cgal(const Triangle_mesh<typename Kernel::Point_3>& m, int levels, Diff diff) {
  using SM = CGAL::Surface_mesh<typename CgalK::Point_3>;
  SM sm;
  using CFT = typename CgalK::FT;
  const auto to_cgal = [](const auto& c) {
    if constexpr (std::is_same_v<std::remove_cvref_t<decltype(c)>, mpq_class>) return CFT(c.get_mpq_t());
    else return CFT(c);
  };
  for (const auto& p : m.vertices) sm.add_vertex(typename CgalK::Point_3(to_cgal(p.x), to_cgal(p.y), to_cgal(p.z)));
  for (const Triangle& f : m.faces)
    sm.add_face(typename SM::Vertex_index(f[0]), typename SM::Vertex_index(f[1]), typename SM::Vertex_index(f[2]));
  Loop_subdivider<Kernel> ours;
  auto cur = m;
  std::vector<Index> map(m.vertices.size());
  for (Index i = 0; i < map.size(); ++i) map[i] = i;
  double worst = 0;
  for (int l = 0; l < levels; ++l) {
    const Mesh_topology t = Mesh_topology::build(cur);
    cur = ours.refine(cur, 1);
    CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(1));
    const Peer_view pv = view(sm);
    map = match_step(map, t, pv);
    if (map.empty()) return INFINITY;
    expect_same_faces(map, pv, cur.faces);
    for (std::size_t x = 0; x < map.size(); ++x) {
      const auto& q = sm.point(typename SM::Vertex_index(x));
      const auto& p = cur.vertices[map[x]];
      worst = std::max({worst, diff(p.x, q.x()), diff(p.y, q.y()), diff(p.z, q.z())});
    }
  }
  return worst;
}

const auto abs_diff = [](double a, double b) { return std::abs(a - b); };

TEST(CgalPeer, SmoothClosedMeshesMatchWithinRounding) {
  using SC = CGAL::Simple_cartesian<double>;
  EXPECT_LT((compare_with_cgal<Naive_kernel<double>, SC>(jitter(icosphere(2), 0.05), 3, abs_diff)), 1e-14);
  EXPECT_LT((compare_with_cgal<Naive_kernel<double>, SC>(torus(9, 7), 3, abs_diff)), 1e-14);
  for (int n : {3, 5, 8, 12})
    EXPECT_LT((compare_with_cgal<Naive_kernel<double>, SC>(bipyramid(n), 2, abs_diff)), 1e-14) << n;
  EXPECT_LT((compare_with_cgal<Failsafe_kernel<double>, SC>(octahedron(), 3, abs_diff)), 1e-14);
}

TEST(CgalPeer, OpenMeshesMatchCgalsBorderRules) {
  using SC = CGAL::Simple_cartesian<double>;
  EXPECT_LT((compare_with_cgal<Naive_kernel<double>, SC>(open_grid(4), 3, abs_diff)), 1e-14);
  EXPECT_LT((compare_with_cgal<Naive_kernel<double>, SC>(relgeo_test::jitter(open_grid(3), 0.2), 2, abs_diff)),
            1e-14);
}

TEST(CgalPeer, ExactlyEqualUnderRationalsWhereTheWeightsCoincide) {
  // Valence 6 everywhere: CGAL's mask uses (10 S + R) / 16 and the exact edge
  // rule, relgeo 5/8 and 1/16: the same rationals.
  using SQ = CGAL::Simple_cartesian<CGAL::Gmpq>;
  const auto exact_diff = [](const mpq_class& a, const CGAL::Gmpq& b) {
    return a == mpq_class(b.mpq()) ? 0.0 : 1.0;
  };
  const auto m = convert<mpq_class>(dyadic_torus(6, 5));
  Triangle_mesh<Point_3<mpq_class>> mq = m;
  EXPECT_EQ((compare_with_cgal<Exact_kernel, SQ>(mq, 2, exact_diff)), 0.0);
  // and where they do not (valence 5): CGAL's double-rounded beta differs
  const auto ico = convert<mpq_class>(icosahedron());
  double differs = 0;
  {
    using SM = CGAL::Surface_mesh<SQ::Point_3>;
    SM sm;
    for (const auto& p : ico.vertices)
      sm.add_vertex(SQ::Point_3(CGAL::Gmpq(p.x.get_mpq_t()), CGAL::Gmpq(p.y.get_mpq_t()), CGAL::Gmpq(p.z.get_mpq_t())));
    for (const Triangle& f : ico.faces)
      sm.add_face(SM::Vertex_index(f[0]), SM::Vertex_index(f[1]), SM::Vertex_index(f[2]));
    CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(1));
    const auto r = loop_subdivide(ico, 1);
    for (Index v = 0; v < 12; ++v) differs += r.vertices[v].x != mpq_class(sm.point(SM::Vertex_index(v)).x().mpq());
  }
  EXPECT_GT(differs, 0);  // relgeo's exact beta(5) is not CGAL's rounded one
}

TEST(CgalPeer, CgalDataMeshes) {
  const std::string dir = RELGEO_CGAL_MESH_DIR;
  if (!std::filesystem::exists(dir + "/elephant.off")) GTEST_SKIP() << "CGAL data set not installed (libcgal-demo)";
  using SC = CGAL::Simple_cartesian<double>;
  for (const char* name : {"elephant.off", "eight.off", "knot1.off"}) {
    const auto m = read_mesh(dir + "/" + name);
    EXPECT_LT((compare_with_cgal<Naive_kernel<double>, SC>(m, 2, abs_diff)), 1e-12) << name;
  }
}

}  // namespace
