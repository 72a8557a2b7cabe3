// relgeo/io/number_text.h — doubles as text: correctly rounded reading of
// decimal literals, and printing that round-trips.
//
// Reading uses std::from_chars, which rounds to nearest (the literal's exact
// value, not a chain of decimal steps), with glibc's correctly rounded
// strtod for literals below the smallest subnormal (they round to a signed
// zero; from_chars refuses them). Printing with 17 significant digits reads
// back to the same double.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>

#include "relgeo/core/errors.h"
#include "relgeo/io/errors.h"

namespace relgeo::io {

namespace internal {
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
inline std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}
/// At most 60 characters of s, quoted, on one line (for messages).
inline std::string quoted(std::string_view s) {
  constexpr std::size_t max_shown = 60;
  std::string out = "'";
  for (char c : s.substr(0, max_shown)) out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
  if (s.size() > max_shown) out += "...";
  out += '\'';
  return out;
}
}  // namespace internal

/// The finite double nearest to the decimal literal `text` (blanks around it
/// and a leading '+' allowed). `source` and `line` name the place in errors.
/// \throws Parse_error for anything but one number (garbage, trailing
///   characters, empty text); relgeo::Non_finite_input for NaN, infinities
///   and literals beyond the range of double (they would round to infinity).
inline double parse_double(std::string_view text, const std::string& source, std::size_t line = 0) {
  const std::string_view s = internal::trim(text);
  std::string_view digits = s;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);  // from_chars rejects '+'
  if (digits.empty() || (digits.front() == '-' && s.front() == '+') || digits.front() == '+')
    throw Parse_error(source, line, internal::quoted(text) + " is not a number");
  double v = 0;
  const char* const end = digits.data() + digits.size();
  const auto [stop, ec] = std::from_chars(digits.data(), end, v, std::chars_format::general);
  if (ec == std::errc::result_out_of_range && stop == end) {
    // from_chars refuses underflow as well as overflow; strtod tells them apart.
    const std::string copy(digits);
    v = std::strtod(copy.c_str(), nullptr);
    if (!std::isfinite(v))
      throw Non_finite_input(Parse_error::where(source, line) + ": " + internal::quoted(text) +
                             " is out of the range of double");
    return v;
  }
  if (ec != std::errc() || stop != end)
    throw Parse_error(source, line, internal::quoted(text) + " is not a number");
  if (!std::isfinite(v))
    throw Non_finite_input(Parse_error::where(source, line) + ": " + internal::quoted(text) +
                           " is not finite (NaN and infinities are refused)");
  return v;
}

/// `v` with 17 significant digits (%.17g): reads back to the same double.
inline std::string format_17(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace relgeo::io
