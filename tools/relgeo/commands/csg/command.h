// tools/relgeo/commands/csg/command.h — `relgeo csg`: a CSG tree of mesh
// files (JSON) evaluated with relgeo::csg.
#pragma once

#include <string>

#include "cli/text.h"
#include "commands/csg/facade.h"

namespace CLI {
class App;
}  // namespace CLI

namespace relgeo::tool {

struct Csg_command_options {
  std::string tree;               ///< the tree's JSON file
  std::string kernel = "filtered";
  std::string output;             ///< the root's solid (format from the extension), empty for none
  std::string report;             ///< JSON report file, empty for none
  std::string rounding = "repaired";
  std::string retriangulation = "delaunay";
  std::string intermediates = "rounded";
  bool skip_self_intersection_check = false;
  Format format = Format::text;
};

int run_csg_command(const Csg_command_options& options, Streams io);
std::string csg_help_footer();
void declare_csg_options(CLI::App& cmd, Csg_command_options& options);

}  // namespace relgeo::tool
