// tools/relgeo/commands/csg/command.h — `relgeo csg`: a CSG tree of mesh
// files (JSON) evaluated with relgeo::csg.
#pragma once

#include <string>

#include "cli/text.h"
#include "relgeo/boolean/csg.h"

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
  bool skip_self_intersection_check = false;
  Format format = Format::text;
};

int run_csg_command(const Csg_command_options& options, Streams io);
std::string csg_help_footer();
void declare_csg_options(CLI::App& cmd, Csg_command_options& options);

/// The kernels `csg` runs (those relgeo::compiled instantiates).   [dispatch.cpp]
const std::vector<std::string>& csg_kernel_names();
/// \throws Usage_error, listing them, unless `name` is one of those kernels.
void validate_csg_kernel(const std::string& name);
/// relgeo::csg under the kernel named. \throws Usage_error for another name.
Csg_result evaluate_csg(const std::string& kernel, const Csg_node& tree, const Csg_options& options);

/// The tree of a JSON document: {"op": "union"|"intersection"|"difference",
/// "args": [NODE, ...]} or {"mesh": "file"}, files relative to `base`.
/// \throws Invalid_csg_node naming the node for anything else.   [command.cpp]
Csg_node parse_csg_tree(const std::string& json_file);

}  // namespace relgeo::tool
