// Error measures of mesh patches (thesis Sec. 4.2) and the certified checks
// of their (u,v) images: orientation (flips) and overlaps (folds), under
// every certified kernel.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <random>

#include "relgeo/core/dyadic.h"
#include "relgeo/joining/error_measures.h"
#include "relgeo/kernel.h"

namespace {

using namespace relgeo;
using Q = mpq_class;

// A regular grid of (n+1)^2 vertices over [0,1]^2, two triangles per cell,
// counter-clockwise.
std::vector<Triangle> grid_faces(Index n) {
  std::vector<Triangle> f;
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j) {
      const Index a = i * (n + 1) + j;
      f.push_back({a, a + n + 1, a + n + 2}), f.push_back({a, a + n + 2, a + 1});
    }
  return f;
}
std::vector<Point_2<double>> grid_uv(Index n) {
  std::vector<Point_2<double>> uv;
  for (Index i = 0; i <= n; ++i)
    for (Index j = 0; j <= n; ++j) uv.push_back({i / double(n), j / double(n)});
  return uv;
}

TEST(PatchErrors, AbsoluteAndNormalVectorErrorsAreUpperBoundsOfTheExactValues) {
  std::mt19937_64 rng(51);
  std::uniform_real_distribution<double> r(-1e-3, 1e-3);
  const Index n = 12;
  Height_field h{grid_uv(n), {}};
  for (std::size_t i = 0; i < h.uv.size(); ++i) h.height.push_back(r(rng));
  const auto faces = grid_faces(n);
  const Patch_errors e = patch_errors(faces, h, true);
  double max_abs = 0;
  for (double x : h.height) max_abs = std::max(max_abs, std::abs(x));
  EXPECT_EQ(e.absolute_error, max_abs);
  EXPECT_EQ(std::abs(h.height[e.worst_vertex]), max_abs);
  // Exact largest squared slope over triangle edges.
  Q best = 0;
  for (const Triangle& t : faces)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      const Q de = exact_rational(h.height[a]) - exact_rational(h.height[b]);
      const Q dx = exact_rational(h.uv[a].x) - exact_rational(h.uv[b].x), dy = exact_rational(h.uv[a].y) - exact_rational(h.uv[b].y);
      const Q s2 = de * de / (dx * dx + dy * dy);
      if (s2 > best) best = s2;
    }
  const Q reported = exact_rational(e.normal_vector_error);
  EXPECT_GE(reported * reported, best);                      // an upper bound
  EXPECT_LE(reported * reported, best * Q(1 + 1e-14));       // and a tight one
  ASSERT_EQ(e.triangle_slope.size(), faces.size());
  EXPECT_EQ(*std::max_element(e.triangle_slope.begin(), e.triangle_slope.end()), e.normal_vector_error);
  // Coincident corners with different heights: an infinite slope.
  h.uv[1] = h.uv[0];
  h.height[1] = h.height[0] + 1e-3;
  EXPECT_EQ(patch_errors(faces, h).normal_vector_error, std::numeric_limits<double>::infinity());
  h.height[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)patch_errors(faces, h), Non_finite_input);
}

template <class K>
class UvChecks : public ::testing::Test {};
using Certified_kernels = ::testing::Types<Failsafe_kernel<double>, Interval_kernel, Filtered_exact_kernel, Exact_kernel>;
TYPED_TEST_SUITE(UvChecks, Certified_kernels);

TYPED_TEST(UvChecks, FlipsAndFoldsAreFound) {
  using K = TypeParam;
  const Index n = 8;
  const auto faces = grid_faces(n);
  auto uv = grid_uv(n);
  const Orientation_report ok = uv_orientations<K>(faces, uv);
  EXPECT_TRUE(ok.all_positive());
  EXPECT_EQ(ok.positive, faces.size());
  EXPECT_TRUE(uv_overlaps<K>(faces, uv).is_embedding());
  // Reversed faces expect clockwise triangles.
  EXPECT_EQ(uv_orientations<K>(faces, uv, Certified_sign::negative).flipped, faces.size());
  // Move an interior vertex across its neighbour: its triangles flip and
  // overlap their neighbours.
  const Index v = 4 * (n + 1) + 4;
  uv[v].x += 1.5 / n;
  const Orientation_report bad = uv_orientations<K>(faces, uv);
  EXPECT_GT(bad.flipped, 0u);
  for (Index f : bad.flipped_faces) EXPECT_TRUE(faces[f][0] == v || faces[f][1] == v || faces[f][2] == v);
  const Overlap_report o = uv_overlaps<K>(faces, uv);
  EXPECT_GT(o.overlapping.size(), 0u);
  EXPECT_TRUE(o.undecided.empty());
  // A degenerate triangle: collinear corners (exactly).
  // v moved to the midpoint of the two other corners of one of its
  // triangles (exact: dyadic coordinates).
  auto flat = grid_uv(n);
  const Triangle t = *std::find_if(faces.begin(), faces.end(), [&](const Triangle& f) { return f[0] == v; });
  flat[v] = {0.5 * (flat[t[1]].x + flat[t[2]].x), 0.5 * (flat[t[1]].y + flat[t[2]].y)};
  const Orientation_report d = uv_orientations<K>(faces, flat);
  if constexpr (K::has_exact_predicates) EXPECT_GT(d.degenerate, 0u);
  else EXPECT_GT(d.degenerate + d.undecided, 0u);
}

}  // namespace
