// relgeo/io/json.h — JSON reports as relgeo writes them, and JSON reading
// with typed errors. Needs nlohmann-json: link relgeo::io (the rest of
// relgeo does not depend on it).
//
// Documents are nlohmann::ordered_json (keys keep their insertion order).
// Conventions, written once here for every report:
//   * coordinates (json_coordinate) print with 17 significant digits, as the
//     text output prints them, and read back to the same double;
//   * measures (json_measure) print as the shortest round-tripping number;
//     +-infinity as the strings "inf" / "-inf" (JSON has no infinity); NaN
//     as null;
//   * a non-finite double stored directly prints as null.
#pragma once

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <system_error>

#include "relgeo/io/errors.h"
#include "relgeo/io/number_text.h"

namespace relgeo::io {

using Json = nlohmann::ordered_json;

namespace internal {

// A coordinate travels through the Json tree as a string with this prefix
// followed by its %.17g text; dump_json prints it as a bare number after
// checking the text is one. Ordinary strings never start with it: the prefix
// begins with two control characters, which JSON text cannot hold unescaped.
inline constexpr std::string_view coordinate_tag = "\x1f\x1e" "coord:";

inline bool is_number_text(std::string_view s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(v);
}

inline void dump(const Json& j, std::string& out, int indent) {
  const std::string pad(static_cast<std::size_t>(indent) * 2, ' ');
  const std::string inner(static_cast<std::size_t>(indent + 1) * 2, ' ');
  switch (j.type()) {
    case Json::value_t::object: {
      if (j.empty()) { out += "{}"; return; }
      out += "{\n";
      bool first = true;
      for (auto it = j.begin(); it != j.end(); ++it) {
        if (!first) out += ",\n";
        first = false;
        out += inner + Json(it.key()).dump() + ": ";
        dump(it.value(), out, indent + 1);
      }
      out += "\n" + pad + "}";
      return;
    }
    case Json::value_t::array: {
      if (j.empty()) { out += "[]"; return; }
      // Arrays of scalars on one line (points, short lists); others one item per line.
      bool scalars = true;
      for (const auto& e : j) scalars = scalars && !e.is_structured();
      out += scalars ? "[" : "[\n";
      for (std::size_t i = 0; i < j.size(); ++i) {
        if (i) out += scalars ? ", " : ",\n";
        if (!scalars) out += inner;
        dump(j[i], out, indent + 1);
      }
      out += scalars ? "]" : "\n" + pad + "]";
      return;
    }
    case Json::value_t::string: {
      const auto& s = j.get_ref<const std::string&>();
      if (s.starts_with(coordinate_tag)) {
        const std::string_view text = std::string_view(s).substr(coordinate_tag.size());
        if (is_number_text(text)) { out += text; return; }
      }
      out += j.dump();
      return;
    }
    case Json::value_t::number_float:
      out += std::isfinite(j.get<double>()) ? j.dump() : "null";
      return;
    default:
      out += j.dump();
  }
}

}  // namespace internal

/// A coordinate, printed with 17 significant digits by dump_json (null when
/// not finite).
inline Json json_coordinate(double v) {
  if (!std::isfinite(v)) return nullptr;
  return std::string(internal::coordinate_tag) + format_17(v);
}

/// [x, y] of json_coordinate values.
inline Json json_point(double x, double y) { return Json::array({json_coordinate(x), json_coordinate(y)}); }

/// A measure (error, margin, rate): the number; "inf" / "-inf" when infinite;
/// null for NaN.
inline Json json_measure(double v) {
  if (std::isnan(v)) return nullptr;
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

/// The document as text, 2-space indentation, arrays of scalars on one line,
/// no newline at the end.
inline std::string dump_json(const Json& j) {
  std::string out;
  internal::dump(j, out, 0);
  return out;
}

/// The JSON document in `text`. \throws Parse_error naming `source` and the
/// line of the first syntax error; relgeo::Non_finite_input for a number
/// beyond the range of double (1e999).
inline Json parse_json(std::string_view text, const std::string& source) {
  try {
    return Json::parse(text);
  } catch (const nlohmann::json::out_of_range& e) {
    // 406: number overflow while parsing
    if (e.id == 406) throw Non_finite_input(source + ": a number beyond the range of double (" + e.what() + ")");
    throw Parse_error(source, 0, "not JSON (" + std::string(e.what()) + ")");
  } catch (const nlohmann::json::parse_error& e) {
    std::size_t line = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) line += text[i] == '\n';
    throw Parse_error(source, line, "not JSON (" + std::string(e.what()) + ")");
  }
}

}  // namespace relgeo::io
