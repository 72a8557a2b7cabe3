// tools/relgeo/commands/boolean/dispatch.cpp — relgeo::boolean under every
// kernel of the tool that models IntersectionKernel_3 (relgeo's own and
// CGAL's Epeck).
#include "kernels/cgal_kernels.h"
#define RELGEO_TOOL_CGAL_KERNELS_COMPLETE 1
#include "commands/boolean/facade.h"
#include "commands/boolean/intersection_kernels.h"
#include "commands/boolean/run_of.h"
#include "relgeo/boolean.h"
#include "relgeo/mesh/self_intersection.h"

namespace relgeo::tool {
namespace {

template <std::size_t... I>
std::vector<std::string> admitted_names(std::index_sequence<I...>) {
  std::vector<std::string> n;
  ((Intersection_kernels::admits<kernel_at<I>> ? n.push_back(kernel_registry()[I].label()) : void()), ...);
  return n;
}

}  // namespace

const std::vector<std::string>& boolean_kernel_names() {
  static const std::vector<std::string> names = admitted_names(std::make_index_sequence<kernel_count>{});
  return names;
}

void validate_boolean_kernel(const std::string& name) {
  const Kernel_entry& e = find_kernel(name);
  for (const std::string& n : boolean_kernel_names())
    if (n == e.label()) return;
  std::string list;
  for (const std::string& n : boolean_kernel_names()) list += (list.empty() ? "" : ", ") + n;
  throw Usage_error("kernel '" + name + "' cannot run a Boolean (no implicit points); use one of: " + list);
}

Boolean_run evaluate_boolean(const std::string& kernel, const Mesh_double& a, const Mesh_double& b, Boolean_operation op,
                             const Boolean_options& options) {
  validate_boolean_kernel(kernel);
  return with_kernel<Intersection_kernels>(find_kernel(kernel), [&](auto k) {
    using K = decltype(k);
    const auto r = relgeo::boolean(a, b, op, k, options);
    Boolean_run run = boolean_run_of(r, find_kernel(kernel).label());
    if (K::is_certified && options.rounding == Output_rounding::repaired) run.rounding_method = "repaired";
    // Exact kernels whose implicit points are exact points (Exact_kernel,
    // Epeck): the result before rounding, tested for self-intersections
    // (unless the repair of the rounding flipped or collapsed edges: those
    // faces are not the exact result's).
    if constexpr (K::has_exact_constructions &&
                  requires { { r.exact_vertex(0).point } -> std::convertible_to<typename K::Point_3>; }) {
      if (r.ok() && r.rounding.flips == 0 && r.rounding.collapses == 0) {
        Triangle_mesh<typename K::Point_3> exact;
        exact.faces = r.mesh.faces;
        for (const auto& v : r.exact_vertices()) exact.vertices.push_back(v.point);
        run.exact_self_intersecting_pairs = find_self_intersections<K>(exact).pairs.size();
      }
    }
    return run;
  });
}

}  // namespace relgeo::tool
