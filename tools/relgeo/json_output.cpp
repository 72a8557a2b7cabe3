// tools/relgeo/json_output.cpp
#include "json_output.h"

#include <charconv>
#include <cmath>
#include <string_view>
#include <system_error>

#include "tool_common.h"

namespace relgeo::tool {

namespace {

// A coordinate travels through the Json tree as a string with this prefix
// followed by its %.17g text; dump_json prints such a string as a bare number
// after checking the text is one. Ordinary strings never start with it: the
// prefix begins with two control characters, which JSON text cannot contain
// unescaped and which the tool never puts into user-visible strings.
constexpr std::string_view coordinate_tag = "\x1f\x1e" "coord:";

bool is_number_text(std::string_view s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(v);
}

void dump(const Json& j, std::string& out, int indent) {
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
      if (scalars) {
        out += "[";
        for (std::size_t i = 0; i < j.size(); ++i) {
          if (i) out += ", ";
          dump(j[i], out, indent + 1);
        }
        out += "]";
        return;
      }
      out += "[\n";
      for (std::size_t i = 0; i < j.size(); ++i) {
        if (i) out += ",\n";
        out += inner;
        dump(j[i], out, indent + 1);
      }
      out += "\n" + pad + "]";
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
    case Json::value_t::number_float: {
      const double v = j.get<double>();
      if (!std::isfinite(v)) { out += "null"; return; }  // JSON has no NaN/inf
      out += j.dump();
      return;
    }
    default:
      out += j.dump();
  }
}

}  // namespace

Json json_coordinate(double v) {
  if (!std::isfinite(v)) return nullptr;
  return std::string(coordinate_tag) + format_17(v);
}

Json json_point(double x, double y) { return Json::array({json_coordinate(x), json_coordinate(y)}); }

std::string dump_json(const Json& j) {
  std::string out;
  dump(j, out, 0);
  return out;
}

}  // namespace relgeo::tool
