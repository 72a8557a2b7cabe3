// Exact chains (issue 28, item 3): Booleans whose operands are meshes of an
// exact kernel's points, so that a chain of Booleans keeps every
// intermediate exact and rounds once at the end. The exact results do not
// depend on how a solid was reached; the rounded ones do.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "boolean_chains.h"
#include "relgeo/boolean.h"
#include "relgeo/mesh/solid_validation.h"
#include "support/soundness_data.h"

namespace relgeo::test {
namespace {

using Op = Boolean_operation;
using Exact_mesh = Triangle_mesh<Exact_kernel::Point_3>;

// The exact signed volume of a mesh of doubles or of rationals.
template <class P>
mpq_class exact_volume(const Triangle_mesh<P>& m) {
  const Solid_report v = validate_solid(m, typename Kernel_for_point<Certified_kernel_for_number, P>::type{},
                                        Solid_validation_options{.exact_volume_string = true});
  return mpq_class(v.volume.exact_value);
}

Boolean_options nearest() {
  Boolean_options o;
  o.rounding = Output_rounding::nearest;
  return o;
}

// The exact points of a mesh, sorted (to compare two results' vertex sets).
std::vector<Point_3<mpq_class>> sorted_points(const Exact_mesh& m) {
  std::vector<Point_3<mpq_class>> p = m.vertices;
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
  });
  return p;
}

// The same two solids as doubles and as rationals: the same exact result
// (its vertices and volume), and from exact operands every output vertex is
// rounded and known exactly.
TEST(ExactChain, ExactOperandsGiveTheResultOfTheSameSolidsInDoubles) {
  const Mesh_double a = torus(1, 0.3, 24, 12), b = rigidly_moved(icosphere(2), 0.3, 0.2, {0, 0, 0.05});
  const Exact_mesh ea = exact_operand(a, Exact_kernel{}), eb = exact_operand(b, Exact_kernel{});
  for (const Op op : {Op::union_of, Op::intersection, Op::difference}) {
    const auto from_doubles = boolean(a, b, op, Exact_kernel{}, nearest());
    const auto from_exact = boolean(ea, eb, op, Exact_kernel{}, nearest());
    ASSERT_TRUE(from_doubles.ok()) << from_doubles.failure;
    ASSERT_TRUE(from_exact.ok()) << from_exact.failure;
    EXPECT_EQ(from_exact.first_new_vertex, 0u);
    EXPECT_EQ(from_exact.new_vertex_points.size(), from_exact.mesh.vertices.size());
    EXPECT_EQ(from_exact.mesh.faces.size(), from_doubles.mesh.faces.size()) << to_string(op);
    const Exact_mesh x = from_exact.exact_mesh(), y = from_doubles.exact_mesh();
    EXPECT_TRUE(sorted_points(x) == sorted_points(y)) << to_string(op);
    EXPECT_EQ(exact_volume(x), exact_volume(y)) << to_string(op);
    EXPECT_TRUE(validate_solid(x, Exact_kernel{}).is_valid_solid()) << to_string(op);
    // Each vertex in doubles within rounding_error of its exact point.
    const mpq_class bound(from_exact.rounding_error);
    for (Index v = 0; v < x.vertices.size(); ++v) {
      const Point_3<double>& d = from_exact.mesh.vertices[v];
      const Point_3<mpq_class>& e = x.vertices[v];
      EXPECT_LE(abs(mpq_class(d.x) - e.x), bound);
      EXPECT_LE(abs(mpq_class(d.y) - e.y), bound);
      EXPECT_LE(abs(mpq_class(d.z) - e.z), bound);
    }
  }
}

// One solid reached two ways: a sphere minus three prisms one after the
// other, and the sphere minus the union of the prisms (which cross each
// other at its centre). Kept exact, both chains end on one exact volume.
// Rounded at every step (the default chain), they do not: each rounds other
// intermediate solids. The test fails on a chain that rounds.
TEST(ExactChain, OneSolidReachedTwoWaysHasOneExactVolume) {
  // (Two prisms in the sanitizer run: exact arithmetic is slow there.)
  const Boolean_chain c = make_chain(Chain_family::drilled_sphere, test_scale() < 1 ? 2 : 3, 7, 2);
  const Exact_kernel k;
  // Exact: ((S - P1) - P2) - P3 and S - ((P1 u P2) u P3).
  Exact_mesh one_by_one = exact_operand(c.start, k), prisms = exact_operand(c.steps[0].second, k);
  for (std::size_t i = 0; i < c.steps.size(); ++i) {
    const auto r = boolean(one_by_one, exact_operand(c.steps[i].second, k), Op::difference, k, nearest());
    ASSERT_TRUE(r.ok()) << r.failure;
    one_by_one = r.exact_mesh();
    if (i == 0) continue;
    const auto u = boolean(prisms, exact_operand(c.steps[i].second, k), Op::union_of, k, nearest());
    ASSERT_TRUE(u.ok()) << u.failure;
    prisms = u.exact_mesh();
  }
  const auto at_once = boolean(exact_operand(c.start, k), prisms, Op::difference, k, nearest());
  ASSERT_TRUE(at_once.ok()) << at_once.failure;
  const mpq_class v = exact_volume(one_by_one);
  EXPECT_EQ(v, exact_volume(at_once.exact_mesh()));
  EXPECT_GT(v, 0);
  // Rounded at every step (the default options), the two ways part.
  Mesh_double rounded = c.start, rounded_prisms = c.steps[0].second;
  for (std::size_t i = 0; i < c.steps.size(); ++i) {
    const auto r = boolean(rounded, c.steps[i].second, Op::difference);
    ASSERT_TRUE(r.ok()) << r.failure;
    rounded = operand_of(r.mesh);
    if (i == 0) continue;
    const auto u = boolean(rounded_prisms, c.steps[i].second, Op::union_of);
    ASSERT_TRUE(u.ok()) << u.failure;
    rounded_prisms = operand_of(u.mesh);
  }
  const auto rounded_at_once = boolean(c.start, rounded_prisms, Op::difference);
  ASSERT_TRUE(rounded_at_once.ok()) << rounded_at_once.failure;
  EXPECT_NE(exact_volume(rounded), exact_volume(rounded_at_once.mesh));
}

// With exact operands the validation is the exact result's (under the
// exact kernel: the next operand's certificate), not the rounded mesh's:
// the torus-sphere union of the insertion order's triangulation, rounded to
// nearest, crosses itself in doubles and not exactly.
TEST(ExactChain, TheValidationIsTheExactResults) {
  Boolean_options o = nearest();
  o.delaunay_retriangulation = false;
  const Exact_kernel k;
  const auto r = boolean(exact_operand(torus(1, 0.3, 24, 12), k),
                         exact_operand(rigidly_moved(icosphere(2), 0.3, 0.2, {0, 0, 0.05}), k), Op::union_of, k, o);
  ASSERT_TRUE(r.ok()) << r.failure;
  EXPECT_EQ(r.validation.kernel, Exact_kernel::name());
  EXPECT_TRUE(r.validation.is_valid_solid()) << r.validation.summary();
  EXPECT_GT(r.counts.unchanged_certified_faces, 0u);  // the operands' checks certify the faces kept whole
  EXPECT_FALSE(validate_solid(r.mesh).self_intersection_free.passed());
}

// Bad exact operands get the typed errors doubles get: the checks decide
// under the exact kernel; a NaN cannot become a rational.
TEST(ExactChain, BadExactOperandsAreRefusedWithTheDefect) {
  const Exact_kernel k;
  const Exact_mesh good = exact_operand(cube(0, 0, 0, 1), k);
  const auto defect_of = [&](const Mesh_double& bad) -> Mesh_defect {
    try {
      (void)boolean(good, exact_operand(bad, k), Op::union_of, k);
    } catch (const Invalid_operand& e) {
      EXPECT_EQ(e.operand(), "B");
      return e.defect();
    }
    ADD_FAILURE() << "not refused";
    return Mesh_defect::undecided;
  };
  Mesh_double open = cube(2, 0, 0, 1);
  open.faces.pop_back();
  EXPECT_EQ(defect_of(open), Mesh_defect::boundary_edge);
  Mesh_double flipped = cube(2, 0, 0, 1);
  std::swap(flipped.faces[0][1], flipped.faces[0][2]);
  EXPECT_EQ(defect_of(flipped), Mesh_defect::inconsistent_orientation);
  Mesh_double crossing = cube(2, 0, 0, 1);
  const Mesh_double other = cube(2.5, 0.5, 0.5, 1);
  for (const auto& p : other.vertices) crossing.vertices.push_back(p);
  for (const auto& f : other.faces) crossing.faces.push_back({f[0] + 8, f[1] + 8, f[2] + 8});
  EXPECT_EQ(defect_of(crossing), Mesh_defect::self_intersection);
  Mesh_double nan = cube(2, 0, 0, 1);
  nan.vertices[3].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)exact_operand(nan, k), Non_finite_input);
}

// The empty solid is an operand of exact chains as of rounded ones: cubes
// apart, intersected, give the empty exact solid, and the chain goes on
// (the other operand's pieces are outside it: no ray to cast).
TEST(ExactChain, TheEmptySolidGoesOn) {
  const Exact_kernel k;
  const auto apart =
      boolean(exact_operand(cube(0, 0, 0, 1), k), exact_operand(cube(3, 0, 0, 1), k), Op::intersection, k, nearest());
  ASSERT_TRUE(apart.ok()) << apart.failure;
  const Exact_mesh empty = apart.exact_mesh();
  ASSERT_TRUE(empty.faces.empty());
  const auto again = boolean(empty, exact_operand(cube(0, 0, 0, 1), k), Op::union_of, k, nearest());
  ASSERT_TRUE(again.ok()) << again.failure;
  EXPECT_EQ(again.mesh.faces.size(), 12u);
  EXPECT_EQ(exact_volume(again.exact_mesh()), 1);
}

TEST(ExactChain, TheExactMeshIsRefusedWhereItIsNotTheExactResult) {
  // A failed Boolean: a repair allowed no round, which the rounding of
  // this union needs (the insertion order's triangulation).
  Boolean_options no_repair;
  no_repair.repair.max_rounds = 0;
  no_repair.delaunay_retriangulation = false;
  const auto failed = boolean(torus(1, 0.3, 24, 12), rigidly_moved(icosphere(2), 0.3, 0.2, {0, 0, 0.05}), Op::union_of,
                              Exact_kernel{}, no_repair);
  ASSERT_FALSE(failed.ok());
  EXPECT_THROW((void)failed.exact_mesh(), Precondition_violation);
  // A repair that only moved vertices keeps the exact faces; one that
  // flipped or collapsed edges (marked here on a copy) changed them.
  Boolean_options repaired;
  repaired.delaunay_retriangulation = false;
  auto moved = boolean(torus(1, 0.3, 24, 12), rigidly_moved(icosphere(2), 0.3, 0.2, {0, 0, 0.05}), Op::union_of,
                       Exact_kernel{}, repaired);
  ASSERT_TRUE(moved.ok()) << moved.failure;
  ASSERT_GT(moved.rounding.moved_vertices, 0u);
  EXPECT_NO_THROW((void)moved.exact_mesh());
  moved.rounding.flips = 1;
  EXPECT_THROW((void)moved.exact_mesh(), Precondition_violation);
}

}  // namespace
}  // namespace relgeo::test
