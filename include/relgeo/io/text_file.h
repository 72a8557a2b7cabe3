// relgeo/io/text_file.h — whole files as text: read a path (or a stream such
// as standard input), write a path, with typed errors that name the file.
#pragma once

#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <string>
#include <string_view>
#include <system_error>

#include "relgeo/core/errors.h"
#include "relgeo/io/errors.h"

namespace relgeo::io {

/// The contents of the file `path`; `what` names it in messages ("point file").
/// \throws relgeo::Unreadable_file for an empty name, a folder, a missing or
///   unreadable file (the message says which).
inline std::string read_text_file(const std::string& path, std::string_view what = "file") {
  const std::string name = std::string(what) + " '" + path + "'";
  if (path.empty()) throw Unreadable_file("cannot read " + std::string(what) + ": empty file name");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Unreadable_file("cannot read " + name + ": it is a folder");
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    const bool exists = std::filesystem::exists(path, ec);
    throw Unreadable_file("cannot read " + name + ": " +
                          (exists ? "permission denied or unreadable" : "no such file"));
  }
  std::string text{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  if (f.bad()) throw Unreadable_file("cannot read " + name + ": read error");
  return text;
}

/// Everything left in `in` (e.g. std::cin); `source` names it in messages.
/// \throws relgeo::Unreadable_file on a read error.
inline std::string read_text_stream(std::istream& in, std::string_view source = "<stdin>") {
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw Unreadable_file("cannot read " + std::string(source));
  return text;
}

/// Writes `text` to `path` (replacing it). \throws Unwritable_file.
inline void write_text_file(const std::string& path, std::string_view text, std::string_view what = "file") {
  std::ofstream f(path, std::ios::binary);
  f.write(text.data(), static_cast<std::streamsize>(text.size()));
  f.close();
  if (!f) throw Unwritable_file("cannot write " + std::string(what) + " '" + path + "'");
}

}  // namespace relgeo::io
