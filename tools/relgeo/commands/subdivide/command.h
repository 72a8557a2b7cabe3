// tools/relgeo/commands/subdivide/command.h — `relgeo subdivide`.
#pragma once

#include <string>

#include "cli/text.h"

namespace CLI {
class App;
}  // namespace CLI

namespace relgeo::tool {

struct Subdivide_options {
  std::string input;        ///< mesh file (OFF, OBJ, PLY, STL), "-" for OFF on standard input
  std::string tags;         ///< feature tag file (crease a b / corner v), empty for none
  std::string output;       ///< mesh file to write (format by extension); empty: default_subdivide_output
  std::string report;       ///< JSON report file, empty for none
  std::string kernel = "double";
  std::string rules = "hoppe";  ///< hoppe | blz
  int levels = 1;
  bool limit = false;       ///< write the limit mesh instead of the refined mesh
  bool bounds = false;      ///< compute the error bounds of the limit mesh
  int samples = 8;          ///< sample grid per face side (power of two, 0: no sampling)
  Format format = Format::text;
};

int run_subdivide_command(const Subdivide_options& options, Streams io);

/// The output file when none is given: in the current folder, the input's
/// name with "_L<levels>" (and "_limit") before its extension
/// (box.off -> box_L1.off); standard input: subdivided_L<levels>.off.
std::string default_subdivide_output(const Subdivide_options& options);

/// The text of `relgeo help subdivide` below the options.
std::string subdivide_help_footer();

/// Declares the options on the subcommand.         [options.cpp]
void declare_subdivide_options(CLI::App& cmd, Subdivide_options& options);

}  // namespace relgeo::tool
