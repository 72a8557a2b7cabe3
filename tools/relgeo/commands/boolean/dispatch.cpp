// tools/relgeo/commands/boolean/dispatch.cpp — relgeo::boolean under every
// kernel of the tool that models IntersectionKernel_3 (relgeo's own).
#include "commands/boolean/facade.h"
#include "kernels/dispatch.h"
#include "relgeo/boolean.h"
#include "relgeo/mesh/self_intersection.h"

namespace relgeo::tool {
namespace {

// relgeo's kernels (the CGAL adapters have no implicit points; their types
// are never completed here). MPFR at 53 and 113 bits only: compile time.
struct Intersection_kernels {
  template <class K>
  static constexpr bool check() {
    if constexpr (is_cgal_kernel_v<K>) return false;
    else if constexpr (mpfr_bits_v<K> > 0) return mpfr_bits_v<K> == 53 || mpfr_bits_v<K> == 113;
    else return IntersectionKernel_3<K>;
  }
  template <class K>
  static constexpr bool admits = check<K>();
};

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
    Boolean_run run;
    run.kernel = find_kernel(kernel).label();
    run.kernel_model = K::name();
    run.certified = K::is_certified;
    run.exact = K::has_exact_predicates;
    run.ok = r.ok();
    run.failure = r.failure;
    run.undecided_pairs = r.undecided_pairs;
    run.output = r.mesh;
    run.rounding_error = r.rounding_error;
    run.perturbations = r.perturbations;
    run.largest_perturbation = r.largest_perturbation;
    run.provenance = r.provenance;
    run.counts = r.counts;
    run.time = r.time;
    run.validation = r.validation;
    if constexpr (requires { { r.exact_vertices[0].point } -> std::same_as<const Point_3<mpq_class>&>; }) {
      if (r.ok()) {
        Triangle_mesh<Point_3<mpq_class>> exact;
        exact.faces = r.mesh.faces;
        for (const auto& v : r.exact_vertices) exact.vertices.push_back(v.point);
        run.exact_self_intersecting_pairs = find_self_intersections<K>(exact).pairs.size();
      }
    }
    return run;
  });
}

}  // namespace relgeo::tool
