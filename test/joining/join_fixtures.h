// The joining cases the joiner tests share (made by the fixtures of
// relgeo_fixtures/joining/test_models.h) and the invariants every Whitney
// result must satisfy.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "relgeo/joining/join_report.h"
#include "relgeo_fixtures/joining/test_models.h"

namespace relgeo_test {

/// The library-made inputs: two and three faces (case 1 with the edges'
/// curves, case 2 without), the rational cylinder and plane, the folding
/// configuration.
inline std::vector<relgeo::Joining_case> joining_cases() {
  using namespace relgeo;
  std::vector<Joining_case> cases;
  cases.push_back(make_joining_case("two faces, case 1", two_face_model(true)));
  cases.push_back(make_joining_case("two faces, case 2", two_face_model(false)));
  cases.push_back(make_joining_case("two faces, all curves", two_face_model(true, 2e-3, true)));
  cases.push_back(make_joining_case("three faces, case 1", three_face_model(true)));
  cases.push_back(make_joining_case("three faces, case 2", three_face_model(false)));
  cases.push_back(make_joining_case("cylinder and plane, case 1", cylinder_and_plane_model(true)));
  cases.push_back(make_joining_case("cylinder and plane, case 2", cylinder_and_plane_model(false)));
  cases.push_back(folding_case());
  return cases;
}

/// The thesis' guarantees and the joiner's promises, asserted on a report.
inline void expect_whitney_guarantees(const relgeo::Join_report& r, const std::string& name) {
  SCOPED_TRACE(name + " / " + r.kernel);
  EXPECT_TRUE(r.guarantees_hold);
  EXPECT_TRUE(r.watertight_seams);
  EXPECT_TRUE(r.conforming);
  EXPECT_EQ(r.seam_boundary_edges, 0u);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_EQ(r.inconsistent_orientations, 0u);
  EXPECT_EQ(r.flipped_triangles, 0u);
  for (std::size_t f = 0; f < r.faces.size(); ++f) {
    const relgeo::Join_face_report& x = r.faces[f];
    SCOPED_TRACE("face " + std::to_string(f));
    // |a| <= max |e| on dR (exactly: both are doubles of the height field).
    EXPECT_LE(x.after.absolute, x.boundary_max_abs_height);
    // Slope <= L, up to the certified deviation of a few ulps.
    EXPECT_LE(x.after.normal_vector, x.lipschitz_constant * (1 + 1e-9) + 1e-12);
    EXPECT_GE(x.lipschitz_constant, x.data_lipschitz_constant);
    EXPECT_EQ(x.whitney_uncertified, 0u);
    EXPECT_LT(x.max_deviation, 1e-14);
    EXPECT_EQ(x.orientation_after.flipped, 0u);
    EXPECT_EQ(x.orientation_after.degenerate, 0u);
    EXPECT_EQ(x.orientation_after.undecided, 0u);
    EXPECT_EQ(x.overlaps_after, 0u);
    EXPECT_EQ(x.overlaps_undecided_after, 0u);
    EXPECT_GT(x.central_triangles, 0u);
    EXPECT_GT(x.external_triangles, 0u);
    // Ruppert's angle in (u,v), where the input angles allow it.
    EXPECT_GT(x.min_angle_external, 5.0);
    // The result's vertices measured again on the surface agree with the
    // height field (rounding of F + a n only).
    EXPECT_NEAR(x.after_reprojected.absolute, x.after.absolute, 1e-12);
  }
}

}  // namespace relgeo_test
