// relgeo::boolean on configurations built exactly (boxes with dyadic corners:
// every volume is exact) and in general position (spheres, a torus), under
// every kernel: exact kernels give the exact volume and a valid solid;
// certified kernels the same or an honest failure; naive kernels never
// crash or hang. Bad operands are refused with the defect named.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "boolean_inputs.h"
#include "mesh/solid_fixtures.h"
#include "relgeo/boolean.h"
#include "relgeo/kernel.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/validity.h"
#include "support/implicit_oracle.h"
#include "support/undecided_order_kernel.h"

namespace relgeo::test {
namespace {

using Op = Boolean_operation;
constexpr Op kOps[] = {Op::union_of, Op::intersection, Op::difference, Op::symmetric_difference};

struct Box_case {
  std::string name;
  Mesh b;
  double overlap;         // vol(A n B), A the unit cube
  bool manifold_union;    // the union is a 2-manifold (not touching along an edge or at a vertex)
};

std::vector<Box_case> box_cases() {
  return {
      {"offset", box(0.5, 0.25, 0.125, 1, 1, 1), 0.5 * 0.75 * 0.875, true},
      {"coplanar-faces", box(0.5, 0, 0, 1, 1, 1), 0.5, true},
      {"coplanar-partial", box(0.5, 0.5, 0, 1, 1, 1), 0.25, true},
      {"touching-face", box(1, 0, 0, 1, 1, 1), 0, true},
      {"touching-partial-face", box(1, 0.5, 0.25, 1, 1, 1), 0, true},
      {"touching-edge", box(1, 1, 0, 1, 1, 1), 0, false},
      {"touching-vertex", box(1, 1, 1, 1, 1, 1), 0, false},
      {"identical", cube(0, 0, 0, 1), 1, true},
      {"nested", box(0.25, 0.25, 0.25, 0.5, 0.5, 0.5), 0.125, true},
      {"nested-touching", box(0, 0.25, 0.25, 0.5, 0.5, 0.5), 0.125, true},
      {"disjoint", box(3, 3, 3, 1, 1, 1), 0, true},
      {"through", box(0.25, 0.25, -1, 0.5, 0.5, 3), 0.25, true},
  };
}

double expected_volume(Op op, double a, double b, double overlap) {
  switch (op) {
    case Op::union_of: return a + b - overlap;
    case Op::intersection: return overlap;
    case Op::difference: return a - overlap;
    case Op::symmetric_difference: return a + b - 2 * overlap;
  }
  return 0;
}

template <class K>
class MeshBoolean : public ::testing::Test {};
using Kernels = ::testing::Types<Filtered_exact_kernel, Exact_kernel, Interval_kernel, Failsafe_kernel<double>,
                                 Naive_kernel<double>>;
TYPED_TEST_SUITE(MeshBoolean, Kernels);

TYPED_TEST(MeshBoolean, BoxesInEveryDegenerateConfiguration) {
  using K = TypeParam;
  const Mesh a = cube(0, 0, 0, 1);
  std::size_t failed = 0, runs = 0;
  for (const auto& c : box_cases())
    for (Op op : kOps) {
      ++runs;
      const auto r = boolean(a, c.b, op, K{});
      if constexpr (!K::is_certified) continue;  // any answer, no crash
      if (!r.ok()) {
        EXPECT_FALSE(K::has_exact_predicates) << c.name << " " << to_string(op) << ": " << r.failure;
        ++failed;
        continue;
      }
      // The exact volume of the output (of its doubles; of the exact result
      // under Exact_kernel): the exact result's, 1, 0.25 or 0.125 here, when
      // no new vertex was rounded. Where a box's face diagonal crosses the
      // cube's plane the new vertex is not dyadic (x = 7/12: "through");
      // moving each vertex by at most rounding_error per coordinate changes
      // the volume by at most about sqrt(3) rounding_error times the area
      // (doubled for the higher-order terms).
      const double rounded = 2 * std::sqrt(3.0) * r.rounding_error * area(r.mesh);
      ASSERT_TRUE(r.validation.volume.exact) << c.name;
      EXPECT_NEAR(r.validation.volume.value, expected_volume(op, 1, volume(c.b), c.overlap), rounded)
          << c.name << " " << to_string(op);
      if (K::has_exact_predicates) {  // new vertices within 4 ulps (|x| <= 2 here)
        EXPECT_LE(r.rounding_error, 0x1p-49) << c.name;
      }
      const Mesh_report report = check_mesh(r.mesh);
      const bool manifold_expected = op != Op::symmetric_difference && (op != Op::union_of || c.manifold_union);
      if (manifold_expected) EXPECT_TRUE(report.is_valid()) << c.name << " " << to_string(op) << " " << to_string(report.issues.front());
      else EXPECT_TRUE(report.is_closed() && report.is_consistently_oriented()) << c.name << " " << to_string(op);
      EXPECT_EQ(r.provenance.size(), r.mesh.faces.size());
    }
  if (K::has_exact_predicates) {
    EXPECT_EQ(failed, 0u);
  }
  std::printf("[ %s ] %zu box Booleans, %zu honest failures\n", K::name().c_str(), runs, failed);
}

// Curved operands in general position: union + intersection = A + B, and
// difference = A - intersection, exactly up to the rounding of new vertices.
TYPED_TEST(MeshBoolean, SpheresAndTorusInGeneralPosition) {
  using K = TypeParam;
  const std::vector<std::pair<std::string, std::pair<Mesh, Mesh>>> cases{
      {"spheres", {icosphere(3), icosphere(3, {0.6, 0.3, 0.2}, 0.9)}},
      {"torus-sphere", {torus(1, 0.4, 32, 16), icosphere(3, {1, 0, 0.1}, 0.5)}},
      {"sphere-through-torus", {torus(1, 0.3, 24, 12), rigidly_moved(icosphere(2), 0.3, 0.2, {0, 0, 0.05})}},
  };
  for (const auto& [name, ab] : cases) {
    const auto& [a, b] = ab;
    std::array<double, 4> v{};
    bool all_ok = true;
    for (int i = 0; i < 4; ++i) {
      const auto r = boolean(a, b, kOps[i], K{});
      if constexpr (!K::is_certified) {
        all_ok = false;
        continue;
      }
      if (!r.ok()) {
        EXPECT_FALSE(K::has_exact_predicates) << name << ": " << r.failure;
        all_ok = false;
        continue;
      }
      v[i] = volume(r.mesh);
      // The exact result is a closed oriented manifold; its doubles may
      // collapse a sliver (rounding_error says how far they moved), so only
      // the combinatorial checks are asserted on the rounded mesh.
      const Mesh_report report = check_mesh(r.mesh);
      if (kOps[i] != Op::symmetric_difference) {
        EXPECT_TRUE(report.is_closed() && report.is_manifold() && report.is_consistently_oriented())
            << name << " " << to_string(kOps[i]);
      }
      EXPECT_GT(r.counts.new_vertices, 0u);
      EXPECT_FALSE(r.mesh.tags.creases().empty()) << "the intersection curves are creases";
      if (kOps[i] == Op::union_of || kOps[i] == Op::intersection) {
        // Each new vertex counted once, however many face pairs reached it:
        // in a union or an intersection every one ends a crease.
        std::set<Index> new_on_creases;
        for (const Edge& e : r.mesh.tags.creases())
          for (const Index v : {e.a, e.b})
            if (r.vertex_locations[v][0].kind != Surface_location::Kind::vertex &&
                r.vertex_locations[v][1].kind != Surface_location::Kind::vertex)
              new_on_creases.insert(v);
        EXPECT_EQ(new_on_creases.size(), r.counts.new_vertices) << name << " " << to_string(kOps[i]);
      }
    }
    if (!all_ok) continue;
    const double scale = volume(a) + volume(b);
    EXPECT_NEAR(v[0] + v[1], scale, 1e-12 * scale) << name;
    EXPECT_NEAR(v[2], volume(a) - v[1], 1e-12 * scale) << name;
    EXPECT_NEAR(v[3], v[0] - v[1], 1e-12 * scale) << name;
  }
}

// The output's vertices: the input vertices it keeps, exactly, then the new
// ones, held as the kernel's points; under the exact kernel each new vertex
// is within rounding_error of its exact point, and that error is an ulp or
// two (the coordinates are below 2).
TYPED_TEST(MeshBoolean, OutputVerticesAreTheKeptInputVerticesThenTheNewOnes) {
  using K = TypeParam;
  if constexpr (K::is_certified) {
    const Mesh a = torus(1, 0.4, 32, 16), b = icosphere(3, {1, 0, 0.1}, 0.5);
    for (Op op : kOps) {
      const auto r = boolean(a, b, op, K{});
      if (!r.ok()) {
        EXPECT_FALSE(K::has_exact_predicates) << r.failure;
        continue;
      }
      ASSERT_LT(r.first_new_vertex, r.mesh.vertices.size()) << to_string(op);
      EXPECT_EQ(r.new_vertex_points.size(), r.mesh.vertices.size() - r.first_new_vertex) << to_string(op);
      for (Index i = 0; i < r.mesh.vertices.size(); ++i) {
        const auto& where = r.vertex_locations[i];
        const int input = where[0].kind == Surface_location::Kind::vertex ? 0
                          : where[1].kind == Surface_location::Kind::vertex ? 1
                                                                             : -1;
        if (i < r.first_new_vertex) {
          ASSERT_NE(input, -1) << to_string(op) << " vertex " << i << " is not an input vertex";
          const Mesh& m = input == 0 ? a : b;
          EXPECT_EQ(r.mesh.vertices[i], m.vertices[where[input].vertices[0]]) << to_string(op) << " vertex " << i;
          EXPECT_EQ(K::implicit_kind(r.exact_vertex(i)), Implicit_point_kind::explicit_point);
        } else {
          EXPECT_EQ(input, -1) << to_string(op) << " new vertex " << i << " is an input vertex";
          EXPECT_NE(K::implicit_kind(r.exact_vertex(i)), Implicit_point_kind::explicit_point);
        }
      }
      if constexpr (std::is_same_v<K, Exact_kernel>) {
        // An ulp or two, plus what the repair of the rounding moved (xor
        // touches itself along its curves: rounding can make it cross there).
        EXPECT_LE(r.rounding_error, 0x1p-50 + r.rounding.largest_change) << to_string(op);
        const mpq_class error(r.rounding_error);
        for (Index i = r.first_new_vertex; i < r.mesh.vertices.size(); ++i) {
          const Point_3<mpq_class>& exact = r.exact_vertex(i).point;
          const Point_3<double>& rounded = r.mesh.vertices[i];
          EXPECT_LE(abs(mpq_class(rounded.x) - exact.x), error) << i;
          EXPECT_LE(abs(mpq_class(rounded.y) - exact.y), error) << i;
          EXPECT_LE(abs(mpq_class(rounded.z) - exact.z), error) << i;
        }
      }
    }
  }
}

// Exact_kernel runs through its Double_point_kernel hook by default; its own
// rational arithmetic (the reference path) must give the same faces and the
// same exact vertices. Compared with nearest rounding: the hook's doubles are
// the filtered kernel's (within its rounding_error, not always the nearest),
// so the repair of the rounding may act on different doubles; with the
// defaults both outputs must be valid whenever the exact result is.
TEST(MeshBooleanExact, TheDoublePointHookGivesTheReferenceResult) {
  std::vector<std::pair<Mesh, Mesh>> cases{{cube(0, 0, 0, 1), box(0.5, 0.25, 0.125, 1, 1, 1)},
                                           {cube(0, 0, 0, 1), box(0.5, 0, 0, 1, 1, 1)},
                                           {icosphere(1), icosphere(1, {0.4, 0.3, 0.1}, 0.8)},
                                           {torus(1, 0.4, 12, 8), icosphere(1, {1, 0, 0.1}, 0.5)}};
  for (const auto& [a, b] : cases)
    for (Op op : kOps) {
      const auto hook = boolean(a, b, op, Exact_kernel{}, Boolean_options{.rounding = Output_rounding::nearest});
      const auto own = boolean(a, b, op, Exact_kernel{},
                               Boolean_options{.use_double_point_kernel = false, .rounding = Output_rounding::nearest});
      ASSERT_TRUE(hook.ok() && own.ok());
      if (op != Op::symmetric_difference) {
        const auto hook_repaired = boolean(a, b, op, Exact_kernel{});
        const auto own_repaired = boolean(a, b, op, Exact_kernel{}, Boolean_options{.use_double_point_kernel = false});
        EXPECT_TRUE(hook_repaired.validation.is_valid_solid()) << to_string(op) << hook_repaired.validation.summary();
        EXPECT_TRUE(own_repaired.validation.is_valid_solid()) << to_string(op) << own_repaired.validation.summary();
      }
      EXPECT_EQ(hook.mesh.faces, own.mesh.faces) << to_string(op);
      EXPECT_EQ(hook.first_new_vertex, own.first_new_vertex) << to_string(op);
      ASSERT_EQ(hook.mesh.vertices.size(), own.mesh.vertices.size());
      for (Index i = 0; i < own.mesh.vertices.size(); ++i)
        EXPECT_EQ(hook.exact_vertex(i).point, own.exact_vertex(i).point) << to_string(op) << " vertex " << i;
    }
}

// A tetrahedron of subnormal size in the corner of the unit one (three
// coplanar overlaps): its faces' normals underflow to zero in doubles, so
// the double heuristic for the projection axis chose one along which a face
// is degenerate and the retriangulation failed on valid operands (fuzzing
// finding, fuzz/corpus/mesh_boolean/regression_subnormal_face_projection).
// The axis is now one the kernel certifies; the volumes are exact.
TEST(MeshBooleanDegenerate, AFaceOfSubnormalSizeIsProjectedAlongACertifiedAxis) {
  const auto tetrahedron = [](double s) {
    Mesh m;
    m.vertices = {{0, 0, 0}, {s, 0, 0}, {0, s, 0}, {0, 0, s}};
    m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
  };
  const double tiny = 16384 * std::numeric_limits<double>::denorm_min();  // 8.1e-320
  const Mesh a = tetrahedron(1), b = tetrahedron(tiny);
  const auto volume_of = [](const Boolean_result<Exact_kernel>& r) {
    mpq_class v = 0;
    const auto p = r.exact_vertices();
    for (const Triangle& f : r.mesh.faces) {
      const auto &x = p[f[0]].point, &y = p[f[1]].point, &z = p[f[2]].point;
      v += x.x * (y.y * z.z - y.z * z.y) - x.y * (y.x * z.z - y.z * z.x) + x.z * (y.x * z.y - y.y * z.x);
    }
    return mpq_class(v / 6);
  };
  const mpq_class va(1, 6), vb = mpq_class(tiny) * mpq_class(tiny) * mpq_class(tiny) / 6;
  const mpq_class expected[] = {va, vb, va - vb};
  const Op ops[] = {Op::union_of, Op::intersection, Op::difference};
  for (int i = 0; i < 3; ++i) {
    const auto exact = boolean(a, b, ops[i], Exact_kernel{});
    ASSERT_TRUE(exact.ok()) << to_string(ops[i]) << ": " << exact.failure;
    EXPECT_EQ(volume_of(exact), expected[i]) << to_string(ops[i]);
    const auto filtered = boolean(a, b, ops[i], Filtered_exact_kernel{});
    ASSERT_TRUE(filtered.ok()) << to_string(ops[i]) << ": " << filtered.failure;
    EXPECT_EQ(filtered.mesh.faces, exact.mesh.faces) << to_string(ops[i]);
  }
}

// Operands scaled by 2^-600 or 2^600: still normal doubles, exactly the
// scaled operands, but the predicates' products underflow or overflow in
// doubles. The exact kernels give the unscaled result scaled: the same faces,
// exact vertices times the same power of two (the filtered kernel's
// approximations of new vertices may then differ by an ulp: they are within
// its rounding_error, not nearest). The naive kernel's orientations vanish on
// valid faces: it fails with the pair named, where it threw before.
TEST(MeshBooleanDegenerate, OperandsScaledByAPowerOfTwoGiveTheScaledResult) {
  const Mesh a = cube(0, 0, 0, 1), b = rigidly_moved(icosphere(2, {0, 0, 0}, 0.7), 0.5, 0.3, {0.6, 0.5, 0.4});
  const auto scaled = [](Mesh m, int e) {
    for (auto& p : m.vertices) p = {std::ldexp(p.x, e), std::ldexp(p.y, e), std::ldexp(p.z, e)};
    return m;
  };
  const auto times_power_of_two = [](const mpq_class& q, int e) {
    mpq_class r;
    if (e >= 0) mpq_mul_2exp(r.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    else mpq_div_2exp(r.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
    return r;
  };
  // The exact results compared (nearest rounding: the repair acts on the
  // doubles, which may differ by an ulp); the defaults' outputs valid.
  const Boolean_options nearest{.rounding = Output_rounding::nearest};
  for (Op op : {Op::union_of, Op::intersection, Op::difference}) {
    const auto unscaled = boolean(a, b, op, Exact_kernel{}, nearest);
    ASSERT_TRUE(unscaled.ok()) << to_string(op) << ": " << unscaled.failure;
    for (int e : {-600, 600}) {
      const std::string what = std::string(to_string(op)) + " at 2^" + std::to_string(e);
      const Mesh as = scaled(a, e), bs = scaled(b, e);
      const auto exact = boolean(as, bs, op, Exact_kernel{}, nearest);
      ASSERT_TRUE(exact.ok()) << what << ": " << exact.failure;
      ASSERT_EQ(exact.mesh.faces, unscaled.mesh.faces) << what;
      const auto p = exact.exact_vertices(), q = unscaled.exact_vertices();
      for (std::size_t v = 0; v < p.size(); ++v) {
        EXPECT_EQ(p[v].point.x, times_power_of_two(q[v].point.x, e)) << what << ", vertex " << v;
        EXPECT_EQ(p[v].point.y, times_power_of_two(q[v].point.y, e)) << what << ", vertex " << v;
        EXPECT_EQ(p[v].point.z, times_power_of_two(q[v].point.z, e)) << what << ", vertex " << v;
      }
      const auto exact_repaired = boolean(as, bs, op, Exact_kernel{});
      EXPECT_TRUE(exact_repaired.validation.is_valid_solid()) << what << ": " << exact_repaired.validation.summary();
      const auto filtered = boolean(as, bs, op, Filtered_exact_kernel{}, nearest);
      ASSERT_TRUE(filtered.ok()) << what << ": " << filtered.failure;
      EXPECT_EQ(filtered.mesh.faces, unscaled.mesh.faces) << what;
      const auto filtered_repaired = boolean(as, bs, op);
      EXPECT_TRUE(filtered_repaired.validation.is_valid_solid()) << what << ": " << filtered_repaired.validation.summary();
      const auto naive = boolean(as, bs, op, Naive_kernel<double>{});
      EXPECT_FALSE(naive.ok()) << what;
      EXPECT_NE(naive.failure.find("degenerate in the kernel's arithmetic"), std::string::npos) << naive.failure;
    }
  }
}

// The checks and the broad phase run on several threads when TBB is there
// (this test's target links it): the same result, face for face; and a
// self-intersecting operand found by the parallel test is refused alike.
// The fail-safe Boolean gives the exact result or fails naming the pairs it
// cannot decide: it never moves a vertex (the thesis' eq. 5.3 applied to one
// pair and not to the others sharing the vertex makes an arrangement of no
// operand at all). Here B's vertex lies one ulp above the plane of A's face,
// within the fail-safe kernel's ambiguity zone; intersect_triangles alone
// moves it and decides the pair (eq. 5.3), the Boolean does not. (Before,
// the narrow phase took such per-pair moves, counted two here, and the
// Boolean failed on the pairs the moves did not settle; no input was found
// where it returned a result after a move.)
TEST(MeshBooleanFailsafe, APairDecidedOnlyByMovingAVertexIsAFailureNamingIt) {
  const Mesh a = tetrahedron({Point_3<double>{0, 0, 0}, {4, 0, 4}, {0, 4, 4}, {4, 4, 0}});  // a face on z = x + y
  const Mesh b = tetrahedron({Point_3<double>{1, 1, 0x1.0000000000001p+1}, {3, -2, 5}, {1, 1, 6}, {-1, 3, 7}});
  const Failsafe_kernel<double> k;
  // The pair alone: decided after moving B's first vertex.
  const auto point = k.construct_point_3_object();
  const auto triangle = [&](const Mesh& m, Index f) {
    std::array<Point_3<double>, 3> t;
    for (int i = 0; i < 3; ++i) t[i] = m.vertices[m.faces[f][i]];
    for (auto& v : t) v = point(v.x, v.y, v.z);
    return t;
  };
  std::size_t moved = 0;
  for (Index fa = 0; fa < a.faces.size(); ++fa)
    for (Index fb = 0; fb < b.faces.size(); ++fb) moved += !intersect_triangles(triangle(a, fa), triangle(b, fb), k).perturbations.empty();
  ASSERT_GT(moved, 0u) << "no pair needs the fail-safe move: the case is not hard";
  for (Op op : kOps) {
    const auto exact = boolean(a, b, op, Filtered_exact_kernel{});
    ASSERT_TRUE(exact.ok()) << exact.failure;
    const auto r = boolean(a, b, op, k);
    if (r.ok()) {  // then the exact result, face for face
      EXPECT_EQ(r.mesh.faces, exact.mesh.faces) << to_string(op);
      EXPECT_EQ(r.mesh.vertices, exact.mesh.vertices) << to_string(op);
      continue;
    }
    EXPECT_FALSE(r.undecided_pairs.empty()) << to_string(op) << ": " << r.failure;
    EXPECT_NE(r.failure.find("cannot decide"), std::string::npos) << r.failure;
  }
  // The exact kernel's answer: B lies above A's face, touching nothing.
  EXPECT_EQ(boolean(a, b, Op::intersection).mesh.faces.size(), 0u);
}

// A certified kernel that cannot order two distinct points (test/support/
// undecided_order_kernel.h): the Boolean gives the exact result or fails
// saying it could not order points; no `uncertain` reaches a sort (before,
// std::sort received comparators answering false for `uncertain`, which is
// no strict weak ordering: undefined behaviour).
TEST(MeshBooleanUncertainty, AnUndecidedOrderIsAReportedFailure) {
  const Mesh a = cube(0, 0, 0, 1);
  std::size_t failed = 0, exact_results = 0;
  for (const auto& c : box_cases())
    for (Op op : kOps) {
      const auto r = boolean(a, c.b, op, Undecided_order_kernel{});
      const auto e = boolean(a, c.b, op, Filtered_exact_kernel{});
      if (!r.ok()) {
        ++failed;
        EXPECT_TRUE(r.failure.find("order") != std::string::npos || r.failure.find("cannot decide") != std::string::npos)
            << c.name << " " << to_string(op) << ": " << r.failure;
        continue;
      }
      ++exact_results;
      EXPECT_EQ(r.mesh.faces, e.mesh.faces) << c.name << " " << to_string(op);
      EXPECT_EQ(r.mesh.vertices, e.mesh.vertices) << c.name << " " << to_string(op);
    }
  std::printf("[ undecided-order ] %zu box Booleans failed honestly, %zu exact\n", failed, exact_results);
  EXPECT_GT(failed, 0u);
}

TEST(MeshBooleanThreads, TheResultDoesNotDependOnTheThreadCount) {
  const Mesh a = icosphere(4), b = icosphere(4, {0.4, 0.3, 0.2}, 0.9);
  for (Op op : kOps) {
    const auto serial = boolean(a, b, op);
    const auto parallel = boolean(a, b, op, Filtered_exact_kernel{}, Boolean_options{.threads = 2});
    ASSERT_TRUE(serial.ok() && parallel.ok()) << to_string(op);
    EXPECT_EQ(serial.mesh.faces, parallel.mesh.faces) << to_string(op);
    EXPECT_EQ(serial.mesh.vertices.size(), parallel.mesh.vertices.size()) << to_string(op);
    EXPECT_TRUE(std::ranges::equal(serial.mesh.tags.creases(), parallel.mesh.tags.creases())) << to_string(op);
    EXPECT_EQ(serial.counts.candidate_pairs, parallel.counts.candidate_pairs) << to_string(op);
  }
  // A sphere against a copy turned by a few hundredths of a radian: the two
  // surfaces nearly coincide, so the narrow phase has several of its blocks
  // of pairs (16384), and the retriangulation several of its blocks of split
  // faces (1024), each split between the threads.
  const Mesh turned = rigidly_moved(a, 0.05, 0.03, {0.002, 0.001, 0});
  const auto serial = boolean(a, turned, Op::union_of);
  const auto parallel = boolean(a, turned, Op::union_of, Filtered_exact_kernel{}, Boolean_options{.threads = 2});
  ASSERT_TRUE(serial.ok() && parallel.ok());
  EXPECT_GT(serial.counts.candidate_pairs, 2u * 16384);
  EXPECT_GT(serial.counts.split_faces, 2u * 1024);
  EXPECT_EQ(serial.counts.split_faces, parallel.counts.split_faces);
  EXPECT_EQ(serial.provenance, parallel.provenance);
  EXPECT_EQ(serial.validation.summary(), parallel.validation.summary());  // the validation on the threads too
  EXPECT_TRUE(parallel.validation.is_valid_solid());
  EXPECT_EQ(serial.mesh.faces, parallel.mesh.faces);
  EXPECT_EQ(serial.mesh.vertices, parallel.mesh.vertices);
  EXPECT_EQ(serial.counts.intersecting_pairs, parallel.counts.intersecting_pairs);
  Mesh crossing = a;
  const auto v0 = crossing.vertices[0];
  crossing.vertices[0] = {-1.5 * v0.x, -1.5 * v0.y, -1.5 * v0.z};  // pulled through the far side
  for (int threads : {1, 2}) {
    try {
      (void)boolean(crossing, b, Op::union_of, Filtered_exact_kernel{}, Boolean_options{.threads = threads});
      ADD_FAILURE() << "a self-intersecting operand was accepted on " << threads << " threads";
    } catch (const Invalid_operand& e) {
      EXPECT_EQ(e.operand(), "A");
      EXPECT_TRUE(std::any_of(e.issues().begin(), e.issues().end(),
                              [](const Mesh_issue& i) { return i.defect == Mesh_defect::self_intersection; }));
    }
  }
}

// The broad phase searches the operands' hierarchies against each other:
// with the checks on, those the checks built (clustered by projected
// patch); without them, built there (Morton order only). The pairs' order
// decides the new vertices' numbers and, on cocircular points, the Delaunay
// faces: the pairs are sorted, for the Boolean not to depend on which
// hierarchies it searched.
TEST(MeshBooleanBroadPhase, TheBooleanDoesNotDependOnWhetherTheChecksRan) {
  const Mesh a = icosphere(4);
  const Mesh turned = rigidly_moved(a, 0.05, 0.03, {0.002, 0.001, 0});
  for (Op op : kOps) {
    const auto checked = boolean(a, turned, op);
    const auto unchecked = boolean(a, turned, op, Filtered_exact_kernel{},
                                   Boolean_options{.check_operands = false, .check_self_intersections = false});
    ASSERT_TRUE(checked.ok() && unchecked.ok()) << to_string(op);
    EXPECT_EQ(checked.counts.checked_operands, 2u);
    EXPECT_EQ(unchecked.counts.checked_operands, 0u);
    EXPECT_EQ(checked.counts.candidate_pairs, unchecked.counts.candidate_pairs) << to_string(op);
    EXPECT_EQ(checked.mesh.faces, unchecked.mesh.faces) << to_string(op);
    EXPECT_EQ(checked.mesh.vertices, unchecked.mesh.vertices) << to_string(op);
    EXPECT_EQ(checked.provenance, unchecked.provenance) << to_string(op);
  }
}

// With certified operands the validation searches a hierarchy of the open
// faces only, and builds one of all the faces for the orientation test of
// several components alone. A cavity (a cube minus a box inside it), two
// shells (disjoint cubes), and two shells one of which was cut (an operand
// of two cubes, a box through one of them): each component is oriented by
// its nesting, as the validation without certificates finds. (Without a
// hierarchy of all the faces every component looks unnested: the cavity
// would be misoriented.)
TEST(MeshBooleanValidation, SeveralComponentsAreOrientedWithCertifiedOperands) {
  const Mesh two_cubes = relgeo_test::disjoint_union(cube(0, 0, 0, 1), cube(3, 0, 0, 1));
  const struct {
    const char* name;
    Mesh a, b;
    Op op;
    int cavities;  // components of negative volume, inside another
  } cases[] = {
      {"cavity", cube(0, 0, 0, 1), box(0.25, 0.25, 0.25, 0.5, 0.5, 0.5), Op::difference, 1},
      {"disjoint shells", cube(0, 0, 0, 1), box(3, 3, 3, 1, 1, 1), Op::union_of, 0},
      {"a cut shell and a whole one", two_cubes, box(0.5, 0.25, 0.125, 1, 1, 1), Op::union_of, 0},
  };
  for (const auto& c : cases) {
    const auto r = boolean(c.a, c.b, c.op);
    ASSERT_TRUE(r.ok()) << c.name;
    EXPECT_GT(r.counts.unchanged_certified_faces, 0u) << c.name;
    EXPECT_EQ(r.validation.components, 2u) << c.name;
    EXPECT_TRUE(r.validation.outward_oriented.passed()) << c.name << ": " << r.validation.summary();
    EXPECT_TRUE(r.validation.is_valid_solid()) << c.name;
    int negative = 0, nested = 0;
    for (const Solid_component& sc : r.validation.component_list) {
      ASSERT_TRUE(sc.winding.has_value()) << c.name;
      negative += sc.volume < 0, nested += *sc.winding == 1;
    }
    EXPECT_EQ(negative, c.cavities) << c.name;
    EXPECT_EQ(nested, c.cavities) << c.name;
    const Solid_report full = validate_solid(r.mesh);
    EXPECT_EQ(full.outward_oriented.status, r.validation.outward_oriented.status) << c.name;
    EXPECT_EQ(full.self_intersection_free.status, r.validation.self_intersection_free.status) << c.name;
  }
}

TEST(MeshBooleanOperands, BadOperandsAreRefusedWithTheDefect) {
  const Mesh good = cube(0, 0, 0, 1);
  const auto defect_of = [&](const Mesh& bad) -> Mesh_defect {
    try {
      (void)boolean(good, bad, Op::union_of);
    } catch (const Invalid_operand& e) {
      EXPECT_EQ(e.operand(), "B");
      return e.defect();
    }
    ADD_FAILURE() << "not refused";
    return Mesh_defect::undecided;
  };
  Mesh open = cube(2, 0, 0, 1);
  open.faces.pop_back();
  EXPECT_EQ(defect_of(open), Mesh_defect::boundary_edge);
  Mesh flipped = cube(2, 0, 0, 1);
  std::swap(flipped.faces[0][1], flipped.faces[0][2]);
  EXPECT_EQ(defect_of(flipped), Mesh_defect::inconsistent_orientation);
  Mesh nan = cube(2, 0, 0, 1);
  nan.vertices[3].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(defect_of(nan), Mesh_defect::non_finite_coordinate);
  Mesh nonmanifold = cube(2, 0, 0, 1);  // a second cube glued to it along one edge's two faces
  const Mesh extra = cube(2, 0, 0, 1);
  for (const auto& f : extra.faces) nonmanifold.faces.push_back(f);
  EXPECT_NE(defect_of(nonmanifold), Mesh_defect::undecided);
  // Two cubes crossing each other in one mesh: a self-intersecting operand.
  Mesh crossing = cube(2, 0, 0, 1);
  const Mesh other = cube(2.5, 0.5, 0.5, 1);
  for (const auto& p : other.vertices) crossing.vertices.push_back(p);
  for (const auto& f : other.faces) crossing.faces.push_back({f[0] + 8, f[1] + 8, f[2] + 8});
  EXPECT_EQ(defect_of(crossing), Mesh_defect::self_intersection);
  // Nothing is checked when asked not to (and then the result may be anything).
  EXPECT_NO_THROW((void)boolean(good, crossing, Op::union_of, Filtered_exact_kernel{},
                                Boolean_options{.check_operands = false}));
  // But an index out of range or a non-finite coordinate still gets a typed
  // error from the broad phase, in either operand (A's face boxes, B's
  // hierarchy), never a read out of bounds.
  Mesh bad_index = cube(2, 0, 0, 1);
  bad_index.faces[4][1] = 99;
  for (const Mesh* bad : {&bad_index, &nan}) {
    EXPECT_THROW((void)boolean(*bad, good, Op::union_of, Filtered_exact_kernel{}, Boolean_options{.check_operands = false}),
                 Invalid_mesh);
    EXPECT_THROW((void)boolean(good, *bad, Op::union_of, Filtered_exact_kernel{}, Boolean_options{.check_operands = false}),
                 Invalid_mesh);
  }
}

// The exact crossing points of the segments of one mesh's faces with the
// other mesh's faces (both ways, coplanar segments left out), less the input
// vertices: the points a Boolean of the two must number once each. From the
// independent oracle (support/implicit_oracle.h: its orientations, and the
// LPI point by Gaussian elimination in rationals).
std::set<std::array<mpq_class, 3>> crossing_points(const Mesh& a, const Mesh& b) {
  using analysis::Implicit_point_definition;
  const auto doubles = [](const Point_3<double>& p) { return std::array<double, 3>{p.x, p.y, p.z}; };
  const auto exact = [&](const Point_3<double>& p) {
    Implicit_point_definition d;
    d.points[0] = doubles(p);
    return *oracle_point(d);
  };
  const auto coordinates = [](const Exact_point& p) {
    return std::array<mpq_class, 3>{p.coordinate(0), p.coordinate(1), p.coordinate(2)};
  };
  const auto sign = [](Certified_sign s) {
    return certainly(s, Certified_sign::positive) ? 1 : certainly(s, Certified_sign::negative) ? -1 : 0;
  };
  std::set<std::array<mpq_class, 3>> points;
  for (int m = 0; m < 2; ++m) {
    const Mesh& e = m == 0 ? a : b;
    const Mesh& f = m == 0 ? b : a;
    for (const Triangle& te : e.faces)
      for (int i = 0; i < 3; ++i)
        for (const Triangle& tf : f.faces) {
          const Point_3<double>&p = e.vertices[te[i]], &q = e.vertices[te[(i + 1) % 3]];
          const Exact_point ep = exact(p), eq = exact(q), x = exact(f.vertices[tf[0]]), y = exact(f.vertices[tf[1]]),
                            z = exact(f.vertices[tf[2]]);
          const int op = sign(oracle_orientation_3(x, y, z, ep)), oq = sign(oracle_orientation_3(x, y, z, eq));
          if (op * oq > 0 || (op == 0 && oq == 0)) continue;
          const int s1 = sign(oracle_orientation_3(ep, eq, x, y)), s2 = sign(oracle_orientation_3(ep, eq, y, z)),
                    s3 = sign(oracle_orientation_3(ep, eq, z, x));
          if ((s1 < 0 || s2 < 0 || s3 < 0) && (s1 > 0 || s2 > 0 || s3 > 0)) continue;  // the line misses the face
          Implicit_point_definition lpi;
          lpi.kind = Implicit_point_kind::lpi;
          lpi.points = {doubles(p), doubles(q), doubles(f.vertices[tf[0]]), doubles(f.vertices[tf[1]]),
                        doubles(f.vertices[tf[2]])};
          points.insert(coordinates(*oracle_point(lpi)));
        }
  }
  for (const Mesh* m : {&a, &b})
    for (const auto& v : m->vertices) points.erase(coordinates(exact(v)));
  return points;
}

// An operand that crosses itself (checks off) can give one point from two
// pairs of faces that share no edge or face: here B's edge meets the first
// cube's face z = 2 and the second cube's face x = 1 at one point (1, y, 2),
// where those faces cross. The narrow phase's cells do not see that the two are
// one point; merge_equal_points does (13 new points without it). The
// Boolean then fails in the retriangulation (B's face sees the cubes'
// curves cross), but it numbers each point once: as many as the exact
// crossings. (The exact order is asked within runs of points whose
// approximate x ranges overlap: the two copies of the point are in one.)
TEST(MeshBooleanOperands, EqualPointsFromFacesThatCrossAreNumberedOnce) {
  Mesh a = box(0, 0, 0, 2, 2, 2);
  const Mesh second = box(1, 0.5, 0.5, 2, 2, 2);
  const Index offset = static_cast<Index>(a.vertices.size());
  for (const auto& p : second.vertices) a.vertices.push_back(p);
  for (const auto& f : second.faces) a.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  Mesh b;
  b.vertices = {{0.5, 0.2, 1.5}, {1.5, 1.2, 2.5}, {0.6, 0.1, 2.4}, {1.4, 0.2, 1.6}};  // edge 0-1 through x = 1, z = 2
  b.faces = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}};
  const std::set<std::array<mpq_class, 3>> expected = crossing_points(a, b);
  ASSERT_TRUE(std::any_of(expected.begin(), expected.end(), [](const auto& p) { return p[0] == 1 && p[2] == 2; }));
  const Boolean_options unchecked{.check_operands = false, .validate_output = false};
  const auto filtered = boolean(a, b, Op::union_of, Filtered_exact_kernel{}, unchecked);
  const auto exact = boolean(a, b, Op::union_of, Exact_kernel{}, unchecked);
  EXPECT_EQ(filtered.counts.new_vertices, expected.size());
  EXPECT_EQ(exact.counts.new_vertices, expected.size());
}

// Every result carries the validation report of its rounded output. Rounding
// can make an exact result cross itself (CGAL issue 9154): on this
// torus-sphere union the exact result has no crossing, its nearest doubles
// do, and the report says which faces.
TEST(MeshBooleanValidation, TheReportSeesWhatRoundingDoesToAnExactResult) {
  // The nearest doubles of the insertion order's triangulation (the default
  // Delaunay faces and repair give a valid solid: boolean_rounding_test.cpp).
  const Mesh a = torus(1, 0.3, 24, 12), b = rigidly_moved(icosphere(2), 0.3, 0.2, {0, 0, 0.05});
  Boolean_options nearest;
  nearest.rounding = Output_rounding::nearest;
  nearest.delaunay_retriangulation = false;
  const auto r = relgeo::boolean(a, b, Boolean_operation::union_of, Exact_kernel{}, nearest);
  ASSERT_TRUE(r.ok()) << r.failure;
  Triangle_mesh<Point_3<mpq_class>> exact;
  exact.faces = r.mesh.faces;
  for (const auto& v : r.exact_vertices()) exact.vertices.push_back(v.point);
  EXPECT_TRUE(find_self_intersections<Exact_kernel>(exact).is_certainly_free());
  const Solid_report& v = r.validation;
  EXPECT_EQ(v.kernel, Filtered_exact_kernel::name());
  EXPECT_TRUE(v.closed.passed() && v.edge_manifold.passed() && v.consistently_oriented.passed());
  ASSERT_EQ(v.self_intersection_free.status, Check_status::fail);
  ASSERT_FALSE(v.self_intersection_free.where.empty());
  EXPECT_EQ(v.self_intersection_free.count, find_self_intersections<Filtered_exact_kernel>(r.mesh).pairs.size());
  for (const Mesh_issue& i : v.self_intersection_free.where) {
    EXPECT_EQ(i.defect, Mesh_defect::self_intersection);
    EXPECT_LT(i.elements[0], r.mesh.faces.size());
    EXPECT_LT(i.elements[1], r.mesh.faces.size());
  }
  // A clean case validates, and the report can be switched off.
  const auto clean = relgeo::boolean(cube(0, 0, 0, 1), cube(0.5, 0.25, 0.125, 1), Boolean_operation::union_of);
  EXPECT_TRUE(clean.validation.is_valid_solid()) << clean.validation.summary();
  EXPECT_EQ(clean.validation.volume.value, 1.671875);
  const auto quiet = relgeo::boolean(cube(0, 0, 0, 1), cube(0.5, 0.25, 0.125, 1), Boolean_operation::union_of,
                                     Filtered_exact_kernel{}, {.validate_output = false});
  EXPECT_TRUE(quiet.validation.kernel.empty());
}

}  // namespace
}  // namespace relgeo::test
