// Regression tests of what the fuzz harnesses found that is not a file of
// the bad-input catalogue (those are in bad_input_catalogue_test.cpp): each
// test holds the input the harness decoded (doc/reliability.md, "Findings").
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "relgeo/intersection/triangle_intersection.h"
#include "relgeo/kernel.h"
#include "relgeo/subdivision.h"
#include "subdivision/loop_stencil_check.h"

namespace relgeo::test {
namespace {

using Mesh_q = Triangle_mesh<Point_3<mpq_class>>;

/// fuzz/loop_subdivision, fuzz/corpus/loop_subdivision/regression_blz_corner_without_creases:
/// a bipyramid over a pentagon whose apex 5 is tagged corner, with no crease
/// edge. With Biermann-Levin-Zorin rules the fast refinement read the sector
/// sizes of the corner from a buffer it had not filled (filled only when
/// some edge is a crease): undefined behaviour (UBSan: offset on a null
/// pointer), or stale sizes from an earlier call; the fused limit mesh summed
/// the corner's neighbours' rings with the standard rule. Both must equal
/// the stencils of loop_masks.h exactly.
Mesh_q pentagonal_bipyramid_with_a_corner() {
  Mesh_q m;
  const double c[5][2] = {{1, 0},
                          {0.30901699437494745, 0.95105651629515353},
                          {-0.80901699437494734, 0.58778525229247325},
                          {-0.80901699437494756, -0.58778525229247303},
                          {0.30901699437494723, -0.95105651629515364}};
  for (const auto& p : c) m.vertices.push_back({mpq_class(p[0]), mpq_class(p[1]), mpq_class(0)});
  m.vertices.push_back({mpq_class(0), mpq_class(0), mpq_class(1)});
  m.vertices.push_back({mpq_class(0), mpq_class(0), mpq_class(-1)});
  for (Index i = 0; i < 5; ++i) {
    m.faces.push_back({i, (i + 1) % 5, 5});
    m.faces.push_back({(i + 1) % 5, i, 6});
  }
  m.tags.add_corner(5);
  return m;
}

TEST(FuzzRegression, BlzCornerWithoutCreasesRefinesByTheStencils) {
  const Mesh_q m = pentagonal_bipyramid_with_a_corner();
  for (const Loop_options o : {Loop_options{.crease_rules = Loop_crease_rules::biermann_levin_zorin}, Loop_options{}}) {
    Loop_subdivider<Exact_kernel> s(o);
    // A first call on a creased mesh leaves sector sizes in the buffers.
    Mesh_q creased = m;
    creased.tags.add_crease(0, 5);
    creased.tags.add_crease(5, 2);
    (void)s.refine(creased, 1);
    const Mesh_q r = s.refine(m, 1);
    relgeo_test::expect_refinement_is_the_stencils(s, m, r);
    // The fused limit mesh equals refinement followed by the limit stencils.
    const Mesh_q limit = s.limit_mesh(m, 1);
    const std::vector<Point_3<mpq_class>> expected = s.limit_positions(r);
    ASSERT_EQ(limit.vertices.size(), expected.size());
    for (std::size_t v = 0; v < expected.size(); ++v) EXPECT_EQ(limit.vertices[v], expected[v]) << v;
  }
}

/// fuzz/implicit_point, fuzz/pending/implicit_point/regression_lpi_approximation_scale
/// (fuzz/corpus/implicit_point/regression_lpi_approximation_scale*):
/// when the filter cannot certify W, Filtered_exact_kernel approximates an
/// implicit point from scaled integers; the scale does not cancel in X / W
/// (degrees 4 and 3), so the point came out multiplied by it with a stated
/// error of 0: (2^112, 0, 0) for (1, 0, 0) below.
/// The fix: internal::Scaled_integers::unscale in the exact fallback.

TEST(FuzzRegression, FilteredExactApproximationOfAnUncertainLpiIsTheExactPoint) {
  const Filtered_exact_kernel k;
  const auto p = k.construct_point_3_object();
  const auto make = k.construct_implicit_point_3_object();
  const auto approximate = k.approximate_point_3_object();
  const double a = -0x1.090909090909p-758;  // the fuzzer's: the line through p0 meets the plane at p4 = p0
  struct Case {
    std::array<std::array<double, 3>, 5> v;
    std::array<double, 3> exact;
  };
  const Case cases[] = {
      {{{{0, 0, 0x1p-60}, {1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {1, 0, 0}},  // W = -2^-60: filter uncertain
      {{{{a, a, a}, {0, 0, -1}, {0, 0x1.cfbffffp-1010, 0x1.ffp-1020}, {-0x1.fffp+960, 0, 0}, {a, a, a}}}, {a, a, a}}};
  for (const Case& c : cases) {
    const auto e = [&](int i) { return p(c.v[i][0], c.v[i][1], c.v[i][2]); };
    const auto x = make(e(0), e(1), e(2), e(3), e(4));
    ASSERT_TRUE(x.has_value());
    const Approximate_point_3 r = approximate(*x);
    EXPECT_LE(std::abs(r.point.x - c.exact[0]), r.error);
    EXPECT_LE(std::abs(r.point.y - c.exact[1]), r.error);
    EXPECT_LE(std::abs(r.point.z - c.exact[2]), r.error);
    EXPECT_EQ(r.point.x, c.exact[0]);  // the exact point is a double here
  }
}

/// fuzz/loop_subdivision, fuzz/corpus/loop_subdivision/regression_limit_positions_pillow:
/// two faces on the same three vertices with opposite orientations (a closed
/// "pillow", each vertex of valence 2). refine and limit_mesh with levels > 0
/// refused it (faces sharing two edges), but limit_positions, and so
/// limit_mesh at level 0, returned positions under every kernel. All three
/// must refuse it alike.
TEST(FuzzRegression, LimitPositionsRefuseFacesSharingTwoEdges) {
  Triangle_mesh<Point_3<double>> pillow;
  pillow.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  pillow.faces = {{0, 1, 3}, {1, 0, 3}};
  Loop_subdivider<Naive_kernel<double>> loop;
  EXPECT_THROW((void)loop.refine(pillow, 1), Invalid_input);
  EXPECT_THROW((void)loop.limit_positions(pillow), Invalid_input);
  EXPECT_THROW((void)loop.limit_mesh(pillow, 0), Invalid_input);
  EXPECT_THROW((void)loop.limit_mesh(pillow, 2), Invalid_input);
}

/// fuzz/triangle_intersection, fuzz/corpus/triangle_intersection/regression_off_plane_overflow:
/// two coplanar triangles sharing the edge from 0 to a point with z = DBL_MAX.
/// The coplanar path builds edge crossings as LPI points against a plane
/// through a point moved off the common plane; the move (2z where z + 1 == z)
/// overflowed to infinity, the point could not be built, and the certified
/// kernels answered `undecided`. Now 2z is replaced by z / 2 where it would
/// overflow, and they decide.
TEST(FuzzRegression, CoplanarTrianglesAtTheLargestDoubleAreDecided) {
  const std::array<std::array<double, 3>, 6> v{{{0x1.0004p-383, 0x1p-383, 0x1.fffffffffffffp+1023},
                                                {0x0.000000000e2p-1022, 0, 0},
                                                {0, 0, 0},
                                                {0x0.001000042p-1022, 0, 0},
                                                {0, 0, 0},
                                                {0x1.0004p-383, 0x1p-383, 0x1.fffffffffffffp+1023}}};
  const auto run = [&](const auto& k) {
    const auto p = k.construct_point_3_object();
    const auto at = [&](int i) { return p(v[i][0], v[i][1], v[i][2]); };
    const auto r = intersect_triangles(std::array{at(0), at(1), at(2)}, std::array{at(3), at(4), at(5)}, k);
    EXPECT_EQ(r.kind, Triangle_intersection_kind::coplanar_overlap) << to_string(r.kind);
    EXPECT_TRUE(r.perturbations.empty());
  };
  run(Filtered_exact_kernel{});
  run(Exact_kernel{});
}

/// fuzz/triangle_intersection, fuzz/corpus/triangle_intersection/regression_naive_polygon_overflow:
/// nearly coplanar triangles under Naive_kernel<double>. Its inconsistent
/// in-plane signs made the clipped polygon alternate sides and outgrow its
/// fixed capacity (std::bad_alloc from boost's static_vector). A polygon
/// that outgrows what two triangles' overlap can have is now `undecided`.
TEST(FuzzRegression, NaiveKernelTriangleIntersectionDoesNotOverflowItsPolygon) {
  const std::array<std::array<double, 3>, 6> v{{{-0x1.f000000000004p+3, -0x1.f000000000004p+3, -0x1.f000000000001p+3},
                                                {-0x1.4803000000001p+11, -0x1.f000000000004p+3, -0x1.f000000000167p+3},
                                                {0x1.7511540000001p+15, -0x1.f000000000004p+3, -0x1.effffffffe666p+3},
                                                {0x1.97ffffffffffcp+2, -0x1.f000000000004p+3, -0x1.efffffffffffep+3},
                                                {0x1.6ac0000000001p+7, -0x1.f000000000004p+3, -0x1.effffffffffe6p+3},
                                                {-0x1.1344000000001p+8, -0x1.f000000000004p+3, -0x1.f000000000024p+3}}};
  const Naive_kernel<double> k;
  const auto p = k.construct_point_3_object();
  const auto at = [&](int i) { return p(v[i][0], v[i][1], v[i][2]); };
  EXPECT_NO_THROW((void)intersect_triangles(std::array{at(0), at(1), at(2)}, std::array{at(3), at(4), at(5)}, k));
}

/// fuzz/loop_limit, fuzz/corpus/loop_limit/regression_exact_bounds_beyond_double:
/// a tetrahedron flattened into the plane z = 0, its fourth vertex at
/// (DBL_MAX, DBL_MAX, 0). Under Exact_kernel the squared normal of a face
/// through that vertex is a rational far beyond double's range, so the
/// upper bound of |n| is +inf; the limit surface lies in the plane, the
/// heights are 0, and their distances t |n| came out as 0 * inf = NaN. A
/// zero height is now at distance zero.
TEST(FuzzRegression, ExactBoundsOfFacesBeyondDoublesRangeAreOrdered) {
  const double big = std::numeric_limits<double>::max();
  const Exact_kernel k;
  const auto p = k.construct_point_3_object();
  Triangle_mesh<Exact_kernel::Point_3> flat;
  flat.vertices = {p(0, 0, 0), p(1, 0, 0), p(0, 1, 0), p(big, big, 0)};
  flat.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const Loop_bound_options shallow{.irregular_depth = 2, .regular_depth = 1, .universal_depth = 2};
  const auto r = Loop_error_bounds<Exact_kernel>(Loop_options{}, shallow).compute(flat, 0);
  bool beyond_double = false;
  for (Index g = 0; g < r.limit_mesh.faces.size(); ++g) {
    ASSERT_FALSE(r.degenerate[g]);
    beyond_double = beyond_double || std::isinf(r.normal_length[g]);
    for (const auto* method : {&r.basis_range, &r.tangent_plane, &r.direct}) {
      if (method->empty()) continue;
      const auto& b = (*method)[g];
      EXPECT_EQ(b.lower, 0) << "face " << g;
      EXPECT_EQ(b.upper, 0) << "face " << g;
      EXPECT_LE(b.lower_distance, 0) << "face " << g;
      EXPECT_GE(b.upper_distance, 0) << "face " << g;
    }
  }
  EXPECT_TRUE(beyond_double) << "no |n| beyond double's range: the case is not the hard one";
}

}  // namespace
}  // namespace relgeo::test
