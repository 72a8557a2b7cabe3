// JSON as relgeo writes and reads it: coordinates with 17 digits, measures
// with "inf", null for NaN, parse errors with a line.
#include <gtest/gtest.h>

#include <limits>

#include "relgeo/io/json.h"

namespace {

using relgeo::io::Json;

TEST(Json, CoordinatesPrintWith17DigitsAndReadBack) {
  Json j;
  j["p"] = relgeo::io::json_point(0.1, 24.000000000000053);
  const std::string s = relgeo::io::dump_json(j);
  EXPECT_EQ(s, "{\n  \"p\": [0.10000000000000001, 24.000000000000053]\n}");
  const Json back = Json::parse(s);
  EXPECT_EQ(back["p"][0].get<double>(), 0.1);
  EXPECT_EQ(back["p"][1].get<double>(), 24.000000000000053);
}

TEST(Json, MeasuresAndNonFiniteValuesAreWrittenOnce) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  Json j;
  j["a"] = relgeo::io::json_measure(inf);
  j["b"] = relgeo::io::json_measure(-inf);
  j["c"] = relgeo::io::json_measure(nan);
  j["d"] = relgeo::io::json_measure(0.5);
  j["e"] = inf;  // stored directly: null, JSON has no infinity
  j["f"] = relgeo::io::json_coordinate(nan);
  EXPECT_EQ(relgeo::io::dump_json(j),
            "{\n  \"a\": \"inf\",\n  \"b\": \"-inf\",\n  \"c\": null,\n  \"d\": 0.5,\n  \"e\": null,\n  \"f\": null\n}");
  EXPECT_NO_THROW(Json::parse(relgeo::io::dump_json(j)));
}

TEST(Json, NestedLayout) {
  Json j;
  j["rows"] = Json::array({Json{{"k", 1}}, Json{{"k", 2}}});
  j["empty"] = Json::object();
  j["list"] = Json::array();
  EXPECT_EQ(relgeo::io::dump_json(j),
            "{\n  \"rows\": [\n    {\n      \"k\": 1\n    },\n    {\n      \"k\": 2\n    }\n  ],\n"
            "  \"empty\": {},\n  \"list\": []\n}");
}

TEST(Json, ATaggedStringThatIsNotANumberStaysAString) {
  // Only a finite number text is printed bare; anything else is quoted.
  Json j = std::string("\x1f\x1e" "coord:12abc");
  EXPECT_EQ(relgeo::io::dump_json(j).front(), '"');
}

TEST(Json, ParseErrorsNameTheLine) {
  try {
    relgeo::io::parse_json("{\n  \"a\": 1,\n  \"b\": ]\n}", "doc.json");
    FAIL() << "accepted";
  } catch (const relgeo::io::Parse_error& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.source(), "doc.json");
  }
  EXPECT_THROW(relgeo::io::parse_json("", "empty.json"), relgeo::io::Parse_error);
  EXPECT_THROW(relgeo::io::parse_json("not json", "x"), relgeo::Unreadable_file);
}

}  // namespace
