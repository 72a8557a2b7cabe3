// tools/relgeo/json_output.h — JSON as the tool prints it.
//
// Documents are built with nlohmann::ordered_json (keys keep their insertion
// order). Measurements (times, rates) are plain JSON numbers printed in the
// shortest form that round-trips; coordinates are wrapped with
// json_coordinate() and printed with 17 significant digits (SPEC Sec. 8), as
// the text output prints them.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace relgeo::tool {

using Json = nlohmann::ordered_json;

/// A coordinate, printed with 17 significant digits by dump_json.
Json json_coordinate(double v);
/// [x, y] of json_coordinate values.
Json json_point(double x, double y);

/// The document as text, 2-space indentation, ending without newline.
std::string dump_json(const Json& j);

}  // namespace relgeo::tool
