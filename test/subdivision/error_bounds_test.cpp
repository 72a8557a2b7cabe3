// Error bounds of the limit mesh (error_bounds.h, thesis Sec. 5.4.1): every
// bound encloses the limit surface, checked against dense exact evaluation
// (doubles with a rounding allowance, GMP rationals with none, intervals
// enclosing the exact bounds), on meshes with valences 3..12, creases,
// corners, darts and boundaries; the tightness (bound / sampled maximum
// distance) is printed per mesh and method.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "relgeo/kernel.h"
#include "subdivision/limit_test_support.h"
#include "support/fp_environments.h"
#include "support/soundness_data.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;
using Mesh_q = Triangle_mesh<Point_3<mpq_class>>;

struct Measure {
  long samples = 0, violations[3] = {0, 0, 0};
  long thesis_samples_outside = 0, thesis_faces_outside = 0;
  int faces = 0, measured_faces = 0;
  double ratio_sum[3] = {0, 0, 0}, ratio_max[3] = {0, 0, 0}, max_distance = 0;
};

const char* method_name[3] = {"basis_range", "tangent_plane", "direct"};

// Samples every face of the limit mesh at the dyadic grid of size n; counts
// samples outside each bound (in the kernel's numbers; doubles get `tol`
// times the mesh size), and the tightness max(|lower|, |upper|) / max |h|.
template <class K>
Measure measure(const Triangle_mesh<typename K::Point_3>& control, unsigned level, int n, const Loop_options& o,
                const Loop_bound_options& bo, double tol) {
  using FT = typename K::FT;
  const Loop_limit_mesh_bounds<K> r = Loop_error_bounds<K>(o, bo).compute(control, level);
  const Loop_limit_surface<K> S(r.refined, o);
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const auto& p : r.limit_mesh.vertices) {
    const double c[3] = {internal::coordinate_to_double(p.x), internal::coordinate_to_double(p.y), internal::coordinate_to_double(p.z)};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
  }
  const double size = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  Measure m;
  const auto grid = dyadic_grid(n);
  for (Index g = 0; g < r.refined.faces.size(); ++g) {
    if (r.degenerate[g]) continue;
    ++m.faces;
    const Loop_face_bound<FT>* b[3] = {&r.basis_range[g], &r.tangent_plane[g], &r.direct[g]};
    const double len = r.normal_length[g];
    double hmax = 0;
    bool thesis_out = false;
    for (const auto& [u, v] : grid) {
      const FT t = r.height(g, Point_3<FT>(S.evaluate(g, u, v)));
      ++m.samples;
      for (int k = 0; k < 3; ++k) {
        bool inside;
        if constexpr (std::is_floating_point_v<FT>) {
          const double e = tol * size / len;
          inside = b[k]->lower - e <= t && t <= b[k]->upper + e;
        } else {
          inside = !(t < b[k]->lower) && !(b[k]->upper < t);
        }
        if (!inside) ++m.violations[k];
      }
      const double d = internal::coordinate_to_double(t) * len;
      hmax = std::max(hmax, std::abs(d));
      if (d > r.thesis_estimate[g].second + 1e-13 * size || d < r.thesis_estimate[g].first - 1e-13 * size) {
        ++m.thesis_samples_outside;
        thesis_out = true;
      }
    }
    m.thesis_faces_outside += thesis_out;
    m.max_distance = std::max(m.max_distance, hmax);
    if (hmax > 1e-9 * size) {  // faces of flat pieces have no meaningful ratio
      ++m.measured_faces;
      for (int k = 0; k < 3; ++k) {
        const double ratio = std::max(std::abs(b[k]->lower_distance), std::abs(b[k]->upper_distance)) / hmax;
        m.ratio_sum[k] += ratio;
        m.ratio_max[k] = std::max(m.ratio_max[k], ratio);
      }
    }
  }
  return m;
}

void print(const std::string& name, unsigned level, const Measure& m) {
  std::printf("%-26s L%u %5d faces %7ld samples  max dist %9.3g |", name.c_str(), level, m.faces, m.samples, m.max_distance);
  for (int k = 0; k < 3; ++k)
    std::printf(" %s %5.2f (max %5.2f) |", method_name[k], m.measured_faces ? m.ratio_sum[k] / m.measured_faces : 0.0, m.ratio_max[k]);
  std::printf(" thesis as printed: %ld faces / %ld samples outside\n", m.thesis_faces_outside, m.thesis_samples_outside);
}

void expect_sound(const std::string& name, const Measure& m) {
  for (int k = 0; k < 3; ++k) EXPECT_EQ(m.violations[k], 0) << name << ": " << method_name[k];
  EXPECT_GT(m.samples, 0);
}

// Samples per face side of the double suites: 16 (153 points, the figures
// of doc/subdivision.md); 4 when scaled down (the sanitizer run, which checks
// memory and UB: the sampling's limit evaluations were most of its time).
int double_grid() { return relgeo::test::test_scale() < 1 ? 4 : 16; }

TEST(LoopErrorBounds, SoundAndMeasuredInDoubleValences3To12) {
  std::printf("Tightness = max(|lower|, |upper|) / sampled max |distance| per face (mean and max over faces);\n"
              "samples: dyadic grid of %d per face side; kernel double.\n",
              double_grid());
  for (const auto& [n, mesh] : valence_meshes())
    for (unsigned level : {1u, 2u}) {
      const std::string name = "bipyramid " + std::to_string(n);
      const Measure m = measure<Naive_kernel<double>>(mesh, level, double_grid(), hoppe, {}, 1e-12);
      print(name, level, m);
      expect_sound(name, m);
    }
}

TEST(LoopErrorBounds, SoundAndMeasuredInDoubleCreasesCornersBoundaries) {
  const std::vector<std::tuple<std::string, Mesh_d, Loop_options>> cases = {
      {"icosphere(1)", icosphere(1), hoppe},
      {"jittered torus", jitter(torus(8, 6), 0.15), hoppe},
      {"creased box (flat sides)", creased_box(), hoppe},
      {"jittered creased box", jitter(creased_box(), 0.3), hoppe},
      {"jittered creased box, BLZ", jitter(creased_box(), 0.3), blz},
      {"wavy grid (boundary)", wavy_grid(6), hoppe},
      {"disk 7 crease 3/4", jitter(disk(7, 3), 0.1), hoppe},
      {"disk 7 crease 3/4, BLZ", jitter(disk(7, 3), 0.1), blz},
      {"dart disk 9", jitter(dart_disk(9), 0.1), hoppe},
      {"open grid (boundary)", open_grid(4), hoppe},
      {"half fan 5 (boundary)", half_fan(5), blz},
      {"bipyramid 9, Warren", bipyramid(9), Loop_options{.vertex_weights = Loop_vertex_weights::warren}}};
  for (const auto& [name, mesh, o] : cases)
    for (unsigned level : {1u, 2u}) {
      const Measure m = measure<Naive_kernel<double>>(mesh, level, double_grid(), o, {}, 1e-12);
      print(name, level, m);
      expect_sound(name, m);
      if (m.measured_faces > 0) {
        // the tangent-plane construction never loses against the slab it cuts
        EXPECT_LE(m.ratio_sum[1], m.ratio_sum[0] * (1 + 1e-12)) << name;
        for (int k = 0; k < 3; ++k) EXPECT_GE(m.ratio_max[k], 1.0 - 1e-9) << name;  // bounds >= sampled maxima
      }
    }
}

// Exact rationals: the bounds are rigorous for the exact limit surface (no
// tolerance at all), at valences 3, 4, 6, with creases, corners, boundaries.
TEST(LoopErrorBounds, SoundExactlyUnderRationals) {
  const Loop_bound_options small{.irregular_depth = 2, .regular_depth = 1, .universal_depth = 2};
  const std::vector<std::tuple<std::string, Mesh_d, Loop_options>> cases = {
      {"bipyramid 3", bipyramid(3), hoppe},       {"bipyramid 4", bipyramid(4), hoppe},
      {"dyadic torus", dyadic_torus(4, 4), hoppe}, {"jittered creased box", jitter(creased_box(), 0.3), hoppe},
      {"open grid", open_grid(2), blz}};
  for (const auto& [name, mesh, o] : cases) {
    const Measure m = measure<Exact_kernel>(convert<mpq_class>(mesh), 1, 4, o, small, 0);
    print(name + " (exact)", 1, m);
    expect_sound(name, m);
  }
}

// Interval bounds enclose the exact bounds (and so the exact surface).
TEST(LoopErrorBounds, IntervalBoundsEncloseTheExactBounds) {
  const Loop_bound_options small{.irregular_depth = 1, .regular_depth = 1, .universal_depth = 2};
  const Mesh_d md = jitter(half_fan(3), 0.05);
  const auto e = Loop_error_bounds<Exact_kernel>(hoppe, small).compute(convert<mpq_class>(md), 1);
  const auto i = Loop_error_bounds<Interval_kernel>(hoppe, small).compute(convert<Interval>(md), 1);
  ASSERT_EQ(e.refined.faces.size(), i.refined.faces.size());
  for (Index g = 0; g < e.refined.faces.size(); ++g) {
    const Loop_face_bound<mpq_class>* eb[3] = {&e.basis_range[g], &e.tangent_plane[g], &e.direct[g]};
    const Loop_face_bound<Interval>* ib[3] = {&i.basis_range[g], &i.tangent_plane[g], &i.direct[g]};
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(mpq_class(ib[k]->lower.inf()), eb[k]->lower) << g << " " << method_name[k];
      EXPECT_GE(mpq_class(ib[k]->upper.sup()), eb[k]->upper) << g << " " << method_name[k];
      EXPECT_LT(ib[k]->upper.sup() - eb[k]->upper.get_d(), 1e-9) << "intervals stay narrow";
    }
  }
}

TEST(LoopErrorBounds, PlanarMeshesHaveZeroBoundsExactly) {
  Mesh_d flat = open_grid(3);
  for (auto& p : flat.vertices) p.z = 0;
  const auto r = Loop_error_bounds<Exact_kernel>(hoppe, {.irregular_depth = 2, .regular_depth = 1, .universal_depth = 2})
                     .compute(convert<mpq_class>(flat), 1);
  for (Index g = 0; g < r.refined.faces.size(); ++g)
    for (const auto* b : {&r.basis_range[g], &r.tangent_plane[g], &r.direct[g]}) {
      EXPECT_EQ(b->lower, 0);
      EXPECT_EQ(b->upper, 0);
    }
}

// Independent of the evaluator: the vertices of the limit mesh `extra`
// levels deeper are exact points of the limit surface (limit masks), and
// face j of that mesh descends from face j / 4^extra of level k (refinement
// numbers the children of face f as 4f .. 4f + 3), so each must lie within
// the bounds of its ancestor. Exact rationals, default depths, irrational
// valences (5, 7), creases and corners: for the rational weights the kernel
// uses (doc/subdivision.md, "What is certified"), a violation is a bug.
// Under Interval_kernel every weight is an enclosure of Loop's own, so
// there the check is one for Loop's true surface: the height interval of a
// deeper point must lie certainly inside [lower.inf(), upper.sup()].
template <class K>
long deeper_violations(const Triangle_mesh<typename K::Point_3>& control, unsigned level, unsigned extra,
                       const Loop_options& o, const Loop_bound_options& bo, long* checked) {
  using FT = typename K::FT;
  const Loop_limit_mesh_bounds<K> r = Loop_error_bounds<K>(o, bo).compute(control, level);
  const auto deeper = Loop_subdivider<K>(o).limit_mesh(control, level + extra);
  long violations = 0;
  for (std::size_t j = 0; j < deeper.faces.size(); ++j) {
    const Index g = static_cast<Index>(j >> (2 * extra));
    if (r.degenerate[g]) continue;
    for (const Index v : deeper.faces[j]) {
      const FT t = r.height(g, deeper.vertices[v]);
      for (const auto* b : {&r.basis_range[g], &r.tangent_plane[g], &r.direct[g]}) {
        ++*checked;
        if constexpr (std::is_same_v<FT, Interval>) violations += !(b->lower.inf() <= t.inf() && t.sup() <= b->upper.sup());
        else violations += (t < b->lower) || (b->upper < t);
      }
    }
  }
  return violations;
}

const std::vector<std::tuple<std::string, Mesh_d, Loop_options>>& deeper_cases() {
  static const std::vector<std::tuple<std::string, Mesh_d, Loop_options>> cases = {
      {"icosahedron (valence 5)", jitter(icosphere(0), 0.1), hoppe},
      {"bipyramid 7 (valences 4, 7)", bipyramid(7), hoppe},
      {"creased box (creases, corners)", jitter(creased_box(), 0.2), hoppe},
      {"creased box, BLZ rules", jitter(creased_box(), 0.2), blz}};
  return cases;
}

TEST(LoopErrorBounds, DeeperLimitPointsLieWithinTheIntervalBoundsAtDefaultDepths) {
  for (const auto& [name, mesh, o] : deeper_cases()) {
    long checked = 0;
    EXPECT_EQ(deeper_violations<Interval_kernel>(convert<Interval>(mesh), 1, 4, o, {}, &checked), 0) << name;
    EXPECT_GT(checked, 10000) << name;
    std::printf("%-32s %ld interval height checks against the level-1 bounds\n", name.c_str(), checked);
  }
}

TEST(LoopErrorBounds, DeeperLimitPointsLieWithinTheExactBounds) {
  // Exactly, for the rational weights of Exact_kernel (at valences 5 and 7
  // the rational values of 256-bit cosines), at reduced depths: exact
  // irregular patches at the default depths take minutes. Scaled down
  // (RELGEO_TEST_SCALE < 1: the sanitizers' run) only the first case: GMP's
  // allocations make each case minutes under AddressSanitizer.
  const Loop_bound_options small{.irregular_depth = 2, .regular_depth = 1, .universal_depth = 2};
  const std::size_t cases = relgeo::test::test_scale() < 1 ? 1 : deeper_cases().size();
  for (std::size_t i = 0; i < cases; ++i) {
    const auto& [name, mesh, o] = deeper_cases()[i];
    if (o.crease_rules != hoppe.crease_rules) continue;  // BLZ: covered by the interval check
    long checked = 0;
    EXPECT_EQ(deeper_violations<Exact_kernel>(convert<mpq_class>(mesh), 1, 2, o, small, &checked), 0) << name;
    EXPECT_GT(checked, 1000) << name;
    std::printf("%-32s %ld exact height checks against the level-1 bounds\n", name.c_str(), checked);
  }
}

TEST(LoopErrorBounds, DistancesUseTheNormalLengthRoundedOutward) {
  // Control points known to +-1e-7 only: n . n is an interval of relative
  // width about 1e-6, so |n| must come from its ends (the square root of its
  // midpoint, as before, made the distances too small by about 2.5e-7).
  Triangle_mesh<Point_3<Interval>> m = convert<Interval>(jitter(icosphere(0), 0.1));
  for (auto& p : m.vertices)
    for (Interval* c : {&p.x, &p.y, &p.z}) *c = Interval(c->inf() - 1e-7, c->sup() + 1e-7);
  const auto r = Loop_error_bounds<Interval_kernel>(hoppe).compute(m, 1);
  std::size_t wide = 0;
  for (Index g = 0; g < r.refined.faces.size(); ++g) {
    if (r.degenerate[g]) continue;
    const auto& n = r.normal[g];
    const Interval nn = n.x * n.x + n.y * n.y + n.z * n.z;
    wide += nn.sup() > nn.inf() * (1 + 1e-7);
    const long double shortest = std::sqrt(static_cast<long double>(nn.inf()));
    const long double longest = std::sqrt(static_cast<long double>(nn.sup()));
    for (const auto* b : {&r.basis_range[g], &r.tangent_plane[g], &r.direct[g]}) {
      const long double lo = b->lower.inf(), up = b->upper.sup();
      EXPECT_LE(b->lower_distance, lo * (lo < 0 ? longest : shortest)) << g;
      EXPECT_GE(b->upper_distance, up * (up > 0 ? longest : shortest)) << g;
    }
  }
  EXPECT_GT(wide, r.refined.faces.size() / 2);
}

TEST(LoopErrorBounds, SameBoundsInEveryFloatingPointEnvironment) {
  // Interval bounds are rounded outward in hardware: the computation runs in
  // the default environment whatever the caller set (the same intervals).
  const auto control = convert<Interval>(jitter(icosphere(0), 0.1));
  const Loop_bound_options quick{.irregular_depth = 2, .regular_depth = 1, .universal_depth = 2};
  const auto reference = Loop_error_bounds<Interval_kernel>(hoppe, quick).compute(control, 1);
  for (const auto& s : relgeo::test::non_default_fp_environments()) {
    Loop_limit_mesh_bounds<Interval_kernel> r;
    {
      const relgeo::test::Scoped_fp_environment environment(s);
      r = Loop_error_bounds<Interval_kernel>(hoppe, quick).compute(control, 1);
    }
    ASSERT_EQ(r.basis_range.size(), reference.basis_range.size());
    for (Index g = 0; g < r.basis_range.size(); ++g) {
      EXPECT_EQ(r.basis_range[g].lower, reference.basis_range[g].lower) << s.name << " face " << g;
      EXPECT_EQ(r.tangent_plane[g].upper, reference.tangent_plane[g].upper) << s.name << " face " << g;
      EXPECT_EQ(r.direct[g].upper_distance, reference.direct[g].upper_distance) << s.name << " face " << g;
    }
  }
}

TEST(LoopErrorBounds, TangentPlaneBoundsAreTighterSomewhere) {
  // Never looser than the slab by construction (clamped to it); what can
  // fail is that the tent of tangent planes gains nothing: it must cut the
  // slab strictly on a good share of the faces of a curved irregular mesh.
  const auto r = Loop_error_bounds<Interval_kernel>(hoppe).compute(convert<Interval>(jitter(icosphere(1), 0.05)), 1);
  std::size_t tighter = 0, faces = 0;
  for (Index g = 0; g < r.refined.faces.size(); ++g) {
    if (r.degenerate[g]) continue;
    ++faces;
    tighter += r.tangent_plane[g].lower.inf() > r.basis_range[g].lower.sup() ||
               r.tangent_plane[g].upper.sup() < r.basis_range[g].upper.inf();
  }
  std::printf("tangent plane strictly inside the basis-range slab on %zu of %zu faces\n", tighter, faces);
  EXPECT_GT(tighter, faces / 4);
}

// The nodal ranges of the 12 box-spline functions over the triangle.
TEST(LoopErrorBounds, UniversalNodalRanges) {
  const Loop_error_bounds<Exact_kernel> eb(hoppe, {.universal_depth = 3});
  const auto& r = eb.regular_basis_ranges();
  mpq_class lo = 0, hi = 0;
  for (int i = 0; i < 12; ++i) {
    lo += r[i].first, hi += r[i].second;
    if (i >= 3) {
      EXPECT_EQ(r[i].first, 0) << i;  // ring functions vanish at a corner
    }
    EXPECT_GE(r[i].first, 0) << i;              // box splines are nonnegative
  }
  EXPECT_LE(lo, 1);
  EXPECT_GE(hi, 1);
  EXPECT_GE(r[0].second, mpq_class(1, 2));  // value 1/2 at its own corner
  EXPECT_LT(r[0].second, mpq_class(11, 20));  // and the hull is tight to 10%
}

TEST(LoopErrorBounds, BadInput) {
  Mesh_d nan_mesh = icosphere(0);
  nan_mesh.vertices[2].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)loop_limit_mesh_bounds(nan_mesh, 1), Non_finite_input);
  Mesh_d nm = tetrahedron();
  nm.faces.push_back({0, 1, 2});
  EXPECT_THROW((void)loop_limit_mesh_bounds(nm, 1), Invalid_mesh);
  // level 0 works: the control mesh's own limit mesh
  const auto r = loop_limit_mesh_bounds(icosphere(0), 0);
  EXPECT_EQ(r.limit_mesh.faces.size(), 20u);
}

}  // namespace
