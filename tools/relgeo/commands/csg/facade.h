// tools/relgeo/commands/csg/facade.h — what `relgeo csg` and the Python
// module's csg() run: the tree read from its JSON document (leaves read by
// the caller's reader), relgeo::csg under a kernel named at run time
// (dispatch.cpp only) and the JSON record of `relgeo csg --format json`.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "relgeo/boolean/csg.h"
#include "relgeo/io/json.h"

namespace relgeo::tool {

/// The kernels `csg` runs (those relgeo::compiled instantiates).   [dispatch.cpp]
const std::vector<std::string>& csg_kernel_names();
/// \throws Usage_error, listing them, unless `name` is one of those kernels.
void validate_csg_kernel(const std::string& name);
/// relgeo::csg under the kernel named. \throws Usage_error for another name.
Csg_result evaluate_csg(const std::string& kernel, const Csg_node& tree, const Csg_options& options);

/// The options of `relgeo csg --rounding R --retriangulation T
/// --intermediates I [--skip-self-intersection-check]` under `kernel`.
/// \throws Usage_error for a bad name, and for exact intermediates under a
/// kernel other than exact (before any file is read).   [tree.cpp]
Csg_options csg_options(const std::string& rounding, const std::string& retriangulation, bool check_self_intersections,
                        const std::string& intermediates, const std::string& kernel);

/// The solid of a leaf {"mesh": M}, given M and the leaf's path ("root.1").
using Csg_leaf_reader = std::function<Csg_node(const io::Json& mesh, const std::string& node)>;

/// The tree of a JSON document: {"op": "union"|"intersection"|"difference",
/// "args": [NODE, ...]} or a leaf {"mesh": M}, M given to `read_leaf`.
/// \throws Invalid_csg_node naming the node for anything else.     [tree.cpp]
Csg_node parse_csg_tree(const io::Json& tree, const Csg_leaf_reader& read_leaf);
/// The tool's leaf: M a file name relative to `base`, read as a mesh file.
/// \throws Invalid_csg_node naming the node when M is no string or the file
/// cannot be read.
Csg_node read_csg_mesh_file(const io::Json& mesh, const std::filesystem::path& base, const std::string& node);
/// The tree of a JSON file, its leaves' files relative to the file's folder.
/// \throws Unreadable_file, io::Parse_error, Invalid_csg_node.
Csg_node parse_csg_tree(const std::string& json_file);

/// The record of `relgeo csg --format json`: tree, kernel, intermediates,
/// status, failure, steps [...], output {vertices, faces, volume, rounding,
/// validation}, seconds, total_seconds.
/// `rounding` as asked (the double kernel's Booleans round to nearest
/// whatever it is).                                               [report.cpp]
io::Json csg_report_json(const std::string& tree, const std::string& kernel, const std::string& rounding,
                         const Csg_result& result, double total_seconds, Csg_intermediates intermediates);

}  // namespace relgeo::tool
