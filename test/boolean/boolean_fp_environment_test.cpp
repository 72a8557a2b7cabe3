// The mesh Boolean and the checks built on the face hierarchy give the
// default environment's answers in every floating-point environment a
// caller can set (flush-to-zero, denormals-are-zero, both, each rounding
// mode), on operands at the scales where the environment reaches the
// arithmetic: 2^-135 (the hierarchy's float node boxes are float
// subnormals), 2^-1050 (the coordinates are double subnormals) and 2^1000
// (products overflow). The naive kernel's answers change with the
// environment on the same operands: the data is hard.
//
// Found before: the hierarchy rounded its node boxes to floats and took
// their min/max in the caller's environment, so under FTZ or DAZ a box
// missed faces, and the union of two crossing cubes of side 2^-134 came out
// "valid" with A's volume alone.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "boolean_inputs.h"
#include "relgeo/boolean.h"
#include "relgeo/kernel.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/solid_validation.h"
#include "support/fp_environments.h"

namespace relgeo::test {
namespace {

using Op = Boolean_operation;
constexpr Op kOps[] = {Op::union_of, Op::intersection, Op::difference};

Mesh scaled(Mesh m, int exponent) {
  for (auto& v : m.vertices) v = {std::ldexp(v.x, exponent), std::ldexp(v.y, exponent), std::ldexp(v.z, exponent)};
  return m;
}

struct Input {
  std::string name;
  Mesh a, b;
};

// Two crossing cubes, a cube and a tetrahedron crossing it in general
// position (new vertices are LPI points), a cube and one sharing a face
// partly (coplanar faces), each at three scales; and two boxes whose faces
// are a subnormal distance apart (2^-1070), at unit scale.
std::vector<Input> inputs() {
  const Mesh tet = tetrahedron({Point_3<double>{-1, 0, 1}, {5, 1, 2}, {1, 6, 0}, {2, 2, 7}});
  const std::vector<Input> unit = {{"cubes", cube(0, 0, 0, 2), cube(1, 1, 1, 2)},
                                   {"cube-tetrahedron", cube(0, 0, 0, 4), tet},
                                   {"coplanar-cubes", cube(0, 0, 0, 2), box(1, 1, 0, 2, 2, 2)}};
  std::vector<Input> out;
  for (int e : {-135, -1050, 1000})
    for (const Input& i : unit)
      out.push_back({i.name + " at 2^" + std::to_string(e), scaled(i.a, e), scaled(i.b, e)});
  out.push_back({"faces 2^-1070 apart", box(0x1p-1070, 0, 0, 2, 2, 2), cube(0, 0, 0, 1)});
  return out;
}

// What a Boolean answered, compared field by field.
struct Boolean_answer {
  bool ok = false;
  std::string failure;
  Mesh mesh;
  std::string validation;
  double volume_lower = 0, volume_upper = 0;
  std::size_t candidate_pairs = 0;
  friend bool operator==(const Boolean_answer& x, const Boolean_answer& y) {
    return x.ok == y.ok && x.failure == y.failure && x.mesh.vertices == y.mesh.vertices &&
           x.mesh.faces == y.mesh.faces && x.validation == y.validation &&
           same(x.volume_lower, y.volume_lower) && same(x.volume_upper, y.volume_upper) &&
           x.candidate_pairs == y.candidate_pairs;
  }
  static bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }
};

template <class K>
Boolean_answer boolean_answer(const Input& in, Op op) {
  const auto r = boolean(in.a, in.b, op, K{});
  return {r.ok(), r.failure, r.mesh, r.validation.summary(), r.validation.volume.lower, r.validation.volume.upper,
          r.counts.candidate_pairs};
}

// f() in the environment `setting` (nullptr: the default one).
template <class F>
auto in_environment(const Fp_environment_setting* setting, const F& f) {
  if (!setting) return f();
  const Scoped_fp_environment environment(*setting);
  return f();
}

template <class K>
void expect_the_same_boolean_in_every_environment() {
  std::size_t compared = 0;
  for (const Input& in : inputs())
    for (Op op : kOps) {
      const Boolean_answer reference = boolean_answer<K>(in, op);
      if (K::has_exact_predicates) {
        EXPECT_TRUE(reference.ok) << K::name() << " " << in.name << " " << to_string(op) << ": " << reference.failure;
      }
      for (const auto& s : non_default_fp_environments()) {
        const Boolean_answer answer = in_environment(&s, [&] { return boolean_answer<K>(in, op); });
        EXPECT_TRUE(answer == reference) << K::name() << " " << in.name << " " << to_string(op) << " under "
                                         << s.name << ": " << (answer.ok ? answer.validation : answer.failure)
                                         << " (default: " << (reference.ok ? reference.validation : reference.failure)
                                         << "), volume " << answer.volume_lower << " (default " << reference.volume_lower
                                         << ")";
        ++compared;
      }
    }
  std::printf("[ %s ] %zu Booleans compared with the default environment's\n", K::name().c_str(), compared);
}

TEST(BooleanFpEnvironment, FilteredExactKernel) { expect_the_same_boolean_in_every_environment<Filtered_exact_kernel>(); }
TEST(BooleanFpEnvironment, ExactKernel) { expect_the_same_boolean_in_every_environment<Exact_kernel>(); }
TEST(BooleanFpEnvironment, IntervalKernel) { expect_the_same_boolean_in_every_environment<Interval_kernel>(); }
TEST(BooleanFpEnvironment, FailsafeKernel) { expect_the_same_boolean_in_every_environment<Failsafe_kernel<double>>(); }

TEST(BooleanFpEnvironment, TheUnionOfTwoCubesAtAFloatSubnormalScaleHasTheRightVolume) {
  // The issue's example: s = 2^-135, A = [0, 2s]^3, B = [s, 3s]^3, union
  // volume 15 s^3 (A alone is 8 s^3).
  const double s = 0x1p-135;
  const Mesh a = scaled(cube(0, 0, 0, 2), -135), b = scaled(cube(1, 1, 1, 2), -135);
  for (const auto& setting : non_default_fp_environments()) {
    const auto r = in_environment(&setting, [&] { return boolean(a, b, Op::union_of); });
    ASSERT_TRUE(r.ok()) << setting.name << ": " << r.failure;
    EXPECT_TRUE(r.validation.is_valid_solid()) << setting.name << ": " << r.validation.summary();
    // The exact volume's bounds, in units of s^3 (exact: powers of two).
    EXPECT_EQ(r.validation.volume.lower / (s * s * s), 15.0) << setting.name;
    EXPECT_EQ(r.mesh.faces.size(), 36u) << setting.name;
  }
}

// check_solid, validate_solid, the self-intersection test and the
// hierarchy's own pair search, on the operands and on two crossing copies
// of each operand merged into one (self-intersecting) mesh.
TEST(BooleanFpEnvironment, ChecksAndHierarchyGiveTheSameAnswers) {
  std::size_t compared = 0;
  for (const Input& in : inputs()) {
    Mesh crossing = in.a;  // A and B as one mesh: they cross (or touch) each other
    const Index offset = static_cast<Index>(crossing.vertices.size());
    crossing.vertices.insert(crossing.vertices.end(), in.b.vertices.begin(), in.b.vertices.end());
    for (Triangle f : in.b.faces) crossing.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
    const auto answers = [&] {
      std::vector<std::string> out;
      for (const Mesh* m : std::array<const Mesh*, 3>{&in.a, &in.b, &crossing}) {
        const Mesh_report checked = check_solid(*m);
        std::string issues;
        for (const Mesh_issue& i : checked.issues) issues += to_string(i) + "; ";
        out.push_back("check_solid: " + issues);
        const Solid_report v = validate_solid(*m);
        char volume[64];
        std::snprintf(volume, sizeof volume, " [%a, %a]", v.volume.lower, v.volume.upper);
        out.push_back("validate_solid: " + v.summary() + volume);
        std::string pairs;
        for (const Face_pair& p : find_self_intersections(*m).pairs)
          pairs += std::to_string(p.first) + "-" + std::to_string(p.second) + " ";
        out.push_back("self-intersections: " + pairs);
      }
      std::string pairs;
      for (const Face_pair& p : Face_bvh(in.a).overlapping_pairs(Face_bvh(in.b)))
        pairs += std::to_string(p.first) + "-" + std::to_string(p.second) + " ";
      out.push_back("Face_bvh pairs: " + pairs);
      return out;
    };
    const std::vector<std::string> reference = answers();
    for (const auto& s : non_default_fp_environments()) {
      const std::vector<std::string> got = in_environment(&s, answers);
      ASSERT_EQ(got.size(), reference.size());
      for (std::size_t i = 0; i < got.size(); ++i, ++compared)
        EXPECT_EQ(got[i], reference[i]) << in.name << " under " << s.name;
    }
  }
  std::printf("[ checks   ] %zu answers compared with the default environment's\n", compared);
}

// The environments reach the arithmetic on these operands: the naive
// kernel, which computes in the caller's environment, answers differently
// from its own default-environment answer on some of them under every
// setting (and the float rounding of the hierarchy's boxes changes too).
TEST(BooleanFpEnvironment, TheOperandsAreHardForTheNaiveKernel) {
  const std::vector<Input> all = inputs();
  std::vector<Boolean_answer> reference;
  for (const Input& in : all)
    for (Op op : kOps) reference.push_back(boolean_answer<Naive_kernel<double>>(in, op));
  for (const auto& s : non_default_fp_environments()) {
    std::size_t differ = 0, i = 0;
    for (const Input& in : all)
      for (Op op : kOps)
        differ += !(in_environment(&s, [&] { return boolean_answer<Naive_kernel<double>>(in, op); }) == reference[i++]);
    // The hierarchy's float boxes: the bounds rounded to float in this
    // environment against the default one.
    std::size_t rounded_differently = 0;
    for (const Input& in : all)
      for (const auto& v : in.a.vertices)
        for (double c : {v.x, v.y, v.z}) {
          const auto to_float = [c] {
            volatile double x = c;
            volatile float f = static_cast<float>(x);
            return static_cast<double>(f);
          };
          const double here = in_environment(&s, to_float), there = to_float();
          rounded_differently += !(here == there) || std::signbit(here) != std::signbit(there);
        }
    std::printf("[ naive    ] %-20s %zu of %zu Booleans differ from the default environment's; %zu float roundings\n",
                s.name.c_str(), differ, reference.size(), rounded_differently);
    EXPECT_GT(differ, 0u) << "the environment does not reach the arithmetic: " << s.name;
  }
}

}  // namespace
}  // namespace relgeo::test
