// tools/relgeo/point_file.cpp
#include "point_file.h"

#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <system_error>

#include "tool_common.h"

namespace relgeo::tool {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

/// The blank-separated tokens of s.
std::vector<std::string_view> split_blanks(std::string_view s) {
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

std::string quoted(std::string_view s) {
  constexpr std::size_t max_shown = 60;
  std::string out(s.substr(0, max_shown));
  if (s.size() > max_shown) out += "...";
  std::string q(1, '\'');  // appended piecewise: GCC 12 warns (-Wrestrict) on "'" + std::string&&
  q += one_line(out);
  q += '\'';
  return q;
}

}  // namespace

std::vector<Point_2<double>> parse_points_2(std::string_view text, std::string_view source) {
  std::vector<Point_2<double>> points;
  std::size_t line_number = 0;
  while (!text.empty()) {
    ++line_number;
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    line = trim(line);
    if (line.empty()) continue;

    const std::string where = std::string(source) + " line " + std::to_string(line_number);
    std::vector<std::string_view> fields;
    if (const std::size_t comma = line.find(','); comma != std::string_view::npos) {
      if (line.find(',', comma + 1) != std::string_view::npos)
        throw Usage_error(where + ": expected two numbers 'X Y' or 'X,Y', got " + quoted(line) +
                          " (more than one comma)");
      fields = {trim(line.substr(0, comma)), trim(line.substr(comma + 1))};
      for (std::string_view f : fields)
        if (f.empty() || split_blanks(f).size() != 1)
          throw Usage_error(where + ": expected two numbers 'X Y' or 'X,Y', got " + quoted(line));
    } else {
      fields = split_blanks(line);
      if (fields.size() != 2)
        throw Usage_error(where + ": expected two numbers 'X Y' or 'X,Y', got " +
                          std::to_string(fields.size()) + (fields.size() == 1 ? " number" : " numbers") +
                          " in " + quoted(line));
    }
    const double x = parse_double(fields[0], where);
    const double y = parse_double(fields[1], where);
    points.push_back({x, y});
  }
  return points;
}

std::vector<Point_2<double>> read_points_2(const std::string& path, std::istream& in) {
  if (path.empty()) throw Usage_error("--input: empty file name (use '-' for standard input)");
  if (path == "-") {
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw Usage_error("cannot read standard input");
    return parse_points_2(text, "<stdin>");
  }
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Usage_error("cannot read point file '" + path + "': it is a folder");
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    const std::string reason = std::filesystem::exists(path, ec) ? "permission denied or unreadable"
                                                                 : "no such file";
    throw Usage_error("cannot read point file '" + path + "': " + reason);
  }
  std::string text{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  if (f.bad()) throw Usage_error("cannot read point file '" + path + "': read error");
  return parse_points_2(text, path);
}

std::string format_points_2(std::span<const Point_2<double>> points, std::string_view header) {
  std::string out;
  while (!header.empty()) {
    const std::size_t end = header.find('\n');
    const std::string_view line = header.substr(0, end);
    out += line.empty() ? "#\n" : "# " + std::string(line) + "\n";
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

void write_points_2(const std::string& path, std::span<const Point_2<double>> points,
                    std::string_view header) {
  std::ofstream f(path, std::ios::binary);
  f << format_points_2(points, header);
  f.close();
  if (!f) throw Usage_error("cannot write point file '" + path + "'");
}

}  // namespace relgeo::tool
