// validate_solid and find_self_intersections on constructed meshes, one test
// per defect (each located), under Filtered_exact_kernel, Exact_kernel and
// Failsafe_kernel (undecided allowed, wrong never); the exact volume against
// an independent rational sum; the face-pair predicates against
// intersect_triangles (a different algorithm) on grid configurations full of
// degeneracies.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <set>

#include "mesh/solid_fixtures.h"
#include "relgeo/core/dyadic.h"
#include "relgeo/intersection/triangle_intersection.h"
#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/failsafe_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/interval_kernel.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/solid_validation.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

using Failsafe = Failsafe_kernel<double>;

bool lists(const Solid_check& c, Mesh_defect d, Index a, Index b = invalid_index) {
  return std::find(c.where.begin(), c.where.end(), Mesh_issue{d, {a, b}}) != c.where.end();
}

// ---- valid solids ------------------------------------------------------------

TEST(SolidValidation, ValidSolidsPassEveryCheckUnderEveryCertifiedKernel) {
  const Mesh_d meshes[] = {cube(), tetrahedron(), icosphere(2), cube_sphere(6), torus(12, 8), creased_box()};
  for (const Mesh_d& m : meshes) {
    const Solid_report f = validate_solid(m);
    EXPECT_TRUE(f.is_valid_solid()) << f.summary();
    EXPECT_EQ(f.kernel, "filtered");
    EXPECT_TRUE(f.volume.computed && f.volume.exact);
    EXPECT_GT(f.volume.value, 0);
    EXPECT_EQ(f.components, 1u);
    const Solid_report e = validate_solid<Exact_kernel>(m);
    EXPECT_TRUE(e.is_valid_solid()) << e.summary();
    EXPECT_EQ(e.volume.exact_value, f.volume.exact_value);
    // Fail-safe: never a failure on a valid solid, at worst undecided.
    const Solid_report s = validate_solid<Failsafe>(m);
    s.for_each_check([&](std::string_view name, const Solid_check& c) {
      EXPECT_NE(c.status, Check_status::fail) << name;
    });
  }
}

TEST(SolidValidation, CubeVolumeTopologyAndGenusAreExact) {
  const Solid_report r = validate_solid(cube(2));
  EXPECT_EQ(r.volume.exact_value, "8");
  EXPECT_EQ(r.volume.value, 8.0);
  EXPECT_EQ(r.volume.lower, 8.0);
  EXPECT_EQ(r.volume.upper, 8.0);
  EXPECT_EQ(r.euler_characteristic, 2);
  EXPECT_EQ(r.genus, 0);
  EXPECT_EQ(r.edges, 18u);
  ASSERT_EQ(r.component_list.size(), 1u);
  EXPECT_EQ(r.component_list[0].winding, 0);
  // The fail-safe kernel decides the cube: its degeneracies are exact (axis-aligned).
  EXPECT_TRUE(validate_solid<Failsafe>(cube(2)).is_valid_solid());
  // Two tori: genus 2, Euler characteristic 0, two components.
  const Solid_report t = validate_solid(disjoint_union(torus(10, 6), translated(torus(10, 6), 7, 0, 0)));
  EXPECT_TRUE(t.is_valid_solid()) << t.summary();
  EXPECT_EQ(t.components, 2u);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.genus, 2);
}

TEST(SolidValidation, VolumeEqualsAnIndependentRationalSum) {
  for (const Mesh_d& m : {jitter(cube_sphere(5), 0.01), jitter(torus(9, 7), 0.003), jitter(icosphere(1), 1e-9)}) {
    mpq_class six_v = 0;
    for (const Triangle& t : m.faces) {
      const auto q = [&](Index v) {
        return std::array<mpq_class, 3>{exact_rational(m.vertices[v].x), exact_rational(m.vertices[v].y),
                                        exact_rational(m.vertices[v].z)};
      };
      const auto a = q(t[0]), b = q(t[1]), c = q(t[2]);
      six_v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
               a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    const mpq_class v = six_v / 6;
    const Solid_report r = validate_solid(m);
    EXPECT_EQ(mpq_class(r.volume.exact_value), v);
    EXPECT_EQ(r.volume.value, round_rational<double>(v));
    EXPECT_LE(exact_rational(r.volume.lower), v);
    EXPECT_GE(exact_rational(r.volume.upper), v);
    // Rational coordinates (Exact_kernel's own points): the same value.
    EXPECT_EQ(mpq_class(validate_solid(convert<mpq_class>(m)).volume.exact_value), v);
  }
}

// The integer products of the fast path against GMP, face by face and per
// component, on soups whose coordinates span the whole fast range (2^-200 to
// 2^200, every mantissa width, both signs, zeros) with some outside it (the
// GMP path in the same component), and sums whose limbs carry and borrow.
TEST(SolidValidation, SignedVolumesEqualRationalSumsOverTheWholeRange) {
  std::mt19937_64 rng(1129);
  const auto coordinate = [&]() -> double {
    const std::uint64_t kind = rng() % 16;
    if (kind == 0) return 0.0;
    if (kind == 1) return (rng() & 1 ? 1 : -1) * std::ldexp(1.0, static_cast<int>(rng() % 2) ? 230 : -260);  // GMP path
    // An integer of 1 to 53 bits scaled into [2^t, 2^(t+1)), t in [-200, 199].
    const int bits = 1 + static_cast<int>(rng() % 53);
    const std::uint64_t mantissa = (rng() >> (64 - bits)) | (std::uint64_t{1} << (bits - 1));
    const int t = static_cast<int>(rng() % 400) - 200;
    return (rng() & 1 ? 1 : -1) * std::ldexp(static_cast<double>(mantissa), t - (bits - 1));
  };
  for (int trial = 0; trial < 40; ++trial) {
    Mesh_d m;
    const std::size_t vertices = 3 + rng() % 60, faces = 1 + rng() % 200, components = 1 + rng() % 4;
    for (std::size_t v = 0; v < vertices; ++v) m.vertices.push_back({coordinate(), coordinate(), coordinate()});
    std::vector<Index> component;
    for (std::size_t f = 0; f < faces; ++f) {
      m.faces.push_back({static_cast<Index>(rng() % vertices), static_cast<Index>(rng() % vertices),
                         static_cast<Index>(rng() % vertices)});
      component.push_back(static_cast<Index>(rng() % components));
    }
    std::vector<mpq_class> six_v(components);
    for (std::size_t f = 0; f < faces; ++f) {
      const auto q = [&](Index v) {
        return std::array<mpq_class, 3>{exact_rational(m.vertices[v].x), exact_rational(m.vertices[v].y),
                                        exact_rational(m.vertices[v].z)};
      };
      const Triangle& t = m.faces[f];
      const auto a = q(t[0]), b = q(t[1]), c = q(t[2]);
      six_v[component[f]] += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                             a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    const internal::Signed_volumes r = internal::signed_volumes(m, component, components, components);
    ASSERT_TRUE(r.exact);
    mpq_class total = 0;
    for (std::size_t c = 0; c < components; ++c) {
      EXPECT_EQ(r.sign[c], sign_of(sgn(six_v[c]))) << "trial " << trial << " component " << c;
      EXPECT_EQ(r.value[c], round_rational<double>(mpq_class(six_v[c] / 6))) << "trial " << trial;
      total += six_v[c];
    }
    EXPECT_EQ(r.total, total / 6) << "trial " << trial;
  }
}

TEST(SolidValidation, PortableWideProductsEqualTheCompilers) {
  std::mt19937_64 rng(64);
  for (int i = 0; i < 200000; ++i) {
    // every width, and the extremes (all ones: every carry)
    std::uint64_t a = rng() >> (rng() % 64), b = rng() >> (rng() % 64);
    if (i % 7 == 0) a = ~std::uint64_t{0};
    if (i % 11 == 0) b = ~std::uint64_t{0};
    const internal::Wide_product p = internal::multiply_wide_portable(a, b), q = internal::multiply_wide(a, b);
    ASSERT_EQ(p.low, q.low) << a << " * " << b;
    ASSERT_EQ(p.high, q.high) << a << " * " << b;
#if defined(__SIZEOF_INT128__)
    __extension__ using U128 = unsigned __int128;
    const U128 exact = static_cast<U128>(a) * b;
    ASSERT_EQ(p.low, static_cast<std::uint64_t>(exact));
    ASSERT_EQ(p.high, static_cast<std::uint64_t>(exact >> 64));
#endif
  }
}

TEST(SolidValidation, VolumeIsExactFarOutsideTheFastRangeToo) {
  // Coordinates of 2^-300 and 2^250 (outside the error-free splitting range):
  // the GMP path.
  const Mesh_d tiny = cube(0x1p-300), huge = cube(0x1p250);
  EXPECT_EQ(mpq_class(validate_solid(tiny).volume.exact_value), mpq_class(exact_rational(0x1p-300)) *
                                                                     exact_rational(0x1p-300) * exact_rational(0x1p-300));
  EXPECT_EQ(mpq_class(validate_solid(huge).volume.exact_value), mpq_class(exact_rational(0x1p250)) *
                                                                     exact_rational(0x1p250) * exact_rational(0x1p250));
}

// ---- one defect each ---------------------------------------------------------------

TEST(SolidValidation, OpenMeshListsItsBoundaryEdges) {
  Mesh_d m = cube();
  m.faces.pop_back();  // {1, 7, 5}
  const Solid_report r = validate_solid(m);
  EXPECT_EQ(r.closed.status, Check_status::fail);
  EXPECT_EQ(r.closed.count, 3u);
  EXPECT_TRUE(lists(r.closed, Mesh_defect::boundary_edge, 1, 5));
  EXPECT_TRUE(lists(r.closed, Mesh_defect::boundary_edge, 5, 7));
  EXPECT_TRUE(lists(r.closed, Mesh_defect::boundary_edge, 1, 7));
  EXPECT_EQ(r.outward_oriented.status, Check_status::not_checked);
  EXPECT_NE(r.outward_oriented.note.find("closed"), std::string::npos);
  EXPECT_FALSE(r.genus.has_value());
  EXPECT_EQ(r.euler_characteristic, 1);
  EXPECT_TRUE(r.self_intersection_free.passed());
  EXPECT_FALSE(r.is_valid_solid());
}

TEST(SolidValidation, NonManifoldEdgeAndVertexAreLocated) {
  Mesh_d m = cube();
  const Index a = 8;
  m.vertices.push_back({0.5, 0.5, 3});
  m.faces.push_back({0, 1, a});  // a third face on edge {0, 1}
  const Solid_report r = validate_solid(m);
  EXPECT_EQ(r.edge_manifold.status, Check_status::fail);
  EXPECT_TRUE(lists(r.edge_manifold, Mesh_defect::non_manifold_edge, 0, 1));
  // Two cubes sharing vertex 7 = (1, 1, 1) by index: a non-manifold vertex.
  Mesh_d two = cube();
  const Mesh_d other = cube(1, {1, 1, 1});
  std::vector<Index> map(8);
  for (Index v = 0; v < 8; ++v) {
    if (v == 0) { map[v] = 7; continue; }  // other's corner (1,1,1) is cube's vertex 7
    map[v] = static_cast<Index>(two.vertices.size());
    two.vertices.push_back(other.vertices[v]);
  }
  for (const Triangle& t : other.faces) two.faces.push_back({map[t[0]], map[t[1]], map[t[2]]});
  const Solid_report rv = validate_solid(two);
  EXPECT_EQ(rv.vertex_manifold.status, Check_status::fail);
  EXPECT_TRUE(lists(rv.vertex_manifold, Mesh_defect::non_manifold_vertex, 7, 2));
  EXPECT_TRUE(rv.closed.passed() && rv.edge_manifold.passed());
  EXPECT_TRUE(rv.self_intersection_free.passed());  // they share the vertex, nothing more
  EXPECT_EQ(rv.components, 1u);                     // connected through it
  EXPECT_EQ(rv.euler_characteristic, 3);            // 15 - 36 + 24
}

TEST(SolidValidation, EulerCountsReadOffTheTopologyEqualThoseOfTheEdgeList) {
  Mesh_d open = cube();
  open.faces.pop_back();
  Mesh_d pinched = cube();  // two cubes sharing vertex 7: edge-manifold, not vertex-manifold
  const Mesh_d other = cube(1, {1, 1, 1});
  std::vector<Index> map(8, 7);
  for (Index v = 1; v < 8; ++v)
    map[v] = static_cast<Index>(pinched.vertices.size()), pinched.vertices.push_back(other.vertices[v]);
  for (const Triangle& t : other.faces) pinched.faces.push_back({map[t[0]], map[t[1]], map[t[2]]});
  Mesh_d two_with_isolated = disjoint_union(torus(10, 6), translated(cube_sphere(4), 7, 0, 0));
  two_with_isolated.vertices.push_back({9, 9, 9});  // an isolated vertex counts in no component
  for (const Mesh_d& m : {cube(), open, pinched, two_with_isolated}) {
    std::vector<Mesh_issue> issues;
    const Mesh_topology t = Mesh_topology::build_checked(m.vertices.size(), m.faces, issues);
    for (const Mesh_issue& i : issues) ASSERT_EQ(i.defect, Mesh_defect::non_manifold_vertex);
    const internal::Face_components c = internal::face_components(m.faces, m.vertices.size());
    const auto listed = internal::euler_counts(m.faces, m.vertices.size(), c);
    const auto read = internal::euler_counts(m.faces, m.vertices.size(), c, t);
    ASSERT_TRUE(read.has_value());
    ASSERT_EQ(read->size(), listed.size());
    for (std::size_t k = 0; k < listed.size(); ++k) {
      EXPECT_EQ((*read)[k].vertices, listed[k].vertices);
      EXPECT_EQ((*read)[k].edges, listed[k].edges);
      EXPECT_EQ((*read)[k].faces, listed[k].faces);
    }
  }
  // A face that repeats a vertex has no adjacency: the edge list counts it.
  Mesh_d repeated = cube();
  repeated.faces.push_back({0, 0, 1});
  std::vector<Mesh_issue> issues;
  const Mesh_topology t = Mesh_topology::build_checked(repeated.vertices.size(), repeated.faces, issues);
  const internal::Face_components c = internal::face_components(repeated.faces, repeated.vertices.size());
  EXPECT_FALSE(internal::euler_counts(repeated.faces, repeated.vertices.size(), c, t).has_value());
  EXPECT_EQ(validate_solid(repeated).euler_characteristic, 8 - 18 + 13);
}

TEST(SolidValidation, FlippedFaceIsAnInconsistentOrientation) {
  Mesh_d m = cube();
  std::swap(m.faces[0][1], m.faces[0][2]);  // {0, 3, 2}
  const Solid_report r = validate_solid(m);
  EXPECT_EQ(r.consistently_oriented.status, Check_status::fail);
  EXPECT_EQ(r.consistently_oriented.count, 3u);
  EXPECT_TRUE(lists(r.consistently_oriented, Mesh_defect::inconsistent_orientation, 0, 2));
  EXPECT_EQ(r.outward_oriented.status, Check_status::not_checked);
  EXPECT_FALSE(r.genus.has_value());
}

template <class K>
void expect_misoriented_cases() {
  const Solid_report inv = validate_solid<K>(inverted(cube_sphere(4)));
  EXPECT_EQ(inv.outward_oriented.status, Check_status::fail);
  EXPECT_TRUE(lists(inv.outward_oriented, Mesh_defect::misoriented_component, 0, 0));
  EXPECT_LT(inv.volume.value, 0);
  // A cavity (inner shell inward) bounds a solid; both outward does not,
  // nor an inward shell outside the other.
  const Mesh_d outer = cube(4, {-2, -2, -2}), inner = jitter(cube_sphere(3), 1e-3);
  const Solid_report hollow = validate_solid<K>(disjoint_union(outer, inverted(inner)));
  EXPECT_TRUE(hollow.is_valid_solid()) << hollow.summary();
  ASSERT_EQ(hollow.component_list.size(), 2u);
  EXPECT_EQ(hollow.component_list[0].winding, 0);
  EXPECT_EQ(hollow.component_list[1].winding, 1);
  const mpq_class inner_volume(validate_solid<K>(inner).volume.exact_value);
  EXPECT_EQ(mpq_class(hollow.volume.exact_value), mpq_class(64 - inner_volume));
  const Solid_report nested = validate_solid<K>(disjoint_union(outer, inner));
  EXPECT_EQ(nested.outward_oriented.status, Check_status::fail);
  EXPECT_EQ(nested.outward_oriented.count, 1u);
  EXPECT_TRUE(lists(nested.outward_oriented, Mesh_defect::misoriented_component, 12, 1));
  const Solid_report apart = validate_solid<K>(disjoint_union(outer, translated(inverted(inner), 9, 0, 0)));
  EXPECT_TRUE(lists(apart.outward_oriented, Mesh_defect::misoriented_component, 12, 1));
  EXPECT_EQ(apart.outward_oriented.count, 1u);
}

TEST(SolidValidation, InvertedSolidAndBadNestingAreMisoriented) {
  expect_misoriented_cases<Filtered_exact_kernel>();
  expect_misoriented_cases<Exact_kernel>();
}

TEST(SolidValidation, FailsafeKernelIsUndecidedOrRightNeverWrong) {
  const Mesh_d outer = cube(4, {-2, -2, -2}), inner = cube_sphere(3);  // symmetric: exactly coplanar neighbours
  const Mesh_d cases[] = {inverted(cube_sphere(4)), disjoint_union(outer, inverted(inner)), disjoint_union(outer, inner),
                          torus(12, 8), disjoint_union(cube(), cube(1, {1, 1, 1})), jitter(cube_sphere(5), 1e-3)};
  std::size_t decided = 0;
  for (const Mesh_d& m : cases) {
    const Solid_report exact = validate_solid(m), failsafe = validate_solid<Failsafe>(m);
    EXPECT_EQ(failsafe.kernel, "failsafe<double>");
    std::vector<const Solid_check*> e, f;
    exact.for_each_check([&](std::string_view, const Solid_check& c) { e.push_back(&c); });
    failsafe.for_each_check([&](std::string_view, const Solid_check& c) { f.push_back(&c); });
    for (std::size_t i = 0; i < e.size(); ++i) {
      if (f[i]->status == Check_status::pass || f[i]->status == Check_status::fail) {
        EXPECT_EQ(f[i]->status, e[i]->status) << i;
        ++decided;
      }
      if (f[i]->status == Check_status::fail) {
        EXPECT_EQ(f[i]->where, e[i]->where) << i;
      }
    }
    EXPECT_EQ(failsafe.volume.exact_value, exact.volume.exact_value);  // the volume does not depend on the kernel
  }
  EXPECT_GT(decided, 50u);
}

TEST(SolidValidation, TouchingComponentsSelfIntersectWhereTheyTouch) {
  // Two cubes meeting in one corner point (distinct vertices at (1, 1, 1)).
  const Solid_report corner = validate_solid(disjoint_union(cube(), cube(1, {1, 1, 1})));
  EXPECT_EQ(corner.self_intersection_free.status, Check_status::fail);
  EXPECT_TRUE(corner.vertex_manifold.passed());
  for (const Mesh_issue& i : corner.self_intersection_free.where) {
    EXPECT_LT(i.elements[0], 12u);  // a face of each cube
    EXPECT_GE(i.elements[1], 12u);
  }
  EXPECT_EQ(corner.outward_oriented.status, Check_status::not_checked);
  // Two cubes sharing a square face's area (coplanar contact).
  const Solid_report face = validate_solid(disjoint_union(cube(), cube(1, {1, 0, 0})));
  EXPECT_EQ(face.self_intersection_free.status, Check_status::fail);
  // Apart by one ulp: no contact.
  const Solid_report apart = validate_solid(disjoint_union(cube(), cube(1, {std::nextafter(1.0, 2.0), 0, 0})));
  EXPECT_TRUE(apart.is_valid_solid()) << apart.summary();
}

TEST(SolidValidation, NonFiniteCoordinatesStopTheGeometricChecks) {
  Mesh_d m = cube();
  m.vertices[6].x = std::numeric_limits<double>::quiet_NaN();
  const Solid_report r = validate_solid(m);
  EXPECT_EQ(r.finite_coordinates.status, Check_status::fail);
  EXPECT_TRUE(lists(r.finite_coordinates, Mesh_defect::non_finite_coordinate, 6));
  EXPECT_EQ(r.self_intersection_free.status, Check_status::not_checked);
  EXPECT_EQ(r.outward_oriented.status, Check_status::not_checked);
  EXPECT_FALSE(r.volume.computed);
  EXPECT_TRUE(r.closed.passed());  // combinatorial checks still run
  EXPECT_EQ(r.euler_characteristic, 2);
  EXPECT_THROW(require_valid_solid(m), Invalid_mesh);
}

TEST(SolidValidation, BadIndicesAndRequireValidSolidNameTheDefect) {
  Mesh_d m = cube();
  m.faces[3][1] = 99;
  const Solid_report r = validate_solid(m);
  EXPECT_TRUE(lists(r.valid_indices, Mesh_defect::index_out_of_range, 3, 99));
  EXPECT_FALSE(r.euler_characteristic.has_value());
  try {
    require_valid_solid(inverted(cube()), {}, "boolean operand A");
    FAIL() << "no exception";
  } catch (const Invalid_mesh& e) {
    EXPECT_EQ(e.defect(), Mesh_defect::misoriented_component);
    EXPECT_NE(std::string(e.what()).find("boolean operand A"), std::string::npos);
  }
  EXPECT_NO_THROW(require_valid_solid(cube()));
}

TEST(SolidValidation, ListsAreCappedCountsAreNot) {
  const Mesh_d m = open_grid(10);  // 40 boundary edges
  const Solid_report r = validate_solid(m, {.max_listed = 5});
  EXPECT_EQ(r.closed.count, 40u);
  EXPECT_EQ(r.closed.where.size(), 5u);
  const Solid_report all = validate_solid(m, {.mesh = {.require_closed = false}});
  EXPECT_EQ(all.closed.status, Check_status::not_checked);
}

TEST(SolidValidation, ATriangleSoupIsReportedInLinearTime) {
  // 30000 separate triangles: 90000 boundary edges, 30000 components (a
  // quadratic boundary or per-component step would not finish).
  Mesh_d soup;
  for (Index i = 0; i < 30000; ++i) {
    const double x = 3.0 * (i % 200), y = 3.0 * (i / 200);
    soup.vertices.insert(soup.vertices.end(), {{x, y, 0}, {x + 1, y, 0}, {x, y + 1, 0.5}});
    soup.faces.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  const Solid_report r = validate_solid(soup);
  EXPECT_EQ(r.closed.count, 90000u);
  EXPECT_EQ(r.components, 30000u);
  EXPECT_EQ(r.component_list.size(), 100u);
  EXPECT_EQ(r.euler_characteristic, 30000);
  EXPECT_TRUE(r.self_intersection_free.passed());
  EXPECT_TRUE(r.volume.exact);
}

TEST(SolidValidation, ResultDoesNotDependOnThreads) {
  Mesh_d m = disjoint_union(cube_sphere(8), translated(cube_sphere(8), 0.7, 0.2, 0.1));
  const Solid_report one = validate_solid(m), two = validate_solid(m, {.threads = 2});
  EXPECT_EQ(one.self_intersection_free.where, two.self_intersection_free.where);
  EXPECT_EQ(one.self_intersection_free.count, two.self_intersection_free.count);
  EXPECT_GT(one.self_intersection_free.count, 0u);
}

// ---- self-intersections by folds and crossings ---------------------------------------

TEST(SelfIntersection, FoldsAcrossASharedEdge) {
  // (0,1,2) and (1,0,3) share edge {0,1}; 3 coplanar on 2's side: folded.
  const Point_3<double> p0{0, 0, 0}, p1{1, 0, 0}, p2{0, 1, 0};
  for (const auto& [p3, meet] : std::vector<std::pair<Point_3<double>, bool>>{
           {{0.5, 0.5, 0}, true}, {{0.5, -0.5, 0}, false}, {{0.5, 0.5, 1e-300}, false}, {{3, 5, 0}, true}}) {
    Mesh_d m;
    m.vertices = {p0, p1, p2, p3};
    m.faces = {{0, 1, 2}, {1, 0, 3}};
    const auto r = find_self_intersections(m);
    EXPECT_EQ(r.pairs.size(), meet ? 1u : 0u) << p3.x << " " << p3.y << " " << p3.z;
    EXPECT_EQ(find_self_intersections<Exact_kernel>(m).pairs, r.pairs);
  }
}

TEST(SelfIntersection, SharedVertexFacesCrossingElsewhere) {
  Mesh_d m;
  // (0,1,2) in z = 0; (0,3,4) shares vertex 0 and its opposite edge 3-4
  // pierces the first face.
  m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}};
  m.faces = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_EQ(find_self_intersections(m).pairs.size(), 1u);
  m.vertices[3] = {-0.5, -0.5, -1}, m.vertices[4] = {-0.5, -0.5, 1};  // on the other side of the corner
  EXPECT_TRUE(find_self_intersections(m).pairs.empty());
  // Coplanar, inside the first face's angle: overlap.
  m.vertices[3] = {0.5, 0.1, 0}, m.vertices[4] = {0.1, 0.5, 0};
  EXPECT_EQ(find_self_intersections(m).pairs.size(), 1u);
  // Coplanar, outside the angle: only the vertex.
  m.vertices[3] = {-0.5, 0.1, 0}, m.vertices[4] = {-0.1, -0.5, 0};
  EXPECT_TRUE(find_self_intersections(m).pairs.empty());
  // Coplanar, touching along an edge from the shared vertex: meet beyond it.
  m.vertices[3] = {1, 0, 0}, m.vertices[4] = {0.5, -1, 0};
  EXPECT_EQ(find_self_intersections(m).pairs.size(), 1u);
}

TEST(SelfIntersection, CrossingWithoutSharedVerticesAndIdenticalFaces) {
  const Mesh_d crossing = disjoint_union(cube(), translated(cube(), 0.5, 0.25, 0.125));
  const auto r = find_self_intersections(crossing);
  EXPECT_FALSE(r.pairs.empty());
  for (const Face_pair& p : r.pairs) EXPECT_TRUE(p.first < 12 && p.second >= 12);
  EXPECT_FALSE(r.is_certainly_free());
  Mesh_d twice = cube();
  twice.faces.push_back(twice.faces[4]);  // the same face twice
  const auto d = find_self_intersections(twice);
  EXPECT_TRUE(std::find(d.pairs.begin(), d.pairs.end(), Face_pair{4, 12}) != d.pairs.end());
}

TEST(SelfIntersection, ACornerOnTheOtherPlaneOutsideItIsNoContact) {
  // t touches f's plane only at (3, 3, 3), outside f; f touches t's plane
  // along an edge. Disjoint.
  Mesh_d m;
  m.vertices = {{0, 0, 3}, {3, 0, 1}, {2, 2, 3}, {3, 3, 3}, {3, 3, 2}, {1, 1, 0}};
  m.faces = {{0, 1, 2}, {3, 4, 5}};
  EXPECT_TRUE(find_self_intersections(m).pairs.empty());
  EXPECT_TRUE(find_self_intersections<Exact_kernel>(m).pairs.empty());
  m.vertices[3] = {1.5, 1.5, 3};  // now inside f: they touch
  EXPECT_EQ(find_self_intersections(m).pairs.size(), 1u);
}

TEST(SelfIntersection, DegenerateFacesAreSkippedAndReported) {
  Mesh_d m = cube();
  m.vertices.push_back({0.5, 0, 0});  // 8 on edge {0, 1}
  m.faces.push_back({0, 8, 1});       // collinear
  m.faces.push_back({2, 2, 3});       // repeated index
  const auto r = find_self_intersections(m);
  EXPECT_EQ(r.degenerate_faces, (std::vector<Index>{12, 13}));
  const Solid_report s = validate_solid(m);
  EXPECT_TRUE(lists(s.non_degenerate_faces, Mesh_defect::collinear_face, 12));
  EXPECT_TRUE(lists(s.non_degenerate_faces, Mesh_defect::repeated_vertex_in_face, 13));
}

// The face-pair predicates (what two faces share decides the test) against
// intersect_triangles, which computes the whole intersection: they meet
// beyond what they share iff the intersection is more than that.
bool meets_beyond_by_intersection(const Mesh_d& m, const Triangle& f, const Triangle& g) {
  const Filtered_exact_kernel k;
  const auto pt = [&](Index v) { return m.vertices[v]; };
  const auto x = intersect_triangles<Filtered_exact_kernel>({pt(f[0]), pt(f[1]), pt(f[2])},
                                                           {pt(g[0]), pt(g[1]), pt(g[2])}, k);
  std::set<Index> shared;
  for (Index a : f)
    for (Index b : g)
      if (a == b) shared.insert(a);
  using Kind = Triangle_intersection_kind;
  if (x.kind == Kind::disjoint) return false;
  if (shared.empty()) return true;
  if (x.kind == Kind::coplanar_overlap || x.kind == Kind::crossing) return true;
  // A point or a segment: beyond the share unless every point is a shared vertex.
  for (std::size_t i = 0; i < x.points.size(); ++i) {
    const auto loc = x.locations[i][0];
    if (loc.kind != Triangle_location::Kind::vertex || !shared.count(f[loc.index])) return true;
  }
  return false;
}

TEST(SelfIntersection, AgreesWithTheClassifiedIntersectionOnDegenerateGrids) {
  std::mt19937_64 g(2024);
  std::uniform_int_distribution<int> u(0, 3);
  std::size_t meet = 0, tested = 0, failsafe_decided = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Mesh_d m;
    for (int i = 0; i < 6; ++i) m.vertices.push_back({double(u(g)), double(u(g)), double(u(g))});
    const int share = trial % 3;  // 0, 1 or 2 shared vertices
    const Triangle f{0, 1, 2};
    const Triangle t = share == 0 ? Triangle{3, 4, 5} : share == 1 ? Triangle{0, 4, 5} : Triangle{1, 0, 5};
    m.faces = {f, t};
    const auto r = find_self_intersections(m);
    if (!r.degenerate_faces.empty()) continue;
    ++tested;
    const bool expected = meets_beyond_by_intersection(m, f, t);
    meet += expected;
    ASSERT_EQ(r.pairs.size(), expected ? 1u : 0u) << "trial " << trial;
    ASSERT_EQ(find_self_intersections<Exact_kernel>(m).pairs, r.pairs) << "trial " << trial;
    // Fail-safe: its answer, when it gives one, is the exact one.
    const auto s = find_self_intersections<Failsafe>(m);
    if (s.undecided.empty() && s.undecided_faces.empty()) {
      ++failsafe_decided;
      ASSERT_EQ(s.pairs, r.pairs) << "trial " << trial;
    } else {
      ASSERT_TRUE(s.pairs.empty());
    }
  }
  EXPECT_GT(tested, 10000u);
  EXPECT_GT(meet, tested / 10);  // both outcomes are frequent
  EXPECT_LT(meet, tested - tested / 10);
  EXPECT_GT(failsafe_decided, tested / 4);
}

TEST(SelfIntersection, IntervalKernelOnRationalPointsIsNeverWrong) {
  const Mesh_d m = jitter(disjoint_union(cube_sphere(3), translated(cube_sphere(3), 0.5, 0, 0)), 1e-3);
  const auto exact = find_self_intersections(m);
  const auto iv = find_self_intersections<Interval_kernel>(m);
  for (const Face_pair& p : iv.pairs) EXPECT_TRUE(std::binary_search(exact.pairs.begin(), exact.pairs.end(), p));
  for (const Face_pair& p : exact.pairs)
    EXPECT_TRUE(std::binary_search(iv.pairs.begin(), iv.pairs.end(), p) ||
                std::binary_search(iv.undecided.begin(), iv.undecided.end(), p));
  EXPECT_FALSE(exact.pairs.empty());
}

}  // namespace
