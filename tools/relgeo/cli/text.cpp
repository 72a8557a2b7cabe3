// tools/relgeo/cli/text.cpp
#include "cli/text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "relgeo/io/number_text.h"

namespace relgeo::tool {

std::pair<double, double> parse_point_2(std::string_view text, std::string_view what) {
  const std::size_t comma = text.find(',');
  if (comma == std::string_view::npos || text.find(',', comma + 1) != std::string_view::npos)
    throw Usage_error(std::string(what) + ": expected X,Y (two numbers and one comma), got '" +
                      std::string(text) + "'");
  const std::string source(what);
  return {io::parse_double(text.substr(0, comma), source), io::parse_double(text.substr(comma + 1), source)};
}

std::string format_17(double v) { return io::format_17(v); }

std::string format_point_17(double x, double y) {
  std::string s = "(";  // appended piecewise: GCC 12 warns (-Wrestrict) on "(" + std::string&&
  s += format_17(x);
  s += ", ";
  s += format_17(y);
  s += ')';
  return s;
}
std::string format_g(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}
std::string format_fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string measure_text(double v, int digits) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (v == 0) return "0";
  return format_g(v, digits);
}

std::string duration_text(double s) {
  if (s < 1e-6) return format_g(s * 1e9, 3) + " ns";
  if (s < 1e-3) return format_g(s * 1e6, 3) + " us";
  if (s < 1) return format_g(s * 1e3, 3) + " ms";
  return format_g(s, 3) + " s";
}

void Key_value_text::add(std::string_view key, std::string_view value) {
  text_ += key;
  text_ += std::string(key.size() < width_ ? width_ - key.size() : 1, ' ');
  text_ += value;
  text_ += '\n';
}

std::string one_line(std::string_view message) {
  std::string out(message);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

std::string comma_list(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return list;
}

std::string Text_table::str() const {
  const std::size_t ncols = header_.size();
  std::vector<std::size_t> width(ncols, 0);
  auto widen = [&](const std::vector<std::string>& row) {
    for (std::size_t i = 0; i < std::min(ncols, row.size()); ++i)
      width[i] = std::max(width[i], row[i].size());
  };
  widen(header_);
  for (const auto& r : rows_) widen(r);
  // Group labels must fit over the columns they span (separated by 2 blanks).
  if (!groups_.empty()) {
    std::size_t col = 0;
    for (const auto& [label, span] : groups_) {
      if (span == 0 || col + span > ncols) break;
      std::size_t w = 0;
      for (std::size_t i = col; i < col + span; ++i) w += width[i] + (i > col ? 2 : 0);
      if (label.size() > w) width[col + span - 1] += label.size() - w;
      col += span;
    }
  }
  auto cell = [&](const std::string& s, std::size_t i) {
    const std::string pad(width[i] - std::min(width[i], s.size()), ' ');
    return i < std::max<std::size_t>(left_columns_, 1) ? s + pad : pad + s;
  };
  auto line = [&](const std::vector<std::string>& row) {
    std::string out;
    for (std::size_t i = 0; i < ncols; ++i) {
      if (i > 0) out += "  ";
      out += cell(i < row.size() ? row[i] : std::string(), i);
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out + "\n";
  };
  std::size_t total = 0;
  for (std::size_t i = 0; i < ncols; ++i) total += width[i] + (i > 0 ? 2 : 0);
  const std::string rule = std::string(total, '-') + "\n";

  std::string out;
  if (!groups_.empty()) {
    std::string g;
    std::size_t col = 0;
    for (const auto& [label, span] : groups_) {
      if (span == 0 || col + span > ncols) break;
      std::size_t w = 0;
      for (std::size_t i = col; i < col + span; ++i) w += width[i] + (i > col ? 2 : 0);
      if (col > 0) g += "  ";
      // centre the label over its columns
      const std::size_t left = (w - std::min(w, label.size())) / 2;
      g += std::string(left, ' ') + label + std::string(w - left - std::min(w, label.size()), ' ');
      col += span;
    }
    while (!g.empty() && g.back() == ' ') g.pop_back();
    out += g + "\n";
  }
  out += line(header_);
  out += rule;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    if (r > 0 && std::find(rules_.begin(), rules_.end(), r) != rules_.end()) out += rule;
    out += line(rows_[r]);
  }
  return out;
}

}  // namespace relgeo::tool
