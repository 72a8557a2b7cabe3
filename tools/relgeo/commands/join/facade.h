// tools/relgeo/commands/join/facade.h — what `relgeo join` and the
// experiment's joining section run: run_join_with (run_with.h) under a kernel
// named at run time (instantiated in dispatch.cpp only, with the joiner's
// heavy headers), and the result's triangles classified in each face's (u,v)
// domain for the pictures. Light: no kernel, CGAL or Eigen header.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "commands/join/command.h"
#include "relgeo/io/json.h"
#include "relgeo/joining/join_report.h"
#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::tool {

/// The kernels `join` accepts (its certified checks): failsafe, interval,
/// filtered, exact.                                      [dispatch.cpp]
const std::vector<std::string>& join_kernel_names();
/// Throws Usage_error unless `name` names one of join_kernel_names().
void validate_join_kernel(const std::string& name);

/// One face's part of the result in its (u,v) domain.
struct Join_face_picture {
  std::vector<std::vector<Point_2<double>>> domain;  ///< trim loops (outer first)
  std::vector<Point_2<double>> uv;                   ///< result vertices projected onto the face
  std::vector<Triangle> triangles;                   ///< over `uv`
  std::vector<bool> flipped;                         ///< per triangle: flipped, degenerate or undecided (certified)
  std::size_t unprojected = 0;                       ///< triangles left out: a corner has no projection
};

/// What one run gives.
struct Join_tool_result {
  std::string status = "ok", failure;  ///< Join_command_report's verdict (run_with.h)
  std::size_t faces = 0;
  Join_report report;
  io::Json json;                       ///< to_json(Join_command_report) (run_with.h)
  std::string kernel_model;            ///< K::name()
  std::vector<Join_face_picture> pictures;  ///< per face, when asked for
  Mesh_double mesh;                         ///< the joined mesh
  std::vector<Index> face_of_triangle;      ///< the model face of each of its triangles
};

/// Reads, joins and writes `output` as run_join_with (run_with.h) does, under
/// the kernel named `options.kernel`, with the options' criteria and joiner
/// parameters (checked by the command before). With `pictures`, also
/// classifies the result's triangles per face.
/// \throws relgeo::Error as run_join_with does, Usage_error for a kernel join
/// does not take.
Join_tool_result run_join_tool(const Join_tool_options& options, const std::string& output, bool pictures);

/// Throws Usage_error for options `relgeo join` refuses (no surface, no
/// mesh, a bad method, kernel or joiner parameter); the library checks the
/// files.                                                  [facade.cpp]
void validate_join_options(const Join_tool_options& options);
/// run_join_tool, its typed errors rewritten to say which step they belong
/// to (a mesh that does not project onto its face, meshes that do not fit
/// the model), as `relgeo join` reports them.             [facade.cpp]
Join_tool_result run_join_explained(const Join_tool_options& options, const std::string& output, bool pictures);
/// The record of `relgeo join --format json` (without "svg").   [facade.cpp]
io::Json join_report_json(const Join_tool_options& options, const std::string& output, const Join_tool_result& result);

/// The largest of a per-face measure over a report's faces (0 for none).
template <class F>
double largest(const Join_report& r, F&& of) {
  double m = 0;
  for (const Join_face_report& f : r.faces) m = std::max(m, of(f));
  return m;
}
/// The sum of a per-face count over a report's faces.
template <class F>
std::size_t total(const Join_report& r, F&& of) {
  std::size_t n = 0;
  for (const Join_face_report& f : r.faces) n += of(f);
  return n;
}

}  // namespace relgeo::tool
