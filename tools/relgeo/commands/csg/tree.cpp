// tools/relgeo/commands/csg/tree.cpp — a CSG tree from its JSON document
// (`relgeo csg TREE.json`, the Python module's csg()), and csg's options.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "cli/text.h"
#include "commands/boolean/facade.h"
#include "commands/csg/facade.h"
#include "relgeo/io/text_file.h"
#include "relgeo/mesh/mesh_io.h"

namespace relgeo::tool {

namespace {

Csg_node parse_node(const io::Json& j, const Csg_leaf_reader& read_leaf, const std::string& path) {
  if (!j.is_object())
    throw Invalid_csg_node(path, "not an object: {\"op\": ..., \"args\": [...]} or {\"mesh\": \"file\"}");
  if (j.contains("mesh")) return read_leaf(j["mesh"], path);
  if (!j.contains("op") || !j["op"].is_string())
    throw Invalid_csg_node(path, "neither \"mesh\" nor \"op\" (union, intersection or difference)");
  const std::string op = j["op"].get<std::string>();
  Csg_node::Kind kind;
  if (op == "union")
    kind = Csg_node::Kind::union_of;
  else if (op == "intersection")
    kind = Csg_node::Kind::intersection;
  else if (op == "difference")
    kind = Csg_node::Kind::difference;
  else
    throw Invalid_csg_node(path, "unknown op '" + op + "': use union, intersection or difference");
  if (!j.contains("args") || !j["args"].is_array()) throw Invalid_csg_node(path, "\"args\" must be an array of nodes");
  std::vector<Csg_node> args;
  for (std::size_t i = 0; i < j["args"].size(); ++i)
    args.push_back(parse_node(j["args"][i], read_leaf, path + "." + std::to_string(i)));
  if (args.size() < 2)
    throw Invalid_csg_node(path, op + " of " + std::to_string(args.size()) + " argument(s): two or more are needed");
  return Csg_node::operation(kind, std::move(args));
}

}  // namespace

Csg_options csg_options(const std::string& rounding, const std::string& retriangulation,
                        bool check_self_intersections, const std::string& intermediates, const std::string& kernel) {
  Csg_options options;
  if (intermediates == "exact") {
    // (The tool's other kernels compute in doubles: no exact point to keep.)
    if (kernel != "exact")
      throw Usage_error("csg: --intermediates exact keeps every result in exact rationals: it needs --kernel exact, not " +
                        kernel);
    options.intermediates = Csg_intermediates::exact;
  } else if (intermediates != "rounded") {
    throw Usage_error("csg: --intermediates '" + intermediates + "' is not one of rounded, exact");
  }
  options.boolean.rounding = parse_output_rounding(rounding);
  options.boolean.delaunay_retriangulation = parse_delaunay_retriangulation(retriangulation);
  options.boolean.check_self_intersections = check_self_intersections;
  return options;
}

Csg_node parse_csg_tree(const io::Json& tree, const Csg_leaf_reader& read_leaf) {
  return parse_node(tree, read_leaf, "root");
}

Csg_node read_csg_mesh_file(const io::Json& mesh, const std::filesystem::path& base, const std::string& node) {
  if (!mesh.is_string()) throw Invalid_csg_node(node, "\"mesh\" must be a file name");
  const std::string name = mesh.get<std::string>();
  const std::string file = (base / name).string();
  try {
    return Csg_node::solid(read_mesh(file), name);
  } catch (const Invalid_input& e) {
    throw Invalid_csg_node(node, "cannot read '" + file + "': " + e.what());
  }
}

Csg_node parse_csg_tree(const std::string& json_file) {
  const io::Json j = io::parse_json(io::read_text_file(json_file, "CSG tree"), json_file);
  const std::filesystem::path base = std::filesystem::path(json_file).parent_path();
  return parse_csg_tree(
      j, [&](const io::Json& mesh, const std::string& node) { return read_csg_mesh_file(mesh, base, node); });
}

}  // namespace relgeo::tool
