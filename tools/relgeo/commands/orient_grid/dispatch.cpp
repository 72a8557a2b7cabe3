// tools/relgeo/commands/orient_grid/dispatch.cpp — orientation grids under
// every kernel (CGAL Epeck included).
#include "commands/orient_grid/facade.h"
#include "kernels/cgal_kernels.h"
#include "kernels/dispatch.h"

namespace relgeo::tool {

analysis::Orientation_grid_result evaluate_grid(std::string_view kernel,
                                                const analysis::Orientation_grid_triple& triple, int size) {
  return with_kernel(kernel, [&]<class K>(const K& k) { return analysis::evaluate_orientation_grid<K>(triple, size, k); });
}

}  // namespace relgeo::tool
