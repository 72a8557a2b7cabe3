// relgeo/io/solid_report_json.h: the validation report as JSON says what the
// report says, check by check, with where.
#include <gtest/gtest.h>

#include "relgeo/io/solid_report_json.h"
#include "relgeo/mesh/shapes.h"
#include "relgeo/mesh/solid_validation.h"

namespace relgeo {
namespace {

TEST(SolidReportJson, AValidSolid) {
  const io::Json j = io::solid_report_json(validate_solid(cube(0, 0, 0, 2)));
  EXPECT_TRUE(j["valid_solid"].get<bool>());
  EXPECT_EQ(j["summary"], "valid solid");
  EXPECT_EQ(j["checks"].size(), 11u);
  for (const auto& [name, check] : j["checks"].items()) {
    EXPECT_EQ(check["status"], "pass") << name;
    EXPECT_EQ(check["count"], 0) << name;
    EXPECT_TRUE(check["where"].empty()) << name;
  }
  EXPECT_EQ(j["euler_characteristic"], 2);
  EXPECT_EQ(j["genus"], 0);
  EXPECT_EQ(j["volume"]["value"], 8.0);
  EXPECT_TRUE(j["volume"]["exact"].get<bool>());
}

TEST(SolidReportJson, AnOpenMeshNamesItsBoundaryEdges) {
  Mesh_double m = cube(0, 0, 0, 1);
  m.faces.pop_back();  // two boundary edges and one more: the triangle's three
  const Solid_report r = validate_solid(m);
  const io::Json j = io::solid_report_json(r);
  EXPECT_FALSE(j["valid_solid"].get<bool>());
  const io::Json& closed = j["checks"]["closed"];
  EXPECT_EQ(closed["status"], "fail");
  EXPECT_EQ(closed["count"], 3);
  ASSERT_EQ(closed["where"].size(), 3u);
  for (const auto& w : closed["where"]) {
    EXPECT_EQ(w["defect"], std::string(to_string(Mesh_defect::boundary_edge)));
    EXPECT_EQ(w["elements"].size(), 2u);  // the edge's two vertices
  }
  EXPECT_EQ(j["summary"], r.summary());
}

}  // namespace
}  // namespace relgeo
