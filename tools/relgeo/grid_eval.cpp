// tools/relgeo/grid_eval.cpp — orientation grids and kernel metadata under
// every kernel (instantiates all kernels, CGAL Epeck included).
#include "kernel_dispatch.h"
#include "kernel_runs.h"

namespace relgeo::tool {

Kernel_info kernel_info(std::string_view name) {
  return with_kernel(name, [&]<class K>(const K&) {
    return Kernel_info{std::string(name), K::name(), K::is_certified, K::has_exact_predicates,
                       is_slow_kernel(name)};
  });
}

analysis::Orientation_grid_result evaluate_grid(std::string_view kernel,
                                                const analysis::Orientation_grid_triple& triple,
                                                int size) {
  return with_kernel(kernel, [&]<class K>(const K& k) {
    return analysis::evaluate_orientation_grid<K>(triple, size, k);
  });
}

}  // namespace relgeo::tool
