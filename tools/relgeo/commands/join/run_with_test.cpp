// tools/relgeo/commands/join/run_with_test.cpp — run_join_with: files in, a
// mesh file and a JSON report out, what `relgeo join` runs under the kernel
// its --kernel names. Models as JSON and STEP, meshes as OFF, curves from a
// JSON file; each method; typed errors for bad files and options. (Which
// kernels join takes is the tool's kernel table, dispatch.cpp: the tool tests
// join_kernel_not_certified and join_unknown_kernel check it.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "commands/join/run_with.h"
#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo_fixtures/joining/test_models.h"
#ifdef RELGEO_HAS_OCCT
// The test makes its STEP file itself; run_join_with reads it through the plug-in.
#include <BRepBuilderAPI_Sewing.hxx>
#include <TopExp_Explorer.hxx>

#include "relgeo/surfaces/occt_conversion.h"
#include "relgeo/surfaces/occt_io.h"
#endif

namespace {

using namespace relgeo;
using namespace relgeo::tool;

// Under join's default kernel (--kernel filtered).
Join_command_report run_join(const Join_command_options& o) { return run_join_with<Filtered_exact_kernel>(o); }

class JoinCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("relgeo_join_cmd_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // Writes a case: model.json, mesh0.off, ...; returns the options.
  Join_command_options write_case(const Joining_case& c) {
    Join_command_options o;
    o.surface = path("model.json");
    write_surface_model_json(c.model, o.surface);
    for (std::size_t f = 0; f < c.meshes.size(); ++f) {
      o.meshes.push_back(path("mesh" + std::to_string(f) + ".off"));
      write_mesh(o.meshes.back(), c.meshes[f]);
    }
    o.output = path("joined.off");
    return o;
  }
  std::filesystem::path dir_;
};

TEST_F(JoinCommand, WhitneyFromJsonAndOffFilesWithACurveFile) {
  const Joining_case c = make_joining_case("two faces", two_face_model(false));
  Join_command_options o = write_case(c);
  const Join_command_report r = run_join(o);
  EXPECT_EQ(r.status, "ok") << r.failure;
  EXPECT_EQ(r.report.edges_with_median, 1u);
  EXPECT_EQ(r.report.edges_with_curve, 0u);
  const Triangle_mesh<Point_3<double>> back = read_mesh(o.output);
  EXPECT_EQ(back.faces.size(), r.mesh.faces.size());
  const nlohmann::json j = to_json(r);
  for (const char* key : {"status", "failure", "method", "kernel", "faces", "vertices", "triangles", "watertight_seams",
                          "guarantees_hold", "seconds", "total_seconds", "flipped_triangles"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["faces"].size(), 2u);
  EXPECT_TRUE(j["faces"][0].contains("lipschitz_constant"));
  EXPECT_EQ(j["method"], "whitney");
  // The shared edge's 3D curve from a curve file: case 1.
  const Model_edge e = two_face_model(true).edges[0];
  nlohmann::json curves;
  curves["edges"] = nlohmann::json::array();
  nlohmann::json pl = nlohmann::json::array();
  for (const auto& p : e.polyline) pl.push_back({p.x, p.y, p.z});
  curves["edges"].push_back({{"edge", 0}, {"polyline", pl}});
  std::ofstream(path("curves.json")) << curves.dump();
  o.curves = {path("curves.json")};
  const Join_command_report r1 = run_join_with<Exact_kernel>(o);
  EXPECT_EQ(r1.status, "ok");
  EXPECT_EQ(r1.report.edges_with_curve, 1u);
  EXPECT_EQ(r1.report.kernel, "exact");
}

TEST_F(JoinCommand, NaiveSewingOfTheFoldingInputFails) {
  Join_command_options o = write_case(folding_case());
  o.method = "naive";
  const Join_command_report r = run_join(o);
  EXPECT_EQ(r.status, "failed");
  EXPECT_EQ(r.failure, "flipped-triangles");
  o.method = "whitney";
  EXPECT_EQ(run_join(o).status, "ok");
}

TEST_F(JoinCommand, ErrorCriteriaAndTheFacesOfTheTriangles) {
  Join_command_options o = write_case(make_joining_case("two faces", two_face_model(true)));
  const Join_command_report r = run_join(o);
  ASSERT_EQ(r.status, "ok") << r.failure;
  ASSERT_EQ(r.face_of_triangle.size(), r.mesh.faces.size());
  for (std::size_t f = 0; f < 2; ++f)
    EXPECT_GT(std::count(r.face_of_triangle.begin(), r.face_of_triangle.end(), static_cast<Index>(f)), 0);
  EXPECT_EQ(r.model.faces.size(), 2u);
  double nve = 0, abs = 0;
  for (const Join_face_report& f : r.report.faces) nve = std::max(nve, f.after.normal_vector), abs = std::max(abs, f.after.absolute);
  ASSERT_GT(nve, 0);
  ASSERT_GT(abs, 0);
  // Criteria at the result's own errors pass; just below them fail.
  o.max_normal_error = nve, o.max_absolute_error = abs;
  EXPECT_EQ(run_join(o).status, "ok");
  o.max_normal_error = std::nextafter(nve, 0.0);
  const Join_command_report n = run_join(o);
  EXPECT_EQ(n.status, "failed");
  EXPECT_EQ(n.failure, "normal-vector-error");
  o.max_normal_error = nve, o.max_absolute_error = std::nextafter(abs, 0.0);
  const Join_command_report a = run_join(o);
  EXPECT_EQ(a.status, "failed");
  EXPECT_EQ(a.failure, "absolute-error");
  EXPECT_EQ(to_json(a)["failure"], "absolute-error");
}

#ifdef RELGEO_HAS_OCCT
TEST_F(JoinCommand, StepInputAndTheOcctMethod) {
  const Joining_case c = make_joining_case("cylinder and plane", cylinder_and_plane_model(false));
  BRepBuilderAPI_Sewing sewing(1e-3);
  for (TopExp_Explorer x(shape_from_surface_model(c.model), TopAbs_FACE); x.More(); x.Next()) sewing.Add(x.Current());
  sewing.Perform();
  Join_command_options o = write_case(make_joining_case("cylinder and plane", read_cad_model([&] {
    const std::string p = path("model.step");
    write_step_shape(sewing.SewedShape(), p);
    return p;
  }())));
  o.surface = path("model.step");
  const Join_command_report r = run_join(o);
  EXPECT_EQ(r.status, "ok") << r.failure;
  EXPECT_EQ(r.report.edges_with_curve, 7u);
  o.method = "occt";
  const Join_command_report q = run_join(o);
  EXPECT_EQ(q.status, "ok") << q.failure;
  EXPECT_EQ(q.report.method, "occt-sewing");
}
#endif

TEST_F(JoinCommand, BadFilesAndOptionsAreTypedErrors) {
  Join_command_options o = write_case(make_joining_case("two faces", two_face_model(false)));
  {
    Join_command_options b = o;
    b.meshes[1] = path("missing.off");
    EXPECT_THROW((void)run_join(b), Unreadable_file);
  }
  {
    Join_command_options b = o;
    b.meshes.pop_back();
    EXPECT_THROW((void)run_join(b), Joining_input_error);
  }
  {
    Join_command_options b = o;
    b.method = "glue";
    EXPECT_THROW((void)run_join(b), Invalid_input);
  }
  {
    Join_command_options b = o;
    std::ofstream(path("bad.step")) << "ISO-10303-21; nothing here\n";
    b.surface = path("bad.step");
#ifdef RELGEO_HAS_OCCT
    EXPECT_THROW((void)run_join(b), Unreadable_file);
#else
    EXPECT_THROW((void)run_join(b), Invalid_input);
#endif
  }
  {
    Join_command_options b = o;
    std::ofstream(path("curves.json")) << R"({"edges": [{"edge": 42, "polyline": [[0,0,0],[1,0,0]]}]})";
    b.curves = {path("curves.json")};
    EXPECT_THROW((void)run_join(b), Invalid_input);
  }
}

}  // namespace
