// tools/relgeo/point_file.h — planar point files: reading (with line-numbered
// errors) and writing.
//
// Format: one point per line, two numbers separated by blanks (spaces, tabs)
// or by one comma (blanks around it allowed); `#` starts a comment that runs
// to the end of the line; blank lines are ignored; CRLF line ends are
// accepted. Numbers are decimal literals converted with std::from_chars,
// i.e. correctly rounded to the nearest double (a leading '+' is allowed;
// literals below the smallest subnormal round to zero). NaN, infinities,
// out-of-range literals, garbage, and lines with one or three numbers are
// refused with a Usage_error (exit 2) naming the file and the line number.
// An empty file (or one with comments only) is valid: no points.
#pragma once

#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "relgeo/kernel/point.h"

namespace relgeo::tool {

/// The points of a point file's text; `source` names it in error messages.
/// \throws Usage_error "SOURCE line N: ..." for the first malformed line.
std::vector<Point_2<double>> parse_points_2(std::string_view text, std::string_view source);

/// Reads the point file `path`, or standard input `in` when path is "-".
/// \throws Usage_error when the file cannot be read or a line is malformed.
std::vector<Point_2<double>> read_points_2(const std::string& path, std::istream& in);

/// The points as point-file text ("x y" with 17 significant digits, which
/// read_points_2 reads back exactly), after `header` turned into `#` comment
/// lines (each line of header prefixed by "# "; empty header: none).
std::string format_points_2(std::span<const Point_2<double>> points, std::string_view header = {});

/// Writes format_points_2(points, header) to `path`.
/// \throws Usage_error when the file cannot be written.
void write_points_2(const std::string& path, std::span<const Point_2<double>> points,
                    std::string_view header = {});

}  // namespace relgeo::tool
