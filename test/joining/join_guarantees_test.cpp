// The Whitney joiner on the library-made inputs under every certified
// kernel: the thesis' guarantees (|a| <= max|e| on dR, slope <= L, no flipped
// triangle), a conforming result with watertight seams; the error after is
// never above the boundary's and the joint vertices are shared.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "joining/join_fixtures.h"
#include "relgeo/joining/joiner.h"
#include "relgeo/kernel.h"
#include "relgeo/kernel/cgal_kernel.h"
#include "relgeo/mesh/mesh_topology.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

template <class K>
class JoinGuarantees : public ::testing::Test {};
using Certified_kernels = ::testing::Types<Failsafe_kernel<double>, Interval_kernel, Filtered_exact_kernel, Exact_kernel,
                                           Cgal_kernel<CGAL::Epick>>;
TYPED_TEST_SUITE(JoinGuarantees, Certified_kernels);

TYPED_TEST(JoinGuarantees, EveryLibraryCase) {
  using K = TypeParam;
  for (const Joining_case& c : joining_cases()) {
    const Join_result r = join_meshes<K>(c.model, c.meshes);
    expect_whitney_guarantees(r.report, c.name);
    EXPECT_EQ(r.face_of_triangle.size(), r.mesh.faces.size());
    EXPECT_EQ(r.report.faces.size(), c.model.faces.size());
  }
}

TEST(JoinResult, SameMeshUnderEveryExactKernelAndCaseCountsAsDeclared) {
  for (const Joining_case& c : joining_cases()) {
    const Join_result a = join_meshes<Filtered_exact_kernel>(c.model, c.meshes);
    const Join_result b = join_meshes<Exact_kernel>(c.model, c.meshes);
    EXPECT_EQ(a.mesh, b.mesh) << c.name;  // exact predicates decide alike
    const bool curves = c.name.find("case 1") != std::string::npos || c.name.find("all curves") != std::string::npos;
    if (curves) EXPECT_GT(a.report.edges_with_curve, 0u) << c.name;
    else EXPECT_EQ(a.report.edges_with_curve, 0u) << c.name;
    const std::size_t shared = c.name.find("three") != std::string::npos ? 3u : 1u;
    if (c.name.find("all curves") != std::string::npos) EXPECT_EQ(a.report.edges_with_curve, 7u) << c.name;
    else EXPECT_EQ(a.report.edges_with_curve + a.report.edges_with_median, shared) << c.name;
  }
}

TEST(JoinResult, SeamsAreWatertightAndBoundaryOnlyOnFreeEdges) {
  const Joining_case c = make_joining_case("three faces, case 2", three_face_model(false));
  const Join_result r = join_meshes(c.model, c.meshes);
  const Mesh_topology t = Mesh_topology::build(r.mesh);  // throws if not manifold and consistently oriented
  // The boundary of the result is one cycle: the outer square (the three
  // faces' free edges), no hole along the seams.
  std::size_t boundary_vertices = 0;
  for (Index v = 0; v < r.mesh.vertices.size(); ++v) boundary_vertices += t.is_boundary_vertex(v);
  std::size_t boundary_edges = 0;
  for (Index e = 0; e < t.number_of_edges(); ++e) boundary_edges += t.is_boundary_edge(e);
  EXPECT_EQ(boundary_edges, boundary_vertices);  // a single cycle: as many edges as vertices
  EXPECT_EQ(boundary_edges, r.report.boundary_edges);
  // Every triangle of one face shares its seam vertices with a neighbour:
  // vertices used by two faces exist (the shared joints).
  std::vector<std::set<Index>> faces_of(r.mesh.vertices.size());
  for (std::size_t i = 0; i < r.mesh.faces.size(); ++i)
    for (Index v : r.mesh.faces[i]) faces_of[v].insert(r.face_of_triangle[i]);
  std::size_t shared = 0, junction = 0;
  for (const auto& s : faces_of) shared += s.size() >= 2, junction += s.size() == 3;
  EXPECT_GT(shared, 20u);
  EXPECT_EQ(junction, 1u);  // the Y junction: one vertex of all three faces
}

TEST(JoinResult, WithEveryEdgeCurveTheNoiseIsSmoothedAway) {
  // Every boundary height is the surfaces' own discrepancy (0 on face 0, the
  // 2e-3 gap on face 1 along the seam): L is small, and the result's
  // normal-vector error with it, whatever the input's noise (thesis Sec. 4.5:
  // "the procedure smooths the input mesh patches").
  const Joining_case c = make_joining_case("two faces, all curves", two_face_model(true, 2e-3, true));
  const Join_result r = join_meshes(c.model, c.meshes);
  ASSERT_EQ(r.report.faces.size(), 2u);
  for (const Join_face_report& f : r.report.faces) {
    EXPECT_LT(f.after.normal_vector, f.before.normal_vector / 4);
    EXPECT_LE(f.after.normal_vector, f.lipschitz_constant * (1 + 1e-9));
  }
  // Heights: at most the gap (the corners shared with face 1's edges are the
  // means of the edges' ends), and below the input's noise.
  for (const Join_face_report& f : r.report.faces) {
    EXPECT_LE(f.after.absolute, 2e-3);
    EXPECT_LT(f.after.absolute, f.before.absolute);
  }
}

TEST(JoinResult, ErrorsAfterAreBoundedByTheBoundaryData) {
  // Case 1 with the curve on face 0's surface: face 0's boundary heights
  // along the seam are 0, its free edges carry the mesh's own noise.
  const Joining_case c = make_joining_case("two faces, case 1", two_face_model(true), {.normal_noise = 1e-3});
  const Join_result r = join_meshes(c.model, c.meshes);
  for (const Join_face_report& f : r.report.faces) {
    EXPECT_LE(f.after.absolute, f.boundary_max_abs_height);
    EXPECT_LE(f.boundary_max_abs_height, 1e-3 * (1 + 1e-12) + 2e-3);  // noise, plus the surfaces' gap on face 1
    // The interior's noise is gone: the normal-vector error never exceeds
    // the input's or L.
    EXPECT_LE(f.after.normal_vector, std::max(f.before.normal_vector, f.lipschitz_constant) * (1 + 1e-9));
  }
  // Without noise and with the curve on both surfaces (gap 0), the result
  // lies on the surfaces up to the chordal error of the given curve (a
  // polyline of 400 points: a few 1e-7).
  const Joining_case clean = make_joining_case("two faces, exact", two_face_model(true, 0.0), {.normal_noise = 0, .tangential_noise = 0});
  const Join_result q = join_meshes(clean.model, clean.meshes);
  for (const Join_face_report& f : q.report.faces) {
    EXPECT_LT(f.boundary_max_abs_height, 1e-6);
    EXPECT_LE(f.after_reprojected.absolute, f.boundary_max_abs_height + 1e-12);
  }
}

}  // namespace
