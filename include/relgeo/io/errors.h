// relgeo/io/errors.h — the typed errors of relgeo's file readers and writers.
//
// Every reader reports bad input through relgeo::Error (core/errors.h):
//   file cannot be opened or read        relgeo::Unreadable_file
//   malformed content (garbage, wrong    relgeo::io::Parse_error (an Unreadable_file)
//     counts, not JSON, wrong field)       with the source name and the line
//   NaN, infinity, or a literal that     relgeo::Non_finite_input
//     rounds to infinity
//   content that parses but describes    relgeo::Invalid_input
//     an invalid object (open contour)
// and every writer a file it cannot write through relgeo::io::Unwritable_file.
#pragma once

#include <cstddef>
#include <string>

#include "relgeo/core/errors.h"

namespace relgeo::io {

/// Malformed content: `source` (a file name, "<stdin>", an option name) and
/// the 1-based line (0 when the format has no lines to name).
class Parse_error : public Unreadable_file {
 public:
  Parse_error(std::string source, std::size_t line, const std::string& message)
      : Unreadable_file(where(source, line) + ": " + message), source_(std::move(source)), line_(line) {}
  const std::string& source() const noexcept { return source_; }
  std::size_t line() const noexcept { return line_; }

  /// "SOURCE line N" (or "SOURCE" when line is 0): how messages name a place.
  static std::string where(const std::string& source, std::size_t line) {
    return line == 0 ? source : source + " line " + std::to_string(line);
  }

 private:
  std::string source_;
  std::size_t line_;
};

/// A file that cannot be written (bad folder, permissions, full disk). An
/// output path the user gave is input too: the code is invalid_input.
class Unwritable_file : public Invalid_input {
 public:
  explicit Unwritable_file(const std::string& what) : Invalid_input(what) {}
};

}  // namespace relgeo::io
