// OpenCASCADE as a peer: its sewing and meshing of the same models, in the
// comparison table with the Whitney joiner and naive sewing; and real CAD
// input end to end: a model written to STEP and IGES by OCC, read back
// (edges with their 3D curves: case 1) and joined with the guarantees.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include <unistd.h>

#include "joining/join_fixtures.h"
#include "relgeo/joining/joiner.h"
#include "relgeo/joining/naive_sewing.h"
#include "relgeo/joining/occt_sewing.h"
#include "relgeo/kernel.h"
#include "relgeo/surfaces/occt_io.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

TEST(OcctPeer, SewingAndMeshingOfTheLibraryCases) {
  std::printf("\n%-28s %-15s %7s %7s %6s %6s %6s %10s %10s %8s\n", "case", "method", "verts", "tris", "flips", "ovlps",
              "seams", "abs.aft", "nve.aft", "time_s");
  for (const Joining_case& c : joining_cases()) {
    const Join_result results[3] = {naive_sewing(c.model, c.meshes), join_meshes(c.model, c.meshes),
                                    occt_sewing(c.model, c.meshes)};
    for (const Join_result& r : results) {
      double aa = 0, na = 0;
      std::size_t overlaps = 0;
      for (const auto& f : r.report.faces)
        aa = std::max(aa, f.after.absolute), na = std::max(na, f.after.normal_vector), overlaps += f.overlaps_after;
      std::printf("%-28s %-15s %7zu %7zu %6zu %6zu %6s %10.3g %10.3g %8.3f\n", c.name.c_str(), r.report.method.c_str(),
                  r.report.vertices, r.report.triangles, r.report.flipped_triangles, overlaps,
                  r.report.watertight_seams ? "closed" : "open", aa, na, r.report.total_seconds);
    }
    const Join_report& occ = results[2].report;
    // OCC meshes the CAD faces anew: valid triangles, vertices on the
    // surfaces (up to the gap between the faces' surfaces along the seams).
    EXPECT_EQ(occ.flipped_triangles, 0u) << c.name;
    EXPECT_TRUE(occ.conforming) << c.name;
    EXPECT_TRUE(occ.watertight_seams) << c.name;
    for (const auto& f : occ.faces) EXPECT_LT(f.after.absolute, 3e-3) << c.name;
  }
}

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("relgeo_peer_" + std::to_string(::getpid()) + "_" + name)).string();
}

TEST(OcctPeer, StepAndIgesModelsJoinWithTheirEdgeCurves) {
  for (const auto& [name, model] : {std::pair{"two faces", two_face_model(false)}, std::pair{"cylinder and plane", cylinder_and_plane_model(false)}}) {
    BRepBuilderAPI_Sewing sewing(1e-2);
    for (TopExp_Explorer x(shape_from_surface_model(model), TopAbs_FACE); x.More(); x.Next()) sewing.Add(x.Current());
    sewing.Perform();
    for (const std::string ext : {".step", ".igs"}) {
      const std::string path = temp_path(std::string("model") + ext);
      if (ext == ".step") write_step_shape(sewing.SewedShape(), path);
      else write_iges_shape(sewing.SewedShape(), path);
      const Surface_model read = read_cad_model(path);
      std::filesystem::remove(path);
      ASSERT_EQ(read.faces.size(), 2u) << name << ext;
      const Joining_case c = make_joining_case(name, read);
      const Join_result r = join_meshes(c.model, c.meshes);
      EXPECT_EQ(r.report.edges_with_curve, 1u + 6u) << name << ext;  // the seam and six free edges, all with curves
      expect_whitney_guarantees(r.report, std::string(name) + ext);
    }
  }
}

}  // namespace
