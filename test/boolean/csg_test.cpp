// relgeo::csg: trees of unions, intersections and differences, evaluated with
// the Boolean, every step validated; bad trees refused before any Boolean,
// naming the node.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "boolean_chains.h"
#include "relgeo/boolean/csg.h"
#include "support/soundness_data.h"

namespace relgeo::test {
namespace {

using Kind = Csg_node::Kind;

Csg_node cubes_tree() {
  // (unit cube u the cube moved by (0.5, 0.25, 0.125)) - the unit cube moved by (1, 0, 0).
  return Csg_node::operation(
      Kind::difference,
      {Csg_node::operation(Kind::union_of, {Csg_node::solid(cube(0, 0, 0, 1), "cube"),
                                            Csg_node::solid(cube(0.5, 0.25, 0.125, 1), "offset")}),
       Csg_node::solid(cube(1, 0, 0, 1), "next")});
}

TEST(Csg, ADifferenceOfAUnionHasItsExactVolume) {
  const Csg_result r = csg(cubes_tree());
  ASSERT_TRUE(r.ok()) << r.failure;
  ASSERT_EQ(r.steps.size(), 2u);
  EXPECT_EQ(r.steps[0].node, "root.0");
  EXPECT_EQ(r.steps[1].node, "root");
  EXPECT_EQ(r.steps[1].volume, 1.671875 - 0.328125);
  EXPECT_EQ(r.steps[1].validation, "valid solid");
  EXPECT_EQ(r.mesh.faces.size(), r.steps[1].faces);
  const Csg_result exact = csg(cubes_tree(), Exact_kernel{});
  ASSERT_TRUE(exact.ok()) << exact.failure;
  EXPECT_EQ(exact.steps[1].volume, 1.34375);
}

TEST(Csg, AnNAryUnionIsTheUnionOfItsArguments) {
  // Five spheres at once (a balanced reduction) and one after the other.
  const Boolean_chain c = make_chain(Chain_family::fused_spheres, 4, 3, 2);
  std::vector<Csg_node> args{Csg_node::solid(c.start)};
  Csg_node sequential = Csg_node::solid(c.start);
  for (const auto& [op, m] : c.steps) {
    args.push_back(Csg_node::solid(m));
    sequential = Csg_node::operation(Kind::union_of, {sequential, Csg_node::solid(m)});
  }
  const Csg_result at_once = csg(Csg_node::operation(Kind::union_of, args));
  const Csg_result one_by_one = csg(sequential);
  ASSERT_TRUE(at_once.ok()) << at_once.failure;
  ASSERT_TRUE(one_by_one.ok()) << one_by_one.failure;
  EXPECT_EQ(at_once.steps.size(), 4u);
  EXPECT_EQ(at_once.steps[0].node, "root");
  EXPECT_NEAR(at_once.steps.back().volume, one_by_one.steps.back().volume, 1e-12 * one_by_one.steps.back().volume);
}

TEST(Csg, TheDrilledSphereAsOneDifference) {
  // The 24-step chain as one node: the sphere minus 24 prisms, each step
  // valid (the intermediate results are not checked again as operands).
  const Boolean_chain c = make_chain(Chain_family::drilled_sphere, test_scale() < 1 ? 6 : 24);
  std::vector<Csg_node> args{Csg_node::solid(c.start, "sphere")};
  for (const auto& [op, m] : c.steps) args.push_back(Csg_node::solid(m, "prism"));
  const Csg_result r = csg(Csg_node::operation(Kind::difference, args));
  ASSERT_TRUE(r.ok()) << r.failure;
  ASSERT_EQ(r.steps.size(), c.steps.size());
  for (const Csg_step& s : r.steps) EXPECT_EQ(s.validation, "valid solid");
  EXPECT_GT(r.steps.back().volume, 0);
  EXPECT_LT(r.steps.back().volume, 4.0 / 3 * 3.14159265358979 * 1.0001);
}

TEST(Csg, BadTreesAreRefusedBeforeAnyBooleanNamingTheNode) {
  const auto node_of = [](const Csg_node& tree) {
    try {
      (void)csg(tree);
    } catch (const Invalid_csg_node& e) {
      return e.node();
    }
    return std::string("no error");
  };
  EXPECT_EQ(node_of(Csg_node::operation(Kind::union_of, {Csg_node::solid(cube(0, 0, 0, 1))})), "root");
  EXPECT_EQ(node_of(Csg_node::operation(Kind::intersection, {})), "root");
  Csg_node no_mesh;
  EXPECT_EQ(node_of(Csg_node::operation(Kind::union_of, {Csg_node::solid(cube(0, 0, 0, 1)), no_mesh})), "root.1");
  Mesh_double open = cube(0, 0, 0, 1);
  open.faces.pop_back();
  const Csg_node deep = Csg_node::operation(
      Kind::difference,
      {Csg_node::solid(cube(0, 0, 0, 1)),
       Csg_node::operation(Kind::union_of, {Csg_node::solid(cube(2, 0, 0, 1)), Csg_node::solid(open, "open")})});
  EXPECT_EQ(node_of(deep), "root.1.1");
  Mesh_double not_finite = cube(0, 0, 0, 1), empty;
  not_finite.vertices[3].z = std::numeric_limits<double>::infinity();
  EXPECT_EQ(node_of(Csg_node::operation(Kind::union_of, {Csg_node::solid(not_finite), Csg_node::solid(cube(2, 0, 0, 1))})),
            "root.0");
  EXPECT_EQ(node_of(Csg_node::operation(Kind::intersection, {Csg_node::solid(cube(0, 0, 0, 1)), Csg_node::solid(empty)})),
            "root.1");
  try {
    (void)csg(deep);
  } catch (const Invalid_csg_node& e) {
    EXPECT_NE(std::string(e.what()).find("boundary_edge"), std::string::npos) << e.what();
  }
}

TEST(Csg, AFailedStepStopsTheTreeAndSaysWhere) {
  // A repair allowed no round: the torus-sphere union of the insertion
  // order's triangulation (which rounding makes cross) cannot be repaired,
  // and the tree stops at that node with that step's mesh.
  Csg_options o;
  o.boolean.repair.max_rounds = 0;
  o.boolean.delaunay_retriangulation = false;
  const Csg_node tree = Csg_node::operation(
      Kind::difference,
      {Csg_node::operation(Kind::union_of, {Csg_node::solid(torus(1, 0.3, 24, 12)),
                                            Csg_node::solid(rigidly_moved(icosphere(2), 0.3, 0.2, {0, 0, 0.05}))}),
       Csg_node::solid(cube(5, 5, 5, 1))});
  const Csg_result r = csg(tree, Filtered_exact_kernel{}, o);
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_EQ(r.failure.rfind("node root.0 (union, step 1): rounding:", 0), 0u) << r.failure;
  EXPECT_FALSE(r.mesh.faces.empty());
}

// Exact intermediates: the chain's steps kept exact, validated exactly, and
// only the root rounded: the root's mesh is the step-by-step exact chain's
// result rounded once, and the coordinates grow with every step (the cost
// the documentation states).
TEST(Csg, ExactIntermediatesRoundOnlyTheRoot) {
  const Boolean_chain c = make_chain(Chain_family::drilled_sphere, test_scale() < 1 ? 2 : 3, 7, 2);
  Csg_options o;
  o.intermediates = Csg_intermediates::exact;
  const Csg_result r = csg(csg_tree(c), Exact_kernel{}, o);
  ASSERT_TRUE(r.ok()) << r.failure;
  ASSERT_EQ(r.steps.size(), c.steps.size());
  for (const Csg_step& s : r.steps) EXPECT_EQ(s.validation, "valid solid") << s.node;
  EXPECT_GT(r.steps.front().coordinate_bits, 64u);
  EXPECT_GT(r.steps.back().coordinate_bits, r.steps.front().coordinate_bits);
  EXPECT_EQ(r.validation, "valid solid");
  // The same chain by hand: exact Booleans, the last exact mesh rounded.
  Boolean_options nearest;
  nearest.rounding = Output_rounding::nearest;
  auto exact = exact_operand(c.start, Exact_kernel{});
  for (const auto& [op, m] : c.steps) {
    const auto step = boolean(exact, exact_operand(m, Exact_kernel{}), op, Exact_kernel{}, nearest);
    ASSERT_TRUE(step.ok()) << step.failure;
    exact = step.exact_mesh();
  }
  ASSERT_EQ(r.rounding.flips + r.rounding.collapses, 0u);  // (the repair, if any, only moved vertices)
  ASSERT_EQ(r.mesh.faces, exact.faces);
  ASSERT_EQ(r.mesh.vertices.size(), exact.vertices.size());
  std::size_t moved = 0;
  const Exact_kernel k;
  for (std::size_t v = 0; v < exact.vertices.size(); ++v) {
    const Point_3<double> nearest_double =
        k.approximate_point_3_object()(k.construct_implicit_point_3_object()(exact.vertices[v])).point;
    moved += r.mesh.vertices[v] != nearest_double;
  }
  EXPECT_LE(moved, r.rounding.moved_vertices);
  EXPECT_EQ(r.steps.back().volume, validate_solid(exact, Exact_kernel{}).volume.value);
}

// An empty intermediate (cubes apart, intersected) is the empty solid, and
// the tree goes on, with rounded and with exact intermediates.
TEST(Csg, AnEmptyIntermediateIsTheEmptySolid) {
  const Csg_node tree = Csg_node::operation(
      Kind::union_of, {Csg_node::operation(Kind::intersection, {Csg_node::solid(cube(0, 0, 0, 1), "cube"),
                                                                Csg_node::solid(cube(3, 0, 0, 1), "apart")}),
                       Csg_node::solid(cube(0, 0, 0, 1), "again")});
  Csg_options exact;
  exact.intermediates = Csg_intermediates::exact;
  for (const Csg_result& r : {csg(tree), csg(tree, Exact_kernel{}, exact)}) {
    ASSERT_TRUE(r.ok()) << r.failure;
    ASSERT_EQ(r.steps.size(), 2u);
    EXPECT_EQ(r.steps[0].faces, 0u);
    EXPECT_EQ(r.mesh.faces.size(), 12u);
    EXPECT_EQ(r.steps[1].volume, 1);
  }
}

TEST(Csg, ExactIntermediatesNeedAnExactKernel) {
  Csg_options o;
  o.intermediates = Csg_intermediates::exact;
  try {
    (void)csg(cubes_tree(), Filtered_exact_kernel{}, o);
    ADD_FAILURE() << "no error";
  } catch (const Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("filtered"), std::string::npos) << e.what();
  }
  // A bad tree is refused as with rounded intermediates.
  EXPECT_THROW((void)csg(Csg_node::operation(Kind::union_of, {Csg_node::solid(cube(0, 0, 0, 1))}), Exact_kernel{}, o),
               Invalid_csg_node);
  const Csg_result exact = csg(cubes_tree(), Exact_kernel{}, o);
  ASSERT_TRUE(exact.ok()) << exact.failure;
  EXPECT_EQ(exact.steps[1].volume, 1.34375);
  EXPECT_EQ(exact.rounding.rounds, 0);  // every vertex a double: nothing to repair
}

}  // namespace
}  // namespace relgeo::test
