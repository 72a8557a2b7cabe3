// The baseline of thesis Sec. 4.1, naive midpoint sewing, folds on the
// folding configuration (Figs. 4.2, 4.7-4.8) under every certified kernel,
// where the Whitney joiner does not (Fig. 4.9); the comparison table of both
// on every library case.
#include <gtest/gtest.h>

#include <cstdio>

#include "joining/join_fixtures.h"
#include "relgeo/joining/joiner.h"
#include "relgeo/joining/naive_sewing.h"
#include "relgeo/kernel.h"
#include "relgeo/kernel/cgal_kernel.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

template <class K>
class FoldingConfiguration : public ::testing::Test {};
using Certified_kernels = ::testing::Types<Failsafe_kernel<double>, Interval_kernel, Filtered_exact_kernel, Exact_kernel,
                                           Cgal_kernel<CGAL::Epick>>;
TYPED_TEST_SUITE(FoldingConfiguration, Certified_kernels);

TYPED_TEST(FoldingConfiguration, NaiveSewingFoldsWhitneyDoesNot) {
  using K = TypeParam;
  const Joining_case c = folding_case();
  const Join_result naive = naive_sewing<K>(c.model, c.meshes);
  // The seam is closed (both chains moved onto the same midpoints) ...
  EXPECT_TRUE(naive.report.watertight_seams);
  EXPECT_TRUE(naive.report.conforming);
  // ... but the thin strip of patch 0 is turned over: the ten strip triangles
  // on the boundary and their neighbours, certified.
  EXPECT_GE(naive.report.faces[0].orientation_after.flipped, 10u);
  EXPECT_GT(naive.report.faces[0].overlaps_after, 0u);
  EXPECT_EQ(naive.report.faces[1].orientation_after.flipped, 0u);
  EXPECT_FALSE(naive.report.guarantees_hold);
  const Join_result whitney = join_meshes<K>(c.model, c.meshes);
  expect_whitney_guarantees(whitney.report, c.name);
  EXPECT_GT(whitney.report.faces[0].removed_triangles, 20u);  // the strip and the peripheral layer
}

TEST(JoiningComparison, WhitneyAgainstNaiveSewingOnEveryCase) {
  std::printf("\n%-28s %-15s %7s %7s %6s %6s %10s %10s %10s %10s %8s\n", "case", "method", "verts", "tris", "flips",
              "ovlps", "abs.bef", "abs.aft", "nve.bef", "nve.aft", "time_s");
  for (const Joining_case& c : joining_cases()) {
    for (int method = 0; method < 2; ++method) {
      const Join_result r = method == 0 ? naive_sewing(c.model, c.meshes) : join_meshes(c.model, c.meshes);
      double ab = 0, aa = 0, nb = 0, na = 0;
      std::size_t overlaps = 0;
      for (const auto& f : r.report.faces) {
        ab = std::max(ab, f.before.absolute), aa = std::max(aa, f.after.absolute);
        nb = std::max(nb, f.before.normal_vector), na = std::max(na, f.after.normal_vector);
        overlaps += f.overlaps_after;
      }
      std::printf("%-28s %-15s %7zu %7zu %6zu %6zu %10.3g %10.3g %10.3g %10.3g %8.3f\n", c.name.c_str(),
                  r.report.method.c_str(), r.report.vertices, r.report.triangles, r.report.flipped_triangles, overlaps,
                  ab, aa, nb, na, r.report.total_seconds);
      // Both close the seams; only the Whitney joiner guarantees no fold.
      EXPECT_TRUE(r.report.watertight_seams) << c.name << " " << r.report.method;
      if (method == 1) {
        EXPECT_TRUE(r.report.guarantees_hold) << c.name;
      }
    }
  }
}

}  // namespace
