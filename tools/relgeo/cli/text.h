// tools/relgeo/cli/text.h — what every command of the relgeo tool shares:
// the usage error (exit code 2), output formats, the streams a command works
// on, number printing, and aligned text (key-value lines, tables).
#pragma once

#include <cstddef>
#include <iosfwd>
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

/// The exit-code paragraph of the help texts.
inline constexpr const char* exit_codes_text =
    "Exit codes: 0 success, 1 the computation reported a failure (e.g. a certified kernel gave a "
    "wrong answer, a hull algorithm detected non-termination), 2 bad input or usage (one line on "
    "stderr).\n";

/// Bad command line: reported as one line on stderr, exit 2. (Bad file
/// content arrives as relgeo::Error from relgeo/io and exits 2 as well.)
class Usage_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Format { text, json };

/// The streams a command reads and writes.
struct Streams {
  std::istream& in;
  std::ostream& out;
  std::ostream& err;
};

/// "X,Y" -> (x, y), each correctly rounded (relgeo::io::parse_double); `what`
/// names the option in errors.
std::pair<double, double> parse_point_2(std::string_view text, std::string_view what);

/// A double with 17 significant digits (round-trips exactly).
std::string format_17(double v);
/// "(x, y)" with 17 significant digits each.
std::string format_point_17(double x, double y);
/// A double with `digits` significant digits (%.*g), for measurements.
std::string format_g(double v, int digits);
/// A double with `decimals` digits after the point (%.*f).
std::string format_fixed(double v, int decimals);
/// A measure as text: "0", "inf" / "-inf", or `digits` significant digits.
std::string measure_text(double v, int digits = 3);
/// A duration in seconds with a unit (ns, us, ms, s).
std::string duration_text(double seconds);

/// Replaces control characters (newlines...) by blanks: error messages must
/// stay on one line.
std::string one_line(std::string_view message);

/// "a, b, c": the choices a usage message lists.
std::string comma_list(const std::vector<std::string>& names);

/// "key   value" lines with the values aligned at column `width`.
class Key_value_text {
 public:
  explicit Key_value_text(std::size_t width) : width_(width) {}
  void add(std::string_view key, std::string_view value);
  const std::string& str() const { return text_; }

 private:
  std::size_t width_;
  std::string text_;
};

/// A text table with aligned columns: the first column left-aligned (or the
/// first `left_columns`, see set_left_columns), the others right-aligned. An
/// optional group-header line spans several columns. The HTML report renders
/// the same table (header(), rows(), groups()).
class Text_table {
 public:
  explicit Text_table(std::vector<std::string> header) : header_(std::move(header)) {}
  /// A header line above the column names: (label, number of columns it spans).
  void set_groups(std::vector<std::pair<std::string, std::size_t>> groups) { groups_ = std::move(groups); }
  /// Left-align the first n columns (default 1): names rather than numbers.
  void set_left_columns(std::size_t n) { left_columns_ = n; }
  void add_row(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  /// A horizontal rule between rows (drawn before the next row added).
  void add_rule() { rules_.push_back(rows_.size()); }
  std::string str() const;

  const std::vector<std::string>& header() const { return header_; }
  const std::vector<std::vector<std::string>>& rows() const { return rows_; }
  const std::vector<std::pair<std::string, std::size_t>>& groups() const { return groups_; }
  const std::vector<std::size_t>& rules() const { return rules_; }
  std::size_t left_columns() const { return left_columns_; }

 private:
  std::vector<std::string> header_;
  std::vector<std::pair<std::string, std::size_t>> groups_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<std::size_t> rules_;
  std::size_t left_columns_ = 1;
};

}  // namespace relgeo::tool
