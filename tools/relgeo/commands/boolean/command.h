// tools/relgeo/commands/boolean/command.h — `relgeo boolean`.
#pragma once

#include <string>

#include "cli/text.h"

namespace CLI {
class App;
}  // namespace CLI

namespace relgeo::tool {

struct Boolean_command_options {
  std::string op = "union";       ///< union | intersection | difference | xor
  std::string kernel = "filtered";
  std::string a, b;               ///< operand mesh files (OFF, OBJ, PLY, STL)
  std::string tags_a, tags_b;     ///< with --levels: the operands' crease/corner tag files
  std::string output;             ///< result mesh file, empty for none
  std::string tags_output;        ///< the result's crease tags (the intersection curves) as a side file
  std::string polyhedral_output;  ///< with --levels: the Boolean of the two limit meshes
  std::string report;             ///< JSON report file, empty for none
  std::string png;                ///< picture of the result with its curves drawn
  std::string oracle;             ///< "cgal": compare with CGAL's corefinement (Epeck)
  bool skip_self_intersection_check = false;
  std::string rounding = "repaired";  ///< repaired | nearest (Boolean_options::rounding)
  std::string retriangulation = "delaunay";  ///< delaunay | insertion (Boolean_options::delaunay_retriangulation)
  unsigned levels = 0;            ///< >= 1: the Boolean of two Loop subdivision solids at this level
  bool fit = false;               ///< with --levels: fit the control points near the curves
  Format format = Format::text;
};

int run_boolean_command(const Boolean_command_options& options, Streams io);
/// `relgeo boolean --levels K` (subdivision_command.cpp), called by run_boolean_command.
int run_subdivision_boolean_command(const Boolean_command_options& options, Streams io);
std::string boolean_help_footer();
void declare_boolean_options(CLI::App& cmd, Boolean_command_options& options);

}  // namespace relgeo::tool
