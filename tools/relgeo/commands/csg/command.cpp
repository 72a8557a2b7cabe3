// tools/relgeo/commands/csg/command.cpp — `relgeo csg`: read the tree and its
// meshes, evaluate, write the solid and the report.
#include "commands/csg/command.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "commands/boolean/facade.h"
#include "commands/boolean/report.h"
#include "relgeo/core/internal/stopwatch.h"
#include "relgeo/io/errors.h"
#include "relgeo/io/json.h"
#include "relgeo/io/text_file.h"
#include "relgeo/mesh/mesh_io.h"

namespace relgeo::tool {
namespace {

Csg_node parse_node(const io::Json& j, const std::filesystem::path& base, const std::string& path) {
  if (!j.is_object()) throw Invalid_csg_node(path, "not an object: {\"op\": ..., \"args\": [...]} or {\"mesh\": \"file\"}");
  if (j.contains("mesh")) {
    if (!j["mesh"].is_string()) throw Invalid_csg_node(path, "\"mesh\" must be a file name");
    const std::string name = j["mesh"].get<std::string>();
    const std::string file = (base / name).string();
    try {
      return Csg_node::solid(read_mesh(file), name);
    } catch (const Invalid_input& e) {
      throw Invalid_csg_node(path, "cannot read '" + file + "': " + e.what());
    }
  }
  if (!j.contains("op") || !j["op"].is_string())
    throw Invalid_csg_node(path, "neither \"mesh\" nor \"op\" (union, intersection or difference)");
  const std::string op = j["op"].get<std::string>();
  Csg_node::Kind kind;
  if (op == "union") kind = Csg_node::Kind::union_of;
  else if (op == "intersection") kind = Csg_node::Kind::intersection;
  else if (op == "difference") kind = Csg_node::Kind::difference;
  else throw Invalid_csg_node(path, "unknown op '" + op + "': use union, intersection or difference");
  if (!j.contains("args") || !j["args"].is_array()) throw Invalid_csg_node(path, "\"args\" must be an array of nodes");
  std::vector<Csg_node> args;
  for (std::size_t i = 0; i < j["args"].size(); ++i) args.push_back(parse_node(j["args"][i], base, path + "." + std::to_string(i)));
  if (args.size() < 2)
    throw Invalid_csg_node(path, op + " of " + std::to_string(args.size()) + " argument(s): two or more are needed");
  return Csg_node::operation(kind, std::move(args));
}

io::Json report_json(const Csg_command_options& o, const Csg_result& r, double total_seconds) {
  // The double kernel is not certified: its Booleans round to nearest.
  const std::string method = o.kernel == "double" ? "nearest" : o.rounding;
  io::Json steps = io::Json::array();
  for (const Csg_step& s : r.steps) {
    steps.push_back({{"node", s.node},
                     {"operation", std::string(to_string(s.operation))},
                     {"ok", s.ok},
                     {"failure", s.failure},
                     {"faces", s.faces},
                     {"volume", io::json_measure(s.volume)},
                     {"validation", s.validation},
                     {"rounding", rounding_repair_json(s.rounding, method)},
                     {"seconds", s.seconds}});
  }
  return io::Json{{"tree", o.tree},
                  {"kernel", o.kernel},
                  {"status", r.ok() ? "ok" : "failed"},
                  {"failure", r.failure},
                  {"steps", steps},
                  {"output",
                   {{"vertices", r.mesh.vertices.size()},
                    {"faces", r.mesh.faces.size()},
                    {"volume", io::json_measure(r.steps.empty() ? 0.0 : r.steps.back().volume)}}},
                  {"seconds", r.seconds},
                  {"total_seconds", total_seconds}};
}

std::string report_text(const Csg_result& r) {
  std::ostringstream s;
  char buf[256];
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const Csg_step& st = r.steps[i];
    std::snprintf(buf, sizeof buf, "step %-3zu %-14s %-12s %-7s %7zu faces  volume %.12g  %.4f s", i + 1, st.node.c_str(),
                  std::string(to_string(st.operation)).c_str(), st.ok ? "ok" : "FAILED", st.faces, st.volume, st.seconds);
    s << buf;
    if (st.rounding.defects_before)
      s << "  (rounding: " << st.rounding.defects_before << " defects repaired)";
    s << "  " << st.validation << "\n";
  }
  s << "status           " << (r.ok() ? "ok" : "failed: " + r.failure) << "\n";
  s << "output           " << r.mesh.vertices.size() << " vertices, " << r.mesh.faces.size() << " faces\n";
  std::snprintf(buf, sizeof buf, "%.4f s for %zu Booleans", r.seconds, r.steps.size());
  s << "time             " << buf << "\n";
  return s.str();
}

}  // namespace

Csg_node parse_csg_tree(const std::string& json_file) {
  const io::Json j = io::parse_json(io::read_text_file(json_file, "CSG tree"), json_file);
  return parse_node(j, std::filesystem::path(json_file).parent_path(), "root");
}

int run_csg_command(const Csg_command_options& o, Streams io) {
  if (o.tree.empty()) throw Usage_error("a tree is needed: relgeo csg TREE.json");
  validate_csg_kernel(o.kernel);  // before any file is read
  internal::Stopwatch clock;
  Csg_options options;
  options.boolean.rounding = parse_output_rounding(o.rounding);
  options.boolean.delaunay_retriangulation = parse_delaunay_retriangulation(o.retriangulation);
  options.boolean.check_self_intersections = !o.skip_self_intersection_check;
  const Csg_node tree = parse_csg_tree(o.tree);
  const Csg_result r = evaluate_csg(o.kernel, tree, options);
  if (!o.output.empty()) write_mesh(o.output, r.mesh);
  const io::Json json = report_json(o, r, clock.elapsed());
  if (!o.report.empty()) {
    std::ofstream f(o.report);
    f << io::dump_json(json) << '\n';
    if (!f) throw io::Unwritable_file("cannot write the report '" + o.report + "'");
  }
  if (o.format == Format::json) io.out << io::dump_json(json) << '\n';
  else io.out << report_text(r);
  if (!r.ok()) {
    io.err << "relgeo: failure: " << r.failure << '\n';
    return exit_failure;
  }
  return exit_success;
}

}  // namespace relgeo::tool
