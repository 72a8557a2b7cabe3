// tools/relgeo/commands/boolean/dispatch.cpp — relgeo::boolean under every
// kernel of the tool that models IntersectionKernel_3 (relgeo's own and
// CGAL's Epeck).
#include "kernels/cgal_kernels.h"
#include "commands/boolean/facade.h"
#include "commands/boolean/intersection_kernels.h"
#include "commands/boolean/run_of.h"
#include "relgeo/boolean.h"
#include "relgeo/mesh/self_intersection.h"

namespace relgeo::tool {
namespace {

// Relgeo_intersection_kernels and the CGAL adapters that model
// IntersectionKernel_3 (Epeck): the CGAL types are complete in this file.
struct Intersection_kernels {
  template <class K>
  static constexpr bool check() {
    if constexpr (is_cgal_kernel_v<K>) return IntersectionKernel_3<K>;
    else return Relgeo_intersection_kernels::admits<K>;
  }
  template <class K>
  static constexpr bool admits = check<K>();
};

}  // namespace

const std::vector<std::string>& boolean_kernel_names() {
  static const std::vector<std::string> names = admitted_kernel_names<Intersection_kernels>();
  return names;
}

void validate_boolean_kernel(const std::string& name) {
  const Kernel_entry& e = find_kernel(name);
  for (const std::string& n : boolean_kernel_names())
    if (n == e.label()) return;
  throw Usage_error("kernel '" + name + "' cannot run a Boolean (no implicit points); use one of: " +
                    comma_list(boolean_kernel_names()));
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
