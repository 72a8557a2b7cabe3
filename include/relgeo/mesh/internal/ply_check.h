// relgeo/mesh/internal/ply_check.h — a structural check of PLY files that
// read_mesh runs before CGAL's PLY reader (mesh_io.h).
//
// Why: CGAL 5.5's PLY reader trusts the file. A `property` line before any
// `element` line writes through the back() of an empty vector; a list whose
// count says 2^31 is resized to that before a single index is read; an
// element without properties is "read" as many times as its count says
// (found by fuzz/mesh_ply; doc/reliability.md). This check walks the header
// and the body with the sizes the header declares, without building
// anything, and refuses with Unreadable_file (naming the line of the header,
// or the element and item of the body) every file in which a count exceeds
// what the rest of the file holds, or falls short of it (data after the last
// element). Files that pass are read by CGAL.
#pragma once

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "relgeo/core/errors.h"

namespace relgeo::internal {

class Ply_check {
 public:
  Ply_check(std::string_view text, std::string path) : text_(text), path_(std::move(path)) {}

  void run() {
    header();
    for (const Element& e : elements_) {
      if (e.count > 0 && e.properties.empty())
        fail_header("element '" + e.name + "' has " + std::to_string(e.count) + " items but no properties");
      for (std::size_t item = 0; item < e.count; ++item)
        for (const Property& p : e.properties) value(p, e, item);
    }
    // More data than the elements announce: a count is wrong.
    const bool trailing = format_ == Format::ascii ? token() : pos_ < text_.size();
    if (trailing)
      throw Unreadable_file("PLY file '" + path_ + "': data after the last element (wrong counts?)");
  }

 private:
  struct Property {
    int size = 0;        ///< bytes of a value (or of a list item)
    int count_size = 0;  ///< bytes of a list's count, 0 for a scalar
    bool count_signed = false;
    bool is_signed = false, floating = false;  ///< of a value (or of a list item)
  };
  struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> properties;
  };
  enum class Format { ascii, little_endian, big_endian };

  [[noreturn]] void fail_header(const std::string& what) const {
    throw Unreadable_file("PLY file '" + path_ + "', header line " + std::to_string(line_) + ": " + what);
  }
  [[noreturn]] void fail_body(const Element& e, std::size_t item, const std::string& what) const {
    throw Unreadable_file("PLY file '" + path_ + "', element '" + e.name + "' item " + std::to_string(item) + ": " +
                          what);
  }

  /// Bytes of a PLY scalar type (and whether it is signed); 0 if unknown.
  static int type_size(std::string_view t, bool* is_signed = nullptr) {
    struct Type { std::string_view a, b; int size; bool sign; };
    static constexpr Type types[] = {{"char", "int8", 1, true},     {"uchar", "uint8", 1, false},
                                     {"short", "int16", 2, true},   {"ushort", "uint16", 2, false},
                                     {"int", "int32", 4, true},     {"uint", "uint32", 4, false},
                                     {"float", "float32", 4, true}, {"double", "float64", 8, true}};
    for (const Type& x : types)
      if (t == x.a || t == x.b) {
        if (is_signed) *is_signed = x.sign;
        return x.size;
      }
    return 0;
  }

  static std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> w;
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && is_space(line[i])) ++i;
      const std::size_t s = i;
      while (i < line.size() && !is_space(line[i])) ++i;
      if (i > s) w.push_back(line.substr(s, i - s));
    }
    return w;
  }
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

  void header() {
    for (;;) {
      if (pos_ >= text_.size()) fail_header("the file ends before end_header");
      const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
      const std::vector<std::string_view> w = words(text_.substr(pos_, end - pos_));
      pos_ = std::min(end + 1, text_.size());  // no newline at the end: stay at the end
      ++line_;
      if (line_ == 1) {
        if (w.empty() || w[0] != "ply") fail_header("'ply' expected");
        continue;
      }
      if (line_ == 2) {
        if (w.size() < 3 || w[0] != "format") fail_header("'format TYPE VERSION' expected");
        if (w[1] == "ascii") format_ = Format::ascii;
        else if (w[1] == "binary_little_endian") format_ = Format::little_endian;
        else if (w[1] == "binary_big_endian") format_ = Format::big_endian;
        else fail_header("unknown format '" + std::string(w[1].substr(0, 40)) + "'");
        continue;
      }
      if (w.empty()) fail_header("empty line");
      if (w[0] == "end_header") return;
      if (w[0] == "element") {
        std::size_t n = 0;
        if (w.size() < 3 || !integer(w[2], n)) fail_header("'element NAME COUNT' with a non-negative count expected");
        elements_.push_back({std::string(w[1].substr(0, 40)), n, {}});
      } else if (w[0] == "property") {
        if (elements_.empty()) fail_header("a property before any element");
        Property p;
        std::string_view type, name;
        if (w.size() >= 2 && w[1] == "list") {
          if (w.size() < 5) fail_header("'property list COUNT_TYPE ITEM_TYPE NAME' expected");
          p.count_size = type_size(w[2], &p.count_signed);
          p.size = type_size(w[3], &p.is_signed);
          if (p.count_size == 0 || p.count_size > 4 || w[2].find("float") != std::string_view::npos ||
              w[2] == "double")
            fail_header("list count type '" + std::string(w[2].substr(0, 40)) + "' is not an integer type");
          type = w[3], name = w[4];
        } else {
          if (w.size() < 3) fail_header("'property TYPE NAME' expected");
          p.size = type_size(w[1], &p.is_signed);
          type = w[1], name = w[2];
        }
        if (p.size == 0) fail_header("unknown property type");
        p.floating = type == "float" || type == "float32" || type == "double" || type == "float64";
        // CGAL's reader casts vertex coordinates to a float or double scalar
        // without checking (a null pointer for any other type, and for a
        // list; both found by fuzz/mesh_ply).
        const bool coordinate = elements_.back().name == "vertex" && (name == "x" || name == "y" || name == "z");
        if (coordinate && (p.count_size != 0 || !p.floating))
          fail_header("vertex coordinate '" + std::string(name) + "' declared as " +
                      (p.count_size != 0 ? std::string("a list") : "type '" + std::string(type.substr(0, 40)) + "'") +
                      ": a float or double scalar expected");
        elements_.back().properties.push_back(p);
      }
      // comment, obj_info and unknown keywords: ignored, as CGAL does
    }
  }

  static bool integer(std::string_view s, std::size_t& v) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && end == s.data() + s.size();
  }

  /// Skips one property value (a list: its count and items) of `item` of `e`.
  void value(const Property& p, const Element& e, std::size_t item) {
    if (format_ == Format::ascii) {
      if (p.count_size == 0) {
        ascii_number(p, e, item);
        return;
      }
      std::string_view c;
      if (!token(&c)) fail_body(e, item, "the file ends early");
      std::size_t n = 0;
      // A signed count above its type's maximum wraps to a negative one in
      // CGAL's reader, then to a huge size_t.
      const std::size_t max = (std::size_t{1} << (8 * p.count_size - (p.count_signed ? 1 : 0))) - 1;
      if (!integer(c, n) || n > max) fail_body(e, item, "list count '" + std::string(c.substr(0, 40)) + "' is not valid");
      if (n > (text_.size() - pos_) / 2 + 1) fail_body(e, item, "list count " + std::to_string(n) + " exceeds the rest of the file");
      for (std::size_t i = 0; i < n; ++i) ascii_number(p, e, item);
      return;
    }
    if (p.count_size == 0) {
      skip(static_cast<std::size_t>(p.size), e, item);
      return;
    }
    if (text_.size() - pos_ < static_cast<std::size_t>(p.count_size)) fail_body(e, item, "the file ends early");
    std::uint64_t n = 0;
    for (int i = 0; i < p.count_size; ++i) {
      const int k = format_ == Format::big_endian ? i : p.count_size - 1 - i;
      n = (n << 8) | static_cast<unsigned char>(text_[pos_ + static_cast<std::size_t>(k)]);
    }
    if (p.count_signed && (n >> (8 * p.count_size - 1)) != 0) fail_body(e, item, "negative list count");
    pos_ += static_cast<std::size_t>(p.count_size);
    if (n > (text_.size() - pos_) / static_cast<std::size_t>(p.size))
      fail_body(e, item, "list count " + std::to_string(n) + " exceeds the rest of the file");
    skip(static_cast<std::size_t>(n) * static_cast<std::size_t>(p.size), e, item);
  }
  /// Reads one ASCII value of p's (item) type and refuses it unless CGAL's
  /// reader takes the same token whole and without a stream failure: a
  /// failed or partial read leaves its stream out of step with the file, and
  /// a later list count is then read as garbage (or 2^32 - 1) and allocated
  /// (found by fuzz/mesh_ply: "1..0" read as "1." and ".0"). Integers:
  /// optional sign and digits, in the range CGAL reads them with (short for
  /// 8-bit types, as it widens them); floats: a decimal number, finite in
  /// the type.
  void ascii_number(const Property& p, const Element& e, std::size_t item) {
    std::string_view t;
    if (!token(&t)) fail_body(e, item, "the file ends early");
    const auto bad = [&](const char* why) {
      fail_body(e, item, "value '" + std::string(t.substr(0, 40)) + "' " + why);
    };
    std::string_view digits = t;
    if (!digits.empty() && (digits[0] == '+' || digits[0] == '-')) digits.remove_prefix(1);
    if (digits.empty() || !(std::isdigit(static_cast<unsigned char>(digits[0])) || digits[0] == '.'))
      bad("is not a number");
    if (p.floating) {
      double v = 0;
      const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
      if (ec != std::errc() || end != digits.data() + digits.size()) bad("is not a finite decimal number");
      if (p.size == 4 && std::fabs(v) > double(std::numeric_limits<float>::max())) bad("overflows a float");
      return;
    }
    if (!p.is_signed && t[0] == '-') bad("is negative for an unsigned type");
    long long v = 0;
    const auto [end, ec] = std::from_chars(t.data() + (t[0] == '+'), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) bad("is not an integer");
    const int bytes = std::max(p.size, 2);  // 8-bit types are read as 16-bit ones
    const long long hi = p.is_signed ? (1LL << (8 * bytes - 1)) - 1 : (1LL << (8 * bytes)) - 1;
    if (v > hi || v < (p.is_signed ? -hi - 1 : 0)) bad("is out of the type's range");
  }
  void skip(std::size_t bytes, const Element& e, std::size_t item) {
    if (text_.size() - pos_ < bytes) fail_body(e, item, "the file ends early");
    pos_ += bytes;
  }
  bool token(std::string_view* out = nullptr) {
    while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
    const std::size_t s = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    if (out) *out = text_.substr(s, pos_ - s);
    return pos_ > s;
  }

  std::string_view text_;
  std::string path_;
  std::size_t pos_ = 0, line_ = 0;
  Format format_ = Format::ascii;
  std::vector<Element> elements_;
};

/// Throws Unreadable_file unless the PLY text `text` of file `path` is
/// structurally sound (see the file comment).
inline void check_ply_structure(std::string_view text, const std::string& path) { Ply_check(text, path).run(); }

}  // namespace relgeo::internal
