// tools/relgeo/commands/boolean/dispatch_subdivision.cpp —
// relgeo::subdivision_boolean under every kernel `relgeo boolean` accepts
// (the one translation unit that instantiates it), and the limit meshes of
// the pictures.
#include "commands/boolean/intersection_kernels.h"
#include "commands/boolean/run_of.h"
#include "commands/boolean/subdivision_facade.h"
#include "relgeo/boolean.h"
#include "relgeo/boolean/subdivision_boolean.h"
#include "relgeo/subdivision/loop_subdivision.h"

namespace relgeo::tool {

Subdivision_boolean_run evaluate_subdivision_boolean(const std::string& kernel, const Mesh_double& a,
                                                     const Mesh_double& b, Boolean_operation op, unsigned levels,
                                                     const Subdivision_boolean_options& options) {
  validate_boolean_kernel(kernel);
  const Kernel_entry& entry = find_kernel(kernel);
  if (entry.cgal)  // keeps CGAL's kernels out of this translation unit
    throw Usage_error("kernel '" + kernel + "': --levels runs under relgeo's kernels only");
  return with_kernel<Relgeo_intersection_kernels>(entry, [&](auto k) {
    using K = decltype(k);
    const Subdivision_boolean_result<K> r = relgeo::subdivision_boolean(a, b, op, levels, k, options);
    Subdivision_boolean_run run;
    static_cast<Subdivision_boolean_output&>(run) = r;
    set_kernel_fields<K>(run, entry.label());
    run.polyhedral = boolean_run_of(r.polyhedral, entry.label());
    return run;
  });
}

Mesh_double finer_limit_mesh(const Mesh_double& control, unsigned levels, const Loop_options& loop) {
  return loop_limit_mesh(control, levels, loop);
}

}  // namespace relgeo::tool
