// The joined meshes in space: no two triangles intersect other than in a
// shared vertex or edge (exact predicates: relgeo::self_intersections over
// CGAL's Epick), for every library case; naive sewing's folded strip
// overlaps its neighbours (coplanar overlaps in the folding case).
#include <gtest/gtest.h>

#include "joining/join_fixtures.h"
#include "relgeo/joining/joiner.h"
#include "relgeo/joining/naive_sewing.h"
#include "relgeo/mesh/self_intersection.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

TEST(JoinedMeshInSpace, NoSelfIntersectionWhitneyFoldedNaive) {
  for (const Joining_case& c : joining_cases()) {
    const Join_result r = join_meshes(c.model, c.meshes);
    EXPECT_TRUE(self_intersections(r.mesh).empty()) << c.name;
  }
  const Joining_case f = folding_case();
  EXPECT_FALSE(self_intersections(naive_sewing(f.model, f.meshes).mesh).empty());
}

}  // namespace
