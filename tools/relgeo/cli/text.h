// tools/relgeo/tool_common.h — what every subcommand of the relgeo tool shares:
// the usage-error type (exit code 2), output formats, number parsing and
// printing, and aligned text tables.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace relgeo::tool {

/// Exit codes of the tool (SPEC Sec. 8).
inline constexpr int exit_success = 0;
inline constexpr int exit_failure = 1;  ///< the computation reported a failure
inline constexpr int exit_usage = 2;    ///< bad input or usage

/// Bad command line or unusable input: reported as one line on stderr, exit 2.
class Usage_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Format { text, json };

/// A finite double from a decimal literal, correctly rounded (std::from_chars).
/// Leading/trailing blanks are ignored; NaN, infinities, out-of-range values and
/// trailing garbage throw Usage_error naming `what`.
double parse_double(std::string_view text, std::string_view what);

/// "X,Y" -> (x, y), each parsed by parse_double.
std::pair<double, double> parse_point_2(std::string_view text, std::string_view what);

/// A double with 17 significant digits (round-trips exactly).
std::string format_17(double v);
/// "(x, y)" with 17 significant digits each.
std::string format_point_17(double x, double y);
/// A double with `digits` significant digits (%.*g), for measurements.
std::string format_g(double v, int digits);
/// A double with `decimals` digits after the point (%.*f).
std::string format_fixed(double v, int decimals);

/// Replaces control characters (newlines...) by blanks: error messages must
/// stay on one line.
std::string one_line(std::string_view message);

/// A text table with aligned columns: the first column left-aligned (or the
/// first `left_columns`, see set_left_columns), the others right-aligned. An
/// optional group-header line spans several columns.
class Text_table {
 public:
  explicit Text_table(std::vector<std::string> header) : header_(std::move(header)) {}
  /// A header line above the column names: (label, number of columns it spans).
  void set_groups(std::vector<std::pair<std::string, std::size_t>> groups) {
    groups_ = std::move(groups);
  }
  /// Left-align the first n columns (default 1): names rather than numbers.
  void set_left_columns(std::size_t n) { left_columns_ = n; }
  void add_row(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  /// A horizontal rule between rows (drawn before the next row added).
  void add_rule() { rules_.push_back(rows_.size()); }
  std::string str() const;

 private:
  std::vector<std::string> header_;
  std::vector<std::pair<std::string, std::size_t>> groups_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<std::size_t> rules_;
  std::size_t left_columns_ = 1;
};

}  // namespace relgeo::tool
