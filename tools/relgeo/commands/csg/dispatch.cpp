// tools/relgeo/commands/csg/dispatch.cpp — relgeo::csg under the kernels
// relgeo::compiled instantiates the Boolean for (the only TU of `csg` that
// names kernel types).
#include <algorithm>

#include "cli/text.h"
#include "commands/csg/facade.h"
#include "relgeo/boolean.h"
#include "relgeo/kernel.h"

namespace relgeo::tool {

const std::vector<std::string>& csg_kernel_names() {
  static const std::vector<std::string> names{"filtered", "exact", "double"};
  return names;
}

void validate_csg_kernel(const std::string& name) {
  const auto& names = csg_kernel_names();
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  throw Usage_error("csg: kernel '" + name + "' is not one of " + comma_list(names));
}

Csg_result evaluate_csg(const std::string& kernel, const Csg_node& tree, const Csg_options& options) {
  validate_csg_kernel(kernel);
  if (kernel == "exact") return csg(tree, Exact_kernel{}, options);
  if (kernel == "double") return csg(tree, Naive_kernel<double>{}, options);
  return csg(tree, Filtered_exact_kernel{}, options);
}

}  // namespace relgeo::tool
