// relgeo/mesh/internal/off_reader.h — relgeo's own reader of OFF files, used
// by read_mesh instead of CGAL's (mesh_io.h).
//
// Why not CGAL's: on malformed files CGAL 5.5's OFF scanner sizes its arrays
// from the counts in the header and from each face's corner count before
// reading them (a 30-byte file asks for gigabytes), and converts arbitrary
// numbers to indices and colours with casts whose result is undefined for
// negative, huge or NaN values (found by fuzz/mesh_off; doc/reliability.md).
// This reader allocates only for what the file holds and names the line of
// every defect.
//
// Format (the OFF of Geomview and CGAL, one element per line):
//   [comments]  keyword [BINARY]  nv nf [ne]  then nv vertex lines, nf face lines
// * '#' starts a comment running to the end of its line; blank lines are
//   skipped; the keyword is [ST][C][N][4][n]OFF ('n' is followed by the
//   dimension, which must be 3);
// * a vertex line starts with x y z (and w for '4', the point being
//   (x/w, y/w, z/w)); what follows (normal, colour, texture) is ignored;
// * a face line starts with the corner count k and k vertex indices
//   (0-based integers); what follows (a colour) is ignored;
// * OFF BINARY (no prefix): big-endian int32 nv nf ne, nv x 3 float32, then per
//   face int32 k, k int32 indices, int32 c (0..4) and c float32 of colour.
// Errors: Unreadable_file naming the file, the line and the defect (no
// keyword, bad counts, a missing or malformed number, a truncated file,
// content after the announced faces);
// Non_finite_input for a NaN, infinite or out-of-range coordinate. Indices
// are not checked against nv here: from_polygon_soup reports them with the
// face (Invalid_mesh, index_out_of_range).
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/kernel/point.h"

namespace relgeo::internal {

/// The points and polygons of an OFF file. The polygons' corners are stored
/// one after another (one allocation, not one per face): polygon f is
/// corners[polygon_begin[f] .. polygon_begin[f + 1]).
struct Off_soup {
  std::vector<Point_3<double>> points;
  std::vector<std::size_t> corners;
  std::vector<std::size_t> polygon_begin{0};

  std::size_t number_of_polygons() const { return polygon_begin.size() - 1; }
  /// Every polygon as a view of its corners (a PolygonRange of from_polygon_soup).
  std::vector<std::span<const std::size_t>> polygons() const {
    std::vector<std::span<const std::size_t>> out;
    out.reserve(number_of_polygons());
    for (std::size_t f = 0; f < number_of_polygons(); ++f)
      out.emplace_back(corners.data() + polygon_begin[f], polygon_begin[f + 1] - polygon_begin[f]);
    return out;
  }
};

class Off_reader {
 public:
  Off_reader(std::string_view text, std::string path) : text_(text), path_(std::move(path)) {}

  Off_soup read() {
    std::vector<std::string_view> t = next_tokens();
    if (t.empty()) fail("empty file, OFF keyword expected");
    const std::string_view keyword = t[0];
    bool homogeneous = false;
    if (!parse_keyword(keyword, homogeneous)) fail("'" + shown(keyword) + "' is not an OFF keyword ([ST][C][N][4][n]OFF)");
    std::size_t i = 1;
    if (keyword.size() >= 4 && keyword[keyword.size() - 4] == 'n') {  // nOFF: the dimension follows
      if (i == t.size()) t = more(t, i);
      if (t[i] != "3") fail("nOFF of dimension " + shown(t[i]) + ": only 3D meshes are read");
      ++i;
    }
    if (i < t.size() && t[i] == "BINARY") {
      if (keyword != "OFF") fail("binary " + shown(keyword) + " is not supported (plain OFF BINARY is)");
      return read_binary();
    }
    std::size_t counts[2];
    for (std::size_t& c : counts) {
      if (i == t.size()) t = more(t, i);
      c = count(t[i++]);
    }
    const std::size_t nv = counts[0], nf = counts[1];
    Off_soup s;
    // Sized by what the file can hold (a line per element), never by the header alone.
    const std::size_t lines_left = static_cast<std::size_t>(std::count(text_.begin() + pos_, text_.end(), '\n')) + 1;
    if (nv > lines_left || nf > lines_left || nv + nf > lines_left)
      fail("the header announces " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
           " faces but only " + std::to_string(lines_left) + " lines follow");
    s.points.reserve(nv);
    s.corners.reserve(3 * nf);
    s.polygon_begin.reserve(nf + 1);
    const std::size_t coordinates = homogeneous ? 4 : 3;
    for (std::size_t v = 0; v < nv; ++v) {
      const std::vector<std::string_view>& line = next_tokens();
      if (line.empty()) fail("the file ends before vertex " + std::to_string(v) + " of " + std::to_string(nv));
      if (line.size() < coordinates)
        fail("vertex " + std::to_string(v) + " has " + std::to_string(line.size()) + " numbers, " +
             std::to_string(coordinates) + " expected");
      double c[4] = {0, 0, 0, 1};
      for (std::size_t k = 0; k < coordinates; ++k) c[k] = coordinate(line[k], v);
      s.points.push_back({c[0] / c[3], c[1] / c[3], c[2] / c[3]});
    }
    for (std::size_t f = 0; f < nf; ++f) {
      const std::vector<std::string_view>& line = next_tokens();
      if (line.empty()) fail("the file ends before face " + std::to_string(f) + " of " + std::to_string(nf));
      const std::size_t k = integer(line[0], [f] { return "the corner count of face " + std::to_string(f); });
      if (k > line.size() - 1)
        fail("face " + std::to_string(f) + " announces " + std::to_string(k) + " corners but lists " +
             std::to_string(line.size() - 1) + " numbers");
      for (std::size_t j = 0; j < k; ++j)
        s.corners.push_back(
            integer(line[j + 1], [f, j] { return "corner " + std::to_string(j) + " of face " + std::to_string(f); }));
      s.polygon_begin.push_back(s.corners.size());
    }
    // More elements than the header announces: the counts are wrong.
    if (!next_tokens().empty())
      fail("content after the " + std::to_string(nf) + " faces the header announces (wrong counts?)");
    return s;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Unreadable_file("OFF file '" + path_ + "', line " + std::to_string(line_) + ": " + what);
  }
  static std::string shown(std::string_view s) { return std::string(s.substr(0, 40)); }

  /// [ST][C][N][4][n]OFF.
  static bool parse_keyword(std::string_view k, bool& homogeneous) {
    if (k.size() < 3 || k.substr(k.size() - 3) != "OFF") return false;
    k.remove_suffix(3);
    for (std::string_view prefix : {"ST", "C", "N", "4", "n"})
      if (k.substr(0, prefix.size()) == prefix) {
        homogeneous = homogeneous || prefix == "4";
        k.remove_prefix(prefix.size());
      }
    return k.empty();
  }

  /// The tokens of the next line with content (comments removed); empty at
  /// the end of the text. Valid until the next call (one buffer for all
  /// lines: no allocation per line).
  const std::vector<std::string_view>& next_tokens() {
    std::vector<std::string_view>& tokens = tokens_;
    tokens.clear();
    while (tokens.empty() && pos_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
      std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = std::min(end + 1, text_.size());  // no newline at the end: stay at the end
      ++line_;
      line = line.substr(0, line.find('#'));
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !is_blank(line[i])) ++i;
        if (i > start) tokens.push_back(line.substr(start, i - start));
      }
    }
    return tokens;
  }
  /// The next line's tokens when the current ones are used up (header).
  std::vector<std::string_view> more(const std::vector<std::string_view>&, std::size_t& i) {
    std::vector<std::string_view> t = next_tokens();
    if (t.empty()) fail("the file ends inside the header");
    i = 0;
    return t;
  }
  static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

  /// A non-negative decimal integer (an index or a count); `what()` names it
  /// in the message (built only then: most integers are fine).
  template <class What>
  std::size_t integer(std::string_view s, const What& what) const {
    std::size_t v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size())
      fail(std::string(what()) + " is '" + shown(s) + "', not a non-negative integer");
    return v;
  }
  std::size_t count(std::string_view s) const { return integer(s, [] { return "a count of the header"; }); }

  double coordinate(std::string_view s, std::size_t vertex) const {
    double v = 0;
    const char* const end = s.data() + s.size();
    const char* first = s.data() + (!s.empty() && s[0] == '+');
    const auto [stop, ec] = std::from_chars(first, end, v, std::chars_format::general);
    if (ec == std::errc::result_out_of_range && stop == end) {
      v = std::strtod(std::string(s).c_str(), nullptr);  // underflow rounds to 0, overflow to inf
    } else if (ec != std::errc() || stop != end) {
      fail("vertex " + std::to_string(vertex) + ": '" + shown(s) + "' is not a number");
    }
    if (!std::isfinite(v))
      throw Non_finite_input("OFF file '" + path_ + "', line " + std::to_string(line_) + ": vertex " +
                             std::to_string(vertex) + " has the coordinate '" + shown(s) +
                             "' (NaN, infinite or beyond double's range)");
    return v;
  }

  // ---- OFF BINARY -------------------------------------------------------------------
  std::uint32_t word() {
    if (text_.size() - pos_ < 4) fail("the binary data ends early");
    std::uint32_t w = 0;
    for (int i = 0; i < 4; ++i) w = (w << 8) | static_cast<unsigned char>(text_[pos_ + i]);
    pos_ += 4;
    return w;
  }
  std::size_t binary_count(const char* what) {
    const auto v = static_cast<std::int32_t>(word());
    if (v < 0) fail(std::string(what) + " is negative (" + std::to_string(v) + ")");
    return static_cast<std::size_t>(v);
  }
  float binary_float() {
    const std::uint32_t w = word();
    float f;
    std::memcpy(&f, &w, sizeof f);
    return f;
  }
  Off_soup read_binary() {
    Off_soup s;
    const std::size_t nv = binary_count("the vertex count"), nf = binary_count("the face count");
    (void)word();  // edge count
    const std::size_t left = text_.size() - pos_;
    if (nv > left / 12 || nf > left / 8 || 12 * nv + 8 * nf > left)
      fail("the binary header announces " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
           " faces but only " + std::to_string(left) + " bytes follow");
    s.points.reserve(nv);
    s.polygon_begin.reserve(nf + 1);
    for (std::size_t v = 0; v < nv; ++v) {
      double c[3];
      for (double& x : c) x = binary_float();
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
        throw Non_finite_input("OFF file '" + path_ + "': vertex " + std::to_string(v) +
                               " has a NaN or infinite coordinate");
      s.points.push_back({c[0], c[1], c[2]});
    }
    for (std::size_t f = 0; f < nf; ++f) {
      const std::size_t k = binary_count("a corner count");
      if (k > (text_.size() - pos_) / 4) fail("face " + std::to_string(f) + " announces more corners than bytes follow");
      for (std::size_t j = 0; j < k; ++j) s.corners.push_back(binary_count("a vertex index"));
      s.polygon_begin.push_back(s.corners.size());
      const std::size_t colours = binary_count("a colour count");
      if (colours > 4) fail("face " + std::to_string(f) + " has " + std::to_string(colours) + " colour values (0..4)");
      for (std::size_t c = 0; c < colours; ++c) (void)word();
    }
    return s;
  }

  std::string_view text_;
  std::string path_;
  std::vector<std::string_view> tokens_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

/// The soup of the OFF text `text` of file `path` (format and errors above).
inline Off_soup read_off_soup(std::string_view text, const std::string& path) {
  return Off_reader(text, path).read();
}

}  // namespace relgeo::internal
