// The output of relgeo::boolean as a valid solid in doubles: rounding the
// exact result to its nearest doubles makes it cross itself (the torus-sphere
// union, and each of the three CSG chains within a few steps); the default
// rounding repairs that (mesh/rounding_repair.h), so that every step of a
// 24-step chain is a valid solid, by relgeo's validation and by CGAL's
// does_self_intersect over Epeck, with the nearest rounding's volume.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "boolean_chains.h"
#include "relgeo/boolean.h"
#include "relgeo/mesh/rounding_repair.h"
#include "relgeo/mesh/solid_validation.h"
#include "support/soundness_data.h"
#ifdef RELGEO_TEST_WITH_CGAL
#include "mesh/cgal_epeck_oracle.h"
#endif

namespace relgeo::test {
namespace {

using Op = Boolean_operation;

// 24 steps; 6 in the sanitizer run (RELGEO_TEST_SCALE < 1), which checks
// memory and undefined behaviour, not the chains' length.
int chain_steps() { return test_scale() < 1 ? 6 : 24; }

// The engine before issue 28: the triangulation of the insertion order
// (needles), each new vertex its nearest doubles.
Boolean_options nearest_rounding() {
  Boolean_options o;
  o.rounding = Output_rounding::nearest;
  o.delaunay_retriangulation = false;
  return o;
}

// The repair alone on that triangulation (it has defects to repair).
Boolean_options repair_without_delaunay() {
  Boolean_options o;
  o.delaunay_retriangulation = false;
  return o;
}

double diagonal(const Mesh_double& m) {
  Box_3 b;
  for (const auto& p : m.vertices) b.extend(p.x, p.y, p.z);
  return std::hypot(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]);
}

// The union of the experiment's torus and sphere: nearest doubles cross.
Mesh_double torus_operand() { return torus(1, 0.3, 24, 12); }
Mesh_double sphere_operand() { return rigidly_moved(icosphere(2), 0.3, 0.2, {0, 0, 0.05}); }

template <class K>
class BooleanRounding : public ::testing::Test {};
using Certified_kernels = ::testing::Types<Filtered_exact_kernel, Exact_kernel>;
TYPED_TEST_SUITE(BooleanRounding, Certified_kernels);

TYPED_TEST(BooleanRounding, TheRepairedUnionOfTorusAndSphereIsAValidSolid) {
  const Mesh_double a = torus_operand(), b = sphere_operand();
  // The case is hard: the nearest doubles of the exact result cross.
  const auto nearest = boolean(a, b, Op::union_of, TypeParam{}, nearest_rounding());
  ASSERT_TRUE(nearest.ok()) << nearest.failure;
  EXPECT_GT(nearest.validation.self_intersection_free.count, 0u);
  EXPECT_EQ(nearest.rounding.rounds, 0);

  const auto r = boolean(a, b, Op::union_of, TypeParam{}, repair_without_delaunay());
  ASSERT_TRUE(r.ok()) << r.failure;
  EXPECT_TRUE(r.validation.is_valid_solid()) << r.validation.summary();
  EXPECT_TRUE(r.rounding.converged());
  EXPECT_GE(r.rounding.rounds, 1);
  EXPECT_GE(r.rounding.defects_before, nearest.validation.self_intersection_free.count);
  // The repair moved rounded vertices by a unit in the last place or so.
  EXPECT_GT(r.rounding.moved_vertices + r.rounding.flips + r.rounding.collapses, 0u);
  EXPECT_LE(r.rounding.largest_change, 1e-9 * diagonal(r.mesh));
  EXPECT_LE(r.rounding_error, nearest.rounding_error + r.rounding.largest_change);
  EXPECT_NEAR(r.validation.volume.value, nearest.validation.volume.value, 1e-12 * nearest.validation.volume.value);
  // The per-face and per-vertex data follow the repair's renumbering.
  ASSERT_EQ(r.provenance.size(), r.mesh.faces.size());
  ASSERT_EQ(r.vertex_locations.size(), r.mesh.vertices.size());
  ASSERT_EQ(r.new_vertex_points.size(), r.mesh.vertices.size() - r.first_new_vertex);
  const auto approximate = TypeParam{}.approximate_point_3_object();
  for (Index v = r.first_new_vertex; v < r.mesh.vertices.size(); ++v) {
    const Point_3<double> exact = approximate(r.exact_vertex(v)).point, rounded = r.mesh.vertices[v];
    EXPECT_LE(std::hypot(exact.x - rounded.x, exact.y - rounded.y, exact.z - rounded.z), 2 * r.rounding_error + 1e-300)
        << "vertex " << v;
  }
  for (const Edge& e : r.mesh.tags.creases()) {
    ASSERT_LT(e.a, r.mesh.vertices.size());
    ASSERT_LT(e.b, r.mesh.vertices.size());
  }
}

// ---- the three chains, 24 steps each ---------------------------------------------

struct Chain_run {
  int completed = 0;                // steps whose output is a valid solid
  std::size_t repaired_defects = 0;  // defects the nearest rounding made, over the chain
  std::string stopped;              // why it stopped before the last step
};

// Runs the chain, each output the next operand; stops at the first step that
// fails, is refused or is not a valid solid in doubles. With `check` each
// valid step is also compared with the nearest rounding of the same
// operation (volume) and, with CGAL, checked by CGAL.
Chain_run run_chain(const Boolean_chain& c, const Boolean_options& options, bool check) {
  Chain_run run;
  Mesh_double current = c.start;
  for (std::size_t i = 0; i < c.steps.size(); ++i) {
    const auto& [op, operand] = c.steps[i];
    const std::string step = "step " + std::to_string(i + 1);
    Boolean_result<Filtered_exact_kernel> r;
    try {
      r = boolean(current, operand, op, Filtered_exact_kernel{}, options);
    } catch (const Invalid_operand& e) {
      run.stopped = step + ": refused: " + e.what();
      return run;
    }
    if (!r.ok()) {
      run.stopped = step + ": " + r.failure;
      return run;
    }
    if (!r.validation.is_valid_solid()) {
      run.stopped = step + ": " + r.validation.summary();
      return run;
    }
    run.repaired_defects += r.rounding.defects_before;
    if (check) {
      const auto nearest = boolean(current, operand, op, Filtered_exact_kernel{}, nearest_rounding());
      EXPECT_NEAR(r.validation.volume.value, nearest.validation.volume.value,
                  1e-12 * std::abs(nearest.validation.volume.value))
          << step;
#ifdef RELGEO_TEST_WITH_CGAL
      const relgeo_test::Cgal_solid_verdict cgal = relgeo_test::cgal_epeck_verdict(r.mesh);
      EXPECT_TRUE(cgal.representable && cgal.closed && !cgal.self_intersects) << step << ": CGAL finds it invalid";
#endif
    }
    current = operand_of(r.mesh);
    ++run.completed;
  }
  return run;
}

class BooleanChain : public ::testing::TestWithParam<Chain_family> {};

TEST_P(BooleanChain, NearestRoundingStopsTheChain) {
  // The chains are hard: with nearest doubles a result crosses itself (and
  // would be refused as the next operand) before the 24th step.
  const Chain_run run = run_chain(make_chain(GetParam(), chain_steps()), nearest_rounding(), false);
  EXPECT_LT(run.completed, chain_steps());
  EXPECT_FALSE(run.stopped.empty());
}

TEST_P(BooleanChain, EveryStepIsAValidSolidWithTheRepairAlone) {
  // The insertion order's needles, repaired after rounding: the repair has
  // work on every family and makes every step valid.
  const Chain_run run = run_chain(make_chain(GetParam(), chain_steps()), repair_without_delaunay(), false);
  EXPECT_EQ(run.completed, chain_steps()) << run.stopped;
  EXPECT_GT(run.repaired_defects, 0u);
}

TEST_P(BooleanChain, EveryStepIsAValidSolidWithTheDefaults) {
  // Constrained Delaunay faces and the repair (which may find nothing to do):
  // every step valid, by relgeo and by CGAL, on the exact result's volume.
  const Chain_run run = run_chain(make_chain(GetParam(), chain_steps()), {}, true);
  EXPECT_EQ(run.completed, chain_steps()) << run.stopped;
}

INSTANTIATE_TEST_SUITE_P(Families, BooleanChain,
                         ::testing::Values(Chain_family::drilled_sphere, Chain_family::fused_spheres,
                                           Chain_family::slab_and_boxes),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(BooleanChainExact, TheFusedSpheresUnderTheExactKernel) {
  const Boolean_chain c = make_chain(Chain_family::fused_spheres, chain_steps());
  Mesh_double current = c.start;
  for (std::size_t i = 0; i < c.steps.size(); ++i) {
    const auto r = boolean(current, c.steps[i].second, c.steps[i].first, Exact_kernel{});
    ASSERT_TRUE(r.ok()) << "step " << i + 1 << ": " << r.failure;
    ASSERT_TRUE(r.validation.is_valid_solid()) << "step " << i + 1 << ": " << r.validation.summary();
    current = operand_of(r.mesh);
  }
}

// ---- repair_rounding on its own --------------------------------------------------

TEST(RoundingRepair, NothingMovableNothingToDo) {
  Mesh_double m = icosphere(2);
  const Mesh_double before = m;
  const Rounding_repair_report r = repair_rounding(m, std::vector<char>(m.vertices.size(), 0));
  EXPECT_EQ(r.rounds, 0);
  EXPECT_EQ(r.defects_before, 0u);
  EXPECT_TRUE(r.converged());
  EXPECT_EQ(m.vertices, before.vertices);
  EXPECT_EQ(m.faces, before.faces);
}

TEST(RoundingRepair, RepairsTheNearestRoundingOfABoolean) {
  auto r = boolean(torus_operand(), sphere_operand(), Op::union_of, Filtered_exact_kernel{}, nearest_rounding());
  ASSERT_TRUE(r.ok());
  ASSERT_FALSE(validate_solid(r.mesh).is_valid_solid());
  std::vector<char> movable(r.mesh.vertices.size(), 0);
  for (Index v = r.first_new_vertex; v < movable.size(); ++v) movable[v] = 1;
  const std::size_t faces = r.mesh.faces.size();
  Rounding_repair_maps maps;
  const Rounding_repair_report report = repair_rounding(r.mesh, movable, {}, &maps);
  EXPECT_TRUE(report.converged());
  EXPECT_TRUE(validate_solid(r.mesh).is_valid_solid()) << validate_solid(r.mesh).summary();
  ASSERT_EQ(maps.face_origin.size(), r.mesh.faces.size());
  ASSERT_EQ(maps.vertex_map.size(), movable.size());
  for (Index f : maps.face_origin) EXPECT_LT(f, faces);
}

// The first detection's contract: every crossing pair of faces of which one
// at least has a movable vertex (the other with one or not), and no other.
// Two spheres that cross each other, in one mesh; the repair allowed no
// round, so its remaining pairs are what the detection found. Checked
// against the exact self-intersection test of the whole mesh, with the
// movable vertices those of one sphere, then every third vertex of both.
TEST(RoundingRepair, TheDetectionFindsEveryCrossingOfAFaceWithAMovableVertex) {
  Mesh_double m = icosphere(2);
  const Mesh_double other = icosphere(2, {0.6, 0.25, 0.1}, 0.8);
  const auto first_of_other = static_cast<Index>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const Triangle& t : other.faces)
    m.faces.push_back({t[0] + first_of_other, t[1] + first_of_other, t[2] + first_of_other});
  const std::vector<Face_pair> crossings = find_self_intersections(m).pairs;
  std::size_t one_active = 0, both_active = 0;
  for (const bool every_third : {false, true}) {
    std::vector<char> movable(m.vertices.size(), 0);
    for (Index v = 0; v < m.vertices.size(); ++v) movable[v] = every_third ? v % 3 == 0 : v >= first_of_other;
    const auto active = [&](Index f) {
      return movable[m.faces[f][0]] || movable[m.faces[f][1]] || movable[m.faces[f][2]];
    };
    std::vector<Face_pair> expected;
    for (const Face_pair& p : crossings)
      if (active(p.first) || active(p.second)) {
        expected.push_back(p);
        ++(active(p.first) && active(p.second) ? both_active : one_active);
      }
    Mesh_double copy = m;
    const Rounding_repair_report r = repair_rounding(copy, movable, {.max_rounds = 0});
    EXPECT_EQ(r.defects_before, expected.size()) << every_third;
    EXPECT_EQ(r.remaining_pairs, expected) << every_third;
    EXPECT_EQ(copy.vertices, m.vertices);
  }
  // Both of the detection's searches were needed: pairs of two such faces,
  // and pairs of one such face and another.
  EXPECT_GT(one_active, 0u);
  EXPECT_GT(both_active, 0u);
}

// Each round searches a hierarchy of the faces near its defects only, and
// that of every face once a test leaves them. The repair must be the one
// that searches every face (the code before 2026-11-30) when the hierarchy
// holds every defect's neighbourhood, and when it holds one only: then the
// search of every face finds the rest (without it, the second repair
// differs: the faces a test misses change which position, flip or collapse
// is kept). The case: step 8 of the slab's chain (insertion-order
// triangulation), whose nearest rounding is repaired by moves, flips and
// collapses (step 6 was, until the broad phase's pairs came sorted and
// numbered the new points otherwise; the assertions below say whether the
// case still exercises all three).
TEST(RoundingRepair, TheSearchNearTheDefectsRepairsAsTheSearchOfEveryFace) {
  const Boolean_chain chain = make_chain(Chain_family::slab_and_boxes, 8, /*seed=*/1);
  Mesh_double current = chain.start;
  for (std::size_t i = 0; i + 1 < chain.steps.size(); ++i) {
    const auto step = boolean(current, chain.steps[i].second, chain.steps[i].first, Filtered_exact_kernel{},
                              repair_without_delaunay());
    ASSERT_TRUE(step.ok() && step.validation.is_valid_solid()) << "step " << i + 1;
    current = operand_of(step.mesh);
  }
  const auto r = boolean(current, chain.steps.back().second, chain.steps.back().first, Filtered_exact_kernel{},
                         nearest_rounding());
  ASSERT_TRUE(r.ok());
  std::vector<char> movable(r.mesh.vertices.size(), 0);
  for (Index v = r.first_new_vertex; v < movable.size(); ++v) movable[v] = 1;
  struct Repaired {
    Mesh_double mesh;
    Rounding_repair_maps maps;
    Rounding_repair_report report;
  };
  const auto repaired = [&](std::size_t regions) {
    Repaired x{r.mesh, {}, {}};
    x.report = internal::Rounding_repair(x.mesh, movable, {}, regions).run(x.maps);
    return x;
  };
  const Repaired every_face = repaired(0);  // no region: every test searches every face
  // The case exercises more than moves.
  ASSERT_GT(every_face.report.defects_before, 1u);
  ASSERT_GT(every_face.report.flips, 0u);
  ASSERT_GT(every_face.report.collapses, 0u);
  ASSERT_TRUE(every_face.report.converged());
  const auto creases = [](const Mesh_double& m) {
    return std::vector<Edge>(m.tags.creases().begin(), m.tags.creases().end());
  };
  for (const std::size_t regions : {std::numeric_limits<std::size_t>::max(), std::size_t{1}}) {
    const Repaired near = repaired(regions);
    SCOPED_TRACE("regions " + std::to_string(regions));
    EXPECT_EQ(near.mesh.vertices, every_face.mesh.vertices);
    EXPECT_EQ(near.mesh.faces, every_face.mesh.faces);
    EXPECT_EQ(creases(near.mesh), creases(every_face.mesh));
    EXPECT_EQ(near.maps.vertex_map, every_face.maps.vertex_map);
    EXPECT_EQ(near.maps.face_origin, every_face.maps.face_origin);
    EXPECT_EQ(near.report.rounds, every_face.report.rounds);
    EXPECT_EQ(near.report.moved_vertices, every_face.report.moved_vertices);
    EXPECT_EQ(near.report.flips, every_face.report.flips);
    EXPECT_EQ(near.report.collapses, every_face.report.collapses);
    EXPECT_EQ(near.report.largest_change, every_face.report.largest_change);
  }
}

TEST(RoundingRepair, GivesUpAfterItsRoundsAndSaysWhatIsLeft) {
  // Zero rounds allowed: the defects are found and reported, nothing changed.
  auto r = boolean(torus_operand(), sphere_operand(), Op::union_of, Filtered_exact_kernel{}, nearest_rounding());
  ASSERT_TRUE(r.ok());
  std::vector<char> movable(r.mesh.vertices.size(), 0);
  for (Index v = r.first_new_vertex; v < movable.size(); ++v) movable[v] = 1;
  const Rounding_repair_report report = repair_rounding(r.mesh, movable, {.max_rounds = 0});
  EXPECT_FALSE(report.converged());
  EXPECT_EQ(report.remaining_pairs.size() + report.remaining_degenerate_faces.size(), report.defects_before);
  EXPECT_EQ(report.remaining_pairs.size(), validate_solid(r.mesh).self_intersection_free.count);

  // The Boolean fails then, naming the rounding, and still hands the mesh over.
  Boolean_options o = repair_without_delaunay();
  o.repair.max_rounds = 0;
  const auto failed = boolean(torus_operand(), sphere_operand(), Op::union_of, Filtered_exact_kernel{}, o);
  EXPECT_FALSE(failed.ok());
  EXPECT_EQ(failed.failure.rfind("rounding:", 0), 0u) << failed.failure;
  EXPECT_FALSE(failed.mesh.faces.empty());
}

TEST(RoundingRepair, BadInputIsRefused) {
  Mesh_double m = icosphere(1);
  EXPECT_THROW(repair_rounding(m, std::vector<char>(3, 1)), Precondition_violation);
  Mesh_double out_of_range = m;
  out_of_range.faces[0][1] = static_cast<Index>(m.vertices.size());
  EXPECT_THROW(repair_rounding(out_of_range, std::vector<char>(m.vertices.size(), 1)), Invalid_input);
  Mesh_double not_finite = m;
  not_finite.vertices[2].y = std::nan("");
  EXPECT_THROW(repair_rounding(not_finite, std::vector<char>(m.vertices.size(), 1)), Invalid_input);
  for (const double tolerance : {std::nan(""), -1e-9, std::numeric_limits<double>::infinity()})
    EXPECT_THROW(repair_rounding(m, std::vector<char>(m.vertices.size(), 1), {.tolerance = tolerance}), Invalid_input)
        << tolerance;
}

// A tolerance whose margin around the defects overflows: the repair searches
// every face instead of failing (the regions of its hierarchy are not finite).
TEST(RoundingRepair, AHugeToleranceStillRepairs) {
  auto r = boolean(torus_operand(), sphere_operand(), Op::union_of, Filtered_exact_kernel{}, nearest_rounding());
  ASSERT_TRUE(r.ok());
  std::vector<char> movable(r.mesh.vertices.size(), 0);
  for (Index v = r.first_new_vertex; v < movable.size(); ++v) movable[v] = 1;
  Rounding_repair_report report;
  ASSERT_NO_THROW(report = repair_rounding(r.mesh, movable, {.tolerance = 1e308}));
  EXPECT_GT(report.rounds, 0);
  EXPECT_TRUE(report.converged());
}

}  // namespace
}  // namespace relgeo::test
