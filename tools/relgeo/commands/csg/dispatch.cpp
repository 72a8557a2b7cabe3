// tools/relgeo/commands/csg/dispatch.cpp — relgeo::csg under the kernels
// relgeo::compiled instantiates the Boolean for (the only TU of `csg` that
// names kernel types).
#include "commands/csg/command.h"
#include "cli/text.h"
#include "relgeo/boolean.h"
#include "relgeo/kernel.h"

namespace relgeo::tool {

const std::vector<std::string>& csg_kernel_names() {
  static const std::vector<std::string> names{"filtered", "exact", "double"};
  return names;
}

Csg_result evaluate_csg(const std::string& kernel, const Csg_node& tree, const Csg_options& options) {
  if (kernel == "filtered") return csg(tree, Filtered_exact_kernel{}, options);
  if (kernel == "exact") return csg(tree, Exact_kernel{}, options);
  if (kernel == "double") return csg(tree, Naive_kernel<double>{}, options);
  std::string list;
  for (const std::string& n : csg_kernel_names()) list += (list.empty() ? "" : ", ") + n;
  throw Usage_error("csg: kernel '" + kernel + "' is not one of " + list);
}

}  // namespace relgeo::tool
