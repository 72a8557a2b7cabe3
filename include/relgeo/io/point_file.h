// relgeo/io/point_file.h — planar point files: reading with line-numbered
// typed errors, and writing that reads back exactly.
//
// Format: one point per line, two numbers separated by blanks (spaces, tabs)
// or by one comma (blanks around it allowed); '#' starts a comment that runs
// to the end of the line; blank lines are ignored; CRLF line ends are
// accepted. Numbers are decimal literals correctly rounded to the nearest
// double (relgeo::io::parse_double). An empty file (or comments only) holds
// no points. Errors (io/errors.h): a line with one or three numbers, two
// commas or garbage is a Parse_error naming the source and the line; NaN,
// infinities and literals beyond double's range are Non_finite_input; a file
// that cannot be read is Unreadable_file.
#pragma once

#include <istream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "relgeo/io/number_text.h"
#include "relgeo/io/text_file.h"
#include "relgeo/kernel/point.h"

namespace relgeo::io {

namespace internal {
/// The blank-separated fields of s.
inline std::vector<std::string_view> split_blanks(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && is_blank(s[i])) ++i;
    const std::size_t start = i;
    while (i < s.size() && !is_blank(s[i])) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

/// The two fields "X Y" or "X,Y" of a point line (comment and blanks removed).
inline std::vector<std::string_view> point_fields(std::string_view line, const std::string& source,
                                                  std::size_t number) {
  const std::string expected = "expected two numbers 'X Y' or 'X,Y', got ";
  const std::size_t comma = line.find(',');
  if (comma == std::string_view::npos) {
    std::vector<std::string_view> fields = split_blanks(line);
    if (fields.size() != 2)
      throw Parse_error(source, number,
                        expected + std::to_string(fields.size()) +
                            (fields.size() == 1 ? " number in " : " numbers in ") + quoted(line));
    return fields;
  }
  if (line.find(',', comma + 1) != std::string_view::npos)
    throw Parse_error(source, number, expected + quoted(line) + " (more than one comma)");
  std::vector<std::string_view> fields = {trim(line.substr(0, comma)), trim(line.substr(comma + 1))};
  for (std::string_view f : fields)
    if (f.empty() || split_blanks(f).size() != 1) throw Parse_error(source, number, expected + quoted(line));
  return fields;
}
}  // namespace internal

/// The points of a point file's text; `source` names it in error messages.
inline std::vector<Point_2<double>> parse_points_2(std::string_view text, const std::string& source) {
  std::vector<Point_2<double>> points;
  std::size_t number = 0;
  while (!text.empty()) {
    ++number;
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    line = internal::trim(line);
    if (line.empty()) continue;
    const auto fields = internal::point_fields(line, source, number);
    const double x = parse_double(fields[0], source, number);
    const double y = parse_double(fields[1], source, number);
    points.push_back({x, y});
  }
  return points;
}

/// The points of the point file `path`.
inline std::vector<Point_2<double>> read_points_2(const std::string& path) {
  return parse_points_2(read_text_file(path, "point file"), path);
}

/// The points of a point file read from `in` (e.g. standard input).
inline std::vector<Point_2<double>> read_points_2(std::istream& in, const std::string& source = "<stdin>") {
  return parse_points_2(read_text_stream(in, source), source);
}

/// The points as point-file text ("x y", 17 significant digits: parse_points_2
/// reads them back exactly), after `header` as '#' comment lines.
inline std::string format_points_2(std::span<const Point_2<double>> points, std::string_view header = {}) {
  std::string out;
  while (!header.empty()) {
    const std::size_t end = header.find('\n');
    const std::string_view line = header.substr(0, end);
    out += line.empty() ? std::string("#\n") : "# " + std::string(line) + "\n";
    header.remove_prefix(end == std::string_view::npos ? header.size() : end + 1);
  }
  for (const auto& p : points) {
    out += format_17(p.x);
    out += ' ';
    out += format_17(p.y);
    out += '\n';
  }
  return out;
}

/// Writes format_points_2(points, header) to `path`. \throws Unwritable_file.
inline void write_points_2(const std::string& path, std::span<const Point_2<double>> points,
                           std::string_view header = {}) {
  write_text_file(path, format_points_2(points, header), "point file");
}

}  // namespace relgeo::io
