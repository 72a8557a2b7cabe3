// Valid_solid: a certificate that travels with a mesh, so that a Boolean of
// certified solids does not check its operands again (issue 28, item 3).
#include <gtest/gtest.h>

#include <limits>

#include "boolean_chains.h"
#include "relgeo/boolean.h"
#include "relgeo/mesh/shapes.h"

namespace relgeo::test {
namespace {

using Op = Boolean_operation;

bool names(const Invalid_mesh& e, Mesh_defect d) {
  for (const Mesh_issue& i : e.issues())
    if (i.defect == d) return true;
  return false;
}

TEST(ValidSolid, CheckingAMeshCertifiesItOrNamesTheDefects) {
  const Valid_solid cube_solid(cube(0, 0, 0, 1));
  EXPECT_EQ(cube_solid.mesh().faces.size(), 12u);

  Mesh_double open = cube(0, 0, 0, 1);
  open.faces.pop_back();
  try {
    (void)Valid_solid(open);
    FAIL() << "an open mesh was certified";
  } catch (const Invalid_operand& e) {
    EXPECT_EQ(e.operand(), "solid");
    EXPECT_TRUE(names(e, Mesh_defect::boundary_edge)) << e.what();
  }
  Mesh_double not_finite = cube(0, 0, 0, 1);
  not_finite.vertices[0].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)Valid_solid(not_finite), Invalid_operand);
  // Two overlapping cubes in one mesh: closed and manifold, but crossing itself.
  Mesh_double crossing = cube(0, 0, 0, 1);
  const Mesh_double other = cube(0.5, 0.5, 0.5, 1);
  const Index n = static_cast<Index>(crossing.vertices.size());
  crossing.vertices.insert(crossing.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (Triangle t : other.faces) crossing.faces.push_back({t[0] + n, t[1] + n, t[2] + n});
  try {
    (void)Valid_solid(crossing);
    FAIL() << "a self-intersecting mesh was certified";
  } catch (const Invalid_operand& e) {
    EXPECT_TRUE(names(e, Mesh_defect::self_intersection)) << e.what();
  }
}

TEST(ValidSolid, AValidatedResultIsCertifiedAndNotCheckedAgain) {
  // The fused-spheres chain through Valid_solid: every step's operands are
  // certified (the first by checking, the others by the last validation),
  // none is checked again, and each result is the one of the plain Boolean.
  const Boolean_chain c = make_chain(Chain_family::fused_spheres, 6);
  Valid_solid current(c.start);
  Mesh_double plain = c.start;
  for (const auto& [op, operand] : c.steps) {
    const auto r = boolean(current, Valid_solid(operand), op);
    ASSERT_TRUE(r.ok()) << r.failure;
    EXPECT_EQ(r.counts.checked_operands, 0u);
    const auto p = boolean(plain, operand, op);
    EXPECT_EQ(p.counts.checked_operands, 2u);
    EXPECT_EQ(r.mesh.faces, p.mesh.faces);
    EXPECT_EQ(r.mesh.vertices, p.mesh.vertices);
    const std::optional<Valid_solid> next = Valid_solid::of(r);
    ASSERT_TRUE(next.has_value()) << r.validation.summary();
    current = *next;
    plain = operand_of(p.mesh);
  }
}

// A valid result carries the half-edge opposites its validation built (the
// next Boolean of a chain takes them: see the next test); one that is not a
// valid solid carries none.
TEST(ValidSolid, AResultThatIsNotASolidCarriesNoTopology) {
  const Mesh_double a = torus(1, 0.3, 24, 12), b = rigidly_moved(icosphere(2), 0.3, 0.2, {0, 0, 0.05});
  const auto touching = boolean(a, b, Op::symmetric_difference);
  ASSERT_FALSE(touching.validation.is_valid_solid());
  EXPECT_TRUE(touching.halfedge_opposites.empty());
  const auto solid = boolean(a, b, Op::union_of);
  ASSERT_TRUE(solid.validation.is_valid_solid()) << solid.validation.summary();
  EXPECT_EQ(solid.halfedge_opposites, Mesh_topology::build(solid.mesh).take_opposites());
}

// The output's validation skips only the pairs of faces kept unchanged
// from one certified operand, and concludes what the full validation
// concludes. Each result's carried opposites (the next step's operand
// topology) are those of its mesh.
TEST(ValidSolid, TheValidationSkipsOnlyWhatTheCertificatesProve) {
  const Boolean_chain c = make_chain(Chain_family::fused_spheres, 4);
  Valid_solid current(c.start);
  for (const auto& [op, operand] : c.steps) {
    const auto r = boolean(current, Valid_solid(operand), op);
    ASSERT_TRUE(r.ok()) << r.failure;
    // Most faces of a union of spheres are kept whole, not all.
    EXPECT_GT(r.counts.unchanged_certified_faces, r.mesh.faces.size() / 2);
    EXPECT_LT(r.counts.unchanged_certified_faces, r.mesh.faces.size());
    const Solid_report full = validate_solid(r.mesh, Boolean_options{}.validation);
    EXPECT_EQ(r.validation.summary(), full.summary());
    EXPECT_EQ(r.validation.volume.value, full.volume.value);
    EXPECT_EQ(r.halfedge_opposites, Mesh_topology::build(r.mesh).take_opposites());
    current = Valid_solid::of(r).value();
  }
}

// Without a certificate nothing is skipped: an operand that crosses itself
// (two overlapping cubes in one mesh), unchecked, keeps its crossing faces
// in the output, and the validation finds them — also when the options
// carry a certificate made for other meshes.
TEST(ValidSolid, AnUncheckedOperandIsValidatedInFull) {
  Mesh_double crossing = cube(0, 0, 0, 1);
  const Mesh_double other = cube(0.5, 0.5, 0.5, 1);
  const Index n = static_cast<Index>(crossing.vertices.size());
  crossing.vertices.insert(crossing.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (Triangle t : other.faces) crossing.faces.push_back({t[0] + n, t[1] + n, t[2] + n});
  const Mesh_double apart = cube(5, 0, 0, 1);
  const Valid_solid x(cube(0, 0, 0, 1)), y(apart);
  Boolean_options unchecked;
  unchecked.check_operands = false;
  for (const bool foreign_certificate : {false, true}) {
    if (foreign_certificate) unchecked.certified_operands = Valid_solid::certificate(x, y);
    const auto r = boolean(crossing, apart, Op::union_of, Filtered_exact_kernel{}, unchecked);
    ASSERT_TRUE(r.ok()) << r.failure;
    EXPECT_EQ(r.counts.unchanged_certified_faces, 0u);
    EXPECT_EQ(r.validation.self_intersection_free.status, Check_status::fail) << r.validation.summary();
  }
  // The same certificate with its own meshes: certified, nothing to find.
  const auto r = boolean(x, y, Op::union_of);
  EXPECT_EQ(r.counts.unchanged_certified_faces, 24u);
  EXPECT_TRUE(r.validation.is_valid_solid()) << r.validation.summary();
}

TEST(ValidSolid, NoCertificateWithoutAPassedValidation) {
  const Mesh_double a = torus(1, 0.3, 24, 12), b = rigidly_moved(icosphere(2), 0.3, 0.2, {0, 0, 0.05});
  // Nearest rounding of the insertion order's triangulation crosses itself.
  Boolean_options broken;
  broken.rounding = Output_rounding::nearest;
  broken.delaunay_retriangulation = false;
  const auto crossing = boolean(a, b, Op::union_of, Filtered_exact_kernel{}, broken);
  ASSERT_TRUE(crossing.ok());
  ASSERT_FALSE(crossing.validation.is_valid_solid());
  EXPECT_FALSE(Valid_solid::of(crossing).has_value());
  // Not validated: nothing certifies it.
  Boolean_options unvalidated;
  unvalidated.validate_output = false;
  EXPECT_FALSE(Valid_solid::of(boolean(a, b, Op::union_of, Filtered_exact_kernel{}, unvalidated)).has_value());
  // A symmetric difference touches itself along its curves: not a solid.
  EXPECT_FALSE(Valid_solid::of(boolean(a, b, Op::symmetric_difference)).has_value());
  EXPECT_TRUE(Valid_solid::of(boolean(a, b, Op::union_of)).has_value());
}

TEST(ValidSolid, TheEmptySolidIsAnOperandLikeAnyOther) {
  // As the Boolean accepts it: A union nothing is A. An empty result (cubes
  // apart, intersected) is certified as the empty solid and goes on.
  const Valid_solid nothing{Mesh_double{}};
  const auto r = boolean(Valid_solid(cube(0, 0, 0, 1)), nothing, Op::union_of);
  ASSERT_TRUE(r.ok()) << r.failure;
  EXPECT_EQ(r.mesh.faces.size(), 12u);
  const auto apart = boolean(Valid_solid(cube(0, 0, 0, 1)), Valid_solid(cube(3, 0, 0, 1)), Op::intersection);
  ASSERT_TRUE(apart.ok()) << apart.failure;
  ASSERT_TRUE(apart.mesh.faces.empty());
  const std::optional<Valid_solid> empty = Valid_solid::of(apart);
  ASSERT_TRUE(empty.has_value());
  const auto again = boolean(*empty, Valid_solid(cube(0, 0, 0, 1)), Op::union_of);
  ASSERT_TRUE(again.ok()) << again.failure;
  EXPECT_TRUE(again.validation.is_valid_solid()) << again.validation.summary();
  EXPECT_EQ(again.mesh.faces.size(), 12u);
}

}  // namespace
}  // namespace relgeo::test
