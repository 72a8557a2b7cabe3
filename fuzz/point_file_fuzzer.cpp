// Fuzz harness: the point-file parser (relgeo/io/point_file.h) on arbitrary
// text. Contract: the points, all finite, one per line that is not blank
// after removing its comment, reading back bit for bit after
// format_points_2; or a Parse_error naming a line of the text, or
// Non_finite_input.
#include <cmath>
#include <cstring>
#include <string_view>

#include "fuzz_support.h"
#include "relgeo/io/point_file.h"

namespace {

/// Lines that hold something after their comment is removed (the parser's
/// own rule restated: '\n' ends a line, '#' a line's content).
std::size_t data_lines(std::string_view text, std::size_t& lines) {
  std::size_t n = 0;
  lines = 0;
  while (!text.empty()) {
    ++lines;
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    line = line.substr(0, line.find('#'));
    for (char c : line)
      if (!relgeo::io::internal::is_blank(c)) {
        ++n;
        break;
      }
  }
  return n;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace relgeo;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::size_t lines = 0;
  const std::size_t expected = data_lines(text, lines);
  try {
    const auto points = io::parse_points_2(text, "fuzz");
    fuzz::require(points.size() == expected, "one point per line with content");
    for (const auto& p : points) fuzz::require(std::isfinite(p.x) && std::isfinite(p.y), "finite points");
    const auto again = io::parse_points_2(io::format_points_2(points, "round trip\n# second line"), "again");
    fuzz::require(again.size() == points.size(), "round trip keeps the count");
    for (std::size_t i = 0; i < points.size(); ++i)
      fuzz::require(same_bits(again[i].x, points[i].x) && same_bits(again[i].y, points[i].y),
                    "round trip is exact");
  } catch (const io::Parse_error& e) {
    fuzz::require(e.line() >= 1 && e.line() <= lines, "a parse error names a line of the text");
    fuzz::require(e.source() == "fuzz", "a parse error names the source");
  } catch (const Non_finite_input&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "untyped exception: %s\n", e.what());
    std::abort();
  }
  return 0;
}
