// relgeo/io/xml_text.h — text escaped for XML and HTML: the one escaping
// rule of the SVG pictures and the tool's HTML reports.
#pragma once

#include <string>
#include <string_view>

namespace relgeo::io {

/// What xml_escape does with control characters (below 0x20).
enum class Control_characters {
  blank,  ///< become blanks: XML 1.0 forbids most of them in a document
  keep    ///< stay as they are: in HTML text a line break is white space
};

/// Text with &, <, >, " escaped for XML.
inline std::string xml_escape(std::string_view s, Control_characters control = Control_characters::blank) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += control == Control_characters::blank && static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
  }
  return out;
}

}  // namespace relgeo::io
