// tools/relgeo/commands/subdivide/dispatch_float.cpp — run_subdivision under
// the kernels with float, double or long double coordinates, the kernel list
// of `subdivide`, its levels and crease rules, and the dyadic sample grid.
// The interval, exact and MPFR kernels are in dispatch_exact.cpp.
#include "cli/text.h"
#include "commands/subdivide/run_with.h"

namespace relgeo::tool {

const std::vector<std::string>& subdivision_kernel_names() {
  static const std::vector<std::string> names =
      admitted_kernel_names<Subdivision_float_kernels, Subdivision_exact_kernels>();
  return names;
}

void validate_subdivision_kernel(const std::string& name) {
  const Kernel_entry& k = find_kernel(name);  // unknown names: the tool's usual message
  for (const auto& n : subdivision_kernel_names())
    if (n == k.label()) return;
  throw Usage_error("kernel '" + name + "' is not supported by subdivide (its constructions are needed; supported: " +
                    comma_list(subdivision_kernel_names()) + ")");
}

unsigned subdivision_levels(int levels) {
  if (levels < 0 || levels > 12) throw Usage_error("--levels must be in 0..12");
  return static_cast<unsigned>(levels);
}

Loop_crease_rules parse_crease_rules(const std::string& name) {
  if (name == "hoppe") return Loop_crease_rules::hoppe;
  if (name == "blz") return Loop_crease_rules::biermann_levin_zorin;
  throw Usage_error("--rules must be hoppe or blz");
}

std::vector<std::pair<double, double>> dyadic_samples(int n) {
  if (n <= 0 || (n & (n - 1)) != 0) throw Usage_error("--samples must be a power of two (or 0)");
  std::vector<std::pair<double, double>> g;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i + j <= n; ++i) g.push_back({double(i) / n, double(j) / n});
  return g;
}

Subdivision_result run_subdivision(const Mesh_double& input, const Subdivision_request& rq) {
  validate_subdivision_kernel(rq.kernel);
  const Kernel_entry& k = find_kernel(rq.kernel);
  Subdivision_result r;
  if (run_subdivision_exact_kernels(input, rq, r)) return r;
  return with_kernel<Subdivision_float_kernels>(k, [&]<class K>(const K&) { return run_subdivision_with<K>(input, rq); });
}

}  // namespace relgeo::tool

namespace relgeo::tool {

std::vector<Point_3<double>> evaluate_limit_surface(const std::string& kernel, const Mesh_double& control,
                                                    const std::vector<std::int64_t>& faces,
                                                    const std::vector<double>& u, const std::vector<double>& v,
                                                    const Loop_options& options) {
  validate_subdivision_kernel(kernel);
  if (u.size() != faces.size() || v.size() != faces.size())
    throw Precondition_violation("evaluate_limit_surface: as many u and v as faces are needed");
  std::vector<Point_3<double>> points;
  if (evaluate_limit_surface_exact_kernels(kernel, control, faces, u, v, options, points)) return points;
  return with_kernel<Subdivision_float_kernels>(find_kernel(kernel), [&]<class K>(const K&) {
    return evaluate_limit_surface_with<K>(control, faces, u, v, options);
  });
}

}  // namespace relgeo::tool
