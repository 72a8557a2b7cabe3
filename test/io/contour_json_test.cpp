// Contour JSON: both layouts, 3D projection, and a typed error for each kind
// of bad input.
#include <gtest/gtest.h>

#include <filesystem>

#include "relgeo/io/contour_json.h"

namespace {

using relgeo::Invalid_input;
using relgeo::Non_finite_input;
using relgeo::io::Parse_error;
using relgeo::io::parse_contour_json;

const char* const square_chain = R"({"degree": 1, "points": [[0, 0], [1, 0], [1, 1], [0, 1]], "uncertainty": 1e-6})";

TEST(ContourJson, ChainOfPoints) {
  const auto in = parse_contour_json(square_chain, "sq");
  ASSERT_TRUE(in.contour);
  EXPECT_EQ(in.contour->size(), 4u);
  EXPECT_FALSE(in.three_d);
  EXPECT_EQ(in.relative_uncertainty, 1e-6);
  EXPECT_EQ(in.absolute_uncertainty, 0);
  // the last curve closes the chain back to the first point
  EXPECT_EQ((*in.contour)[3].control_points().back().x, 0);
  EXPECT_EQ((*in.contour)[3].control_points().back().y, 0);
}

TEST(ContourJson, ListedCurvesAndOverrides) {
  const auto in = parse_contour_json(
      R"({"curves": [[[0,0],[1,0],[1,1]], [[1,1],[0,1],[0,0]]], "heights": [0, 2], "name": "two"})", "c",
      {.relative_uncertainty = 0.25, .absolute_uncertainty = 0.5});
  EXPECT_EQ(in.contour->size(), 2u);
  EXPECT_EQ(in.relative_uncertainty, 0.25);
  EXPECT_EQ(in.absolute_uncertainty, 0.5);
  ASSERT_TRUE(in.heights);
  EXPECT_EQ(in.heights->second, 2);
}

TEST(ContourJson, ThreeDPointsAreProjected) {
  // a square on the plane z = 3, direction (0, 0, 2)
  const auto in = parse_contour_json(
      R"({"degree": 1, "points": [[0,0,3],[1,0,3],[1,1,3],[0,1,3]], "direction": [0, 0, 2]})", "3d");
  EXPECT_TRUE(in.three_d);
  ASSERT_TRUE(in.projection);
  EXPECT_EQ(in.projection->height_min, 3);
  EXPECT_EQ(in.contour->size(), 4u);
}

TEST(ContourJson, MalformedContentIsAParseError) {
  for (const char* bad : {
           "[1, 2]",                                                      // not an object
           R"({"points": [[0,0],[1,0]]})",                                // no degree
           R"({"degree": 1, "points": [[0,0],[1,0]], "curves": []})",     // both layouts
           R"({"degree": 1, "points": [[0,0],[1,"x"],[0,1]]})",           // a string coordinate
           R"({"degree": 1, "points": [[0,0],[1,0,0],[0,1]]})",           // mixed dimensions
           R"({"degree": 1, "points": [[0,0],[1]]})",                     // one coordinate
           R"({"degree": 1, "points": [[0,0],[1,0],[0,1]], "colour": 1})",  // unknown field
           R"({"degree": 1.5, "points": [[0,0],[1,0],[0,1]]})",           // not an integer
           "{\"degree\": 1,\n \"points\": [[0,0],,]}",                    // not JSON
       })
    EXPECT_THROW(parse_contour_json(bad, "bad.json"), Parse_error) << bad;
}

TEST(ContourJson, NonFiniteNumbersAreTyped) {
  EXPECT_THROW(parse_contour_json(R"({"degree": 1, "points": [[0,0],[1e999,0],[0,1]]})", "inf"), Non_finite_input);
  EXPECT_THROW(parse_contour_json(R"({"degree": 1, "points": [[0,0],[1,0],[0,1]], "uncertainty": -1e999})", "u"),
               Non_finite_input);
}

TEST(ContourJson, InvalidObjectsAreInvalidInput) {
  for (const char* bad : {
           R"({"curves": [[[0,0],[1,0]], [[2,2],[0,0]]]})",                       // not closed
           R"({"degree": 0, "points": [[0,0],[1,0],[0,1]]})",                     // degree 0
           R"({"degree": 2, "points": [[0,0],[1,0],[0,1]]})",                     // 3 points, degree 2
           R"({"curves": [[[0,0]], [[0,0],[1,1]]]})",                             // a one-point curve
           R"({"degree": 1, "points": [[0,0,0],[1,0,0],[0,1,5]], "direction": [0,0,1]})",  // off the plane
           R"({"degree": 1, "points": [[0,0],[1,0],[0,1]], "direction": [1,0,0]})",       // 2D, tilted
           R"({"degree": 1, "points": [[0,0],[1,0],[0,1]], "heights": [2, 1]})",          // l1 >= l2
       }) {
    try {
      parse_contour_json(bad, "bad.json");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const Parse_error&) {
      ADD_FAILURE() << "a parse error, expected invalid input: " << bad;
    } catch (const Invalid_input& e) {
      EXPECT_EQ(std::string(e.what()).rfind("bad.json: ", 0), 0u) << e.what();
    }
  }
}

TEST(ContourJson, UnreadableFile) {
  EXPECT_THROW(relgeo::io::read_contour_json("/nonexistent/relgeo/c.json"), relgeo::Unreadable_file);
}

}  // namespace
