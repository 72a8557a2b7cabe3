// The JSON surface format: lossless round trips, typed errors for files that
// are missing, not JSON, incomplete or inconsistent.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include <unistd.h>

#include "joining/surface_fixtures.h"
#include "relgeo/kernel.h"
#include "relgeo/surfaces/surface_json.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

Surface_model sample_model() {
  std::mt19937_64 rng(7);
  Surface_model m;
  m.edges.push_back({random_curve<3>(rng, 3, 6, true), {}});
  m.edges.push_back({std::nullopt, {{0, 0, 0}, {1, 0.5, 0.25}, {2, 0, 0}}});
  m.edges.push_back({});
  Trim_loop outer;
  outer.curves.push_back({std::vector<Point_2<double>>{{0.1, 0.1}, {0.9, 0.1}}, false, 0});
  outer.curves.push_back({Nurbs_curve_2<double>(2, {0, 0, 0, 1, 1, 1}, {{0.9, 0.1}, {0.95, 0.5}, {0.9, 0.9}}, {1, 0.5, 1}),
                          false, 1});
  outer.curves.push_back({std::vector<Point_2<double>>{{0.9, 0.9}, {0.1, 0.9}, {0.1, 0.1}}, false, 2});
  Trim_loop hole;
  hole.curves.push_back({std::vector<Point_2<double>>{{0.4, 0.4}, {0.4, 0.6}, {0.6, 0.6}, {0.6, 0.4}, {0.4, 0.4}}, false, -1});
  m.faces.emplace_back(random_surface(rng, 3, 2, 6, 5, true), outer, std::vector<Trim_loop>{hole}, true);
  m.faces.push_back(Trimmed_surface::untrimmed(quarter_cylinder()));
  return m;
}

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("relgeo_json_" + std::to_string(::getpid()) + "_" + name)).string();
}

TEST(SurfaceJson, RoundTripIsBitForBit) {
  const Surface_model m = sample_model();
  const std::string path = temp_path("model.json");
  write_surface_model_json(m, path);
  const Surface_model r = read_surface_model_json(path);
  std::filesystem::remove(path);
  ASSERT_EQ(r.faces.size(), m.faces.size());
  ASSERT_EQ(r.edges.size(), m.edges.size());
  EXPECT_EQ(to_json(r), to_json(m));
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    EXPECT_EQ(r.faces[f].reversed(), m.faces[f].reversed());
    EXPECT_EQ(r.faces[f].inner_loops().size(), m.faces[f].inner_loops().size());
    for (double u : {0.13, 0.5, 0.77})
      for (double v : {0.21, 0.6}) {
        const auto a = m.faces[f].surface().derivatives(u, v, 2), b = r.faces[f].surface().derivatives(u, v, 2);
        EXPECT_EQ(a.point, b.point);
        EXPECT_EQ(a.duv, b.duv);
      }
    EXPECT_EQ(r.faces[f].domain_polygon(), m.faces[f].domain_polygon());
  }
  EXPECT_EQ(r.faces[0].locate<Filtered_exact_kernel>({0.5, 0.5}), Domain_location::outside);  // hole
  EXPECT_EQ(r.faces[0].locate<Filtered_exact_kernel>({0.2, 0.5}), Domain_location::inside);
  EXPECT_TRUE(r.edges[0].curve.has_value());
  EXPECT_EQ(r.edges[1].polyline.size(), 3u);
  EXPECT_FALSE(r.edges[2].has_geometry());
  const auto uses = r.edge_uses();
  EXPECT_EQ(uses[0].size(), 1u);
  EXPECT_EQ(uses[1][0].curve, 1u);
}

TEST(SurfaceJsonBadInput, TypedErrorsNameTheProblem) {
  EXPECT_THROW(read_surface_model_json("/nonexistent/relgeo/model.json"), Unreadable_file);
  const std::string path = temp_path("bad.json");
  const auto write = [&](const std::string& text) { std::ofstream(path) << text; };
  write("{ not json");
  EXPECT_THROW(read_surface_model_json(path), Unreadable_file);
  write(R"({"faces": [{"surface": {"degree_u": 1, "degree_v": 1, "count_u": 2, "count_v": 2,
          "knots_v": [0,0,1,1], "control_points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]}}]})");
  try {
    (void)read_surface_model_json(path);
    ADD_FAILURE() << "accepted a surface without knots_u";
  } catch (const Unreadable_file& e) {
    EXPECT_NE(std::string(e.what()).find("knots_u"), std::string::npos) << e.what();
  }
  write(R"({"faces": [{"surface": {"degree_u": 1, "degree_v": 1, "count_u": 2, "count_v": 3,
          "knots_u": [0,0,1,1], "knots_v": [0,0,1,1], "control_points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]}}]})");
  EXPECT_THROW(read_surface_model_json(path), Invalid_spline);
  write(R"({"faces": [{"surface": {"degree_u": 1, "degree_v": 1, "count_u": 2, "count_v": 2,
          "knots_u": [0,0,1,1], "knots_v": [0,0,1,1], "control_points": [[0,0,0],[0,1,0],[1,0,0],[1,1]]}}]})");
  EXPECT_THROW(read_surface_model_json(path), Unreadable_file);  // a point with two coordinates
  write(R"({"faces": [{"surface": {"degree_u": 1, "degree_v": 1, "count_u": 2, "count_v": 2,
          "knots_u": [0,0,1,1], "knots_v": [0,0,1,1], "control_points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]},
          "outer": [{"polyline": [[0.1,0.1],[0.9,0.1],[0.9,0.9]], "edge": 4}]}]})");
  EXPECT_THROW(read_surface_model_json(path), Open_trim_loop);  // does not return to its start
  write(R"({"faces": [{"surface": {"degree_u": 1, "degree_v": 1, "count_u": 2, "count_v": 2,
          "knots_u": [0,0,1,1], "knots_v": [0,0,1,1], "control_points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]},
          "outer": [{"polyline": [[0.1,0.1],[0.9,0.1],[0.9,0.9],[0.1,0.1]], "edge": 4}]}]})");
  EXPECT_THROW(read_surface_model_json(path), Invalid_input);  // edge 4 does not exist
  write(R"({"format": "something-else", "faces": []})");
  EXPECT_THROW(read_surface_model_json(path), Unreadable_file);
  std::filesystem::remove(path);
}

}  // namespace
