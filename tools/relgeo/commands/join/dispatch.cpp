// tools/relgeo/commands/join/dispatch.cpp — run_join_tool under the kernels
// of the joiner's certified checks (the compile firewall: the only file of
// `join` naming kernel types and instantiating run_with.h).
#include "kernels/dispatch.h"

#include <cmath>
#include <map>
#include <optional>
#include <type_traits>

#include "cli/text.h"
#include "commands/join/facade.h"
#include "commands/join/join_kernels.h"
#include "commands/join/run_with.h"
#include "relgeo/joining/error_measures.h"
#include "relgeo/joining/projection.h"

namespace relgeo::tool {

namespace {

template <std::size_t... I>
std::vector<std::string> admitted_names(std::index_sequence<I...>) {
  std::vector<std::string> names;
  const auto& registry = kernel_registry();
  ((Join_kernels::admits<kernel_at<I>> ? names.push_back(registry[I].label()) : void()), ...);
  return names;
}

/// Every face's triangles of the result with their corners projected onto
/// the face, classified by K's certified orientation in (u,v).
template <class K>
std::vector<Join_face_picture> face_pictures(const Surface_model& model, const Join_command_report& r,
                                             const Projection_options& projection) {
  std::vector<Join_face_picture> out(model.faces.size());
  for (std::size_t f = 0; f < model.faces.size(); ++f) {
    const Trimmed_surface& face = model.faces[f];
    Join_face_picture& p = out[f];
    p.domain = face.domain_polygon();
    const Surface_projector projector(face.surface(), projection);
    // A vertex that does not project (a naive result may move seam vertices
    // off the face) leaves its triangles out of the picture: counted.
    std::map<Index, std::optional<Index>> local;
    for (std::size_t t = 0; t < r.mesh.faces.size(); ++t) {
      if (t >= r.face_of_triangle.size() || r.face_of_triangle[t] != f) continue;
      Triangle g;
      bool placed = true;
      for (int i = 0; i < 3 && placed; ++i) {
        const Index v = r.mesh.faces[t][i];
        auto it = local.find(v);
        if (it == local.end()) {
          std::optional<Index> at;
          try {
            const Point_2<double> uv = projector.project(r.mesh.vertices[v]).uv;
            at = static_cast<Index>(p.uv.size());
            p.uv.push_back(uv);
          } catch (const Projection_error&) {
          }
          it = local.emplace(v, at).first;
        }
        placed = it->second.has_value();
        if (placed) g[i] = *it->second;
      }
      if (placed) p.triangles.push_back(g);
      else ++p.unprojected;
    }
    const Orientation_report o = uv_orientations<K>(
        p.triangles, p.uv, face.reversed() ? Certified_sign::negative : Certified_sign::positive);
    p.flipped.assign(p.triangles.size(), false);
    for (const auto* list : {&o.flipped_faces, &o.degenerate_faces, &o.undecided_faces})
      for (Index t : *list) p.flipped[t] = true;
  }
  return out;
}

/// run_with.h's options from the command line's (already checked).
Join_command_options library_options(const Join_tool_options& o, const std::string& output) {
  Join_command_options c;
  c.surface = o.surface;
  c.meshes = o.meshes;
  c.mesh_data = o.mesh_data;
  c.curves = o.curves;
  c.output = output;
  c.method = o.method;
  c.max_absolute_error = o.max_absolute_error;
  c.max_normal_error = o.max_normal_error;
  c.join.use_edge_curves = !o.no_edge_curves;
  c.join.central.layers = o.layers;
  if (o.min_angle != 0) {  // 0: the library's shape bound 0.125 (20.7 degrees)
    const double s = std::sin(o.min_angle * M_PI / 180);
    c.join.external.shape_bound = s * s;
  }
  c.join.whitney.slope_margin = o.slope_margin;
  c.join.projection.extrapolation = o.extrapolation;
  return c;
}

}  // namespace

const std::vector<std::string>& join_kernel_names() {
  static const std::vector<std::string> names = admitted_names(std::make_index_sequence<kernel_count>{});
  return names;
}

void validate_join_kernel(const std::string& name) {
  const Kernel_entry& k = find_kernel(name);  // unknown names: the tool's usual message
  for (const auto& n : join_kernel_names())
    if (n == k.label()) return;
  std::string list;
  for (const auto& n : join_kernel_names()) list += (list.empty() ? "" : ", ") + n;
  throw Usage_error("kernel '" + name + "' is not supported by join (its certified checks need one of: " + list + ")");
}

Join_tool_result run_join_tool(const Join_tool_options& options, const std::string& output, bool pictures) {
  validate_join_kernel(options.kernel);
  const Join_command_options c = library_options(options, output);
  return with_kernel<Join_kernels>(options.kernel, [&]<class K>(const K&) {
    const Join_command_report cr = run_join_with<K>(c);
    Join_tool_result r;
    r.status = cr.status, r.failure = cr.failure, r.faces = cr.faces;
    r.report = cr.report;
    r.json = to_json(cr);
    r.kernel_model = K::name();
    r.mesh = cr.mesh;
    r.face_of_triangle = cr.face_of_triangle;
    if (pictures) r.pictures = face_pictures<K>(cr.model, cr, c.join.projection);
    return r;
  });
}

}  // namespace relgeo::tool
