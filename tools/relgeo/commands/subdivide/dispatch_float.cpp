// tools/relgeo/subdivision_eval_float.cpp — run_subdivision under the kernels
// with double (float, long double) coordinates, the kernel list of
// `subdivide`, and the dyadic sample grid. The interval, exact and MPFR
// kernels are in subdivision_eval_exact.cpp.
#include "kernel_names.h"
#include "relgeo/kernel/failsafe_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/naive_kernel.h"
#include "subdivision_runs.h"

namespace relgeo::tool {

const std::vector<std::string>& subdivision_kernel_names() {
  static const std::vector<std::string> names = {"float",    "double", "long-double", "failsafe", "filtered",
                                                 "interval", "exact",  "mpfr-53",     "mpfr-113"};
  return names;
}

void validate_subdivision_kernel(const std::string& name) {
  validate_kernel_name(name);  // unknown names: the tool's usual message
  for (const auto& n : subdivision_kernel_names())
    if (n == name) return;
  std::string list;
  for (const auto& n : subdivision_kernel_names()) list += (list.empty() ? "" : ", ") + n;
  throw Usage_error("kernel '" + name + "' is not supported by subdivide (its constructions are needed; supported: " +
                    list + ")");
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
  const std::string& k = rq.kernel;
  if (k == "float") return run_subdivision_with<Naive_kernel<float>>(input, rq);
  if (k == "double") return run_subdivision_with<Naive_kernel<double>>(input, rq);
  if (k == "long-double") return run_subdivision_with<Naive_kernel<long double>>(input, rq);
  if (k == "failsafe") return run_subdivision_with<Failsafe_kernel<double>>(input, rq);
  if (k == "filtered") return run_subdivision_with<Filtered_exact_kernel>(input, rq);
  Subdivision_result r;
  if (run_subdivision_exact_kernels(input, rq, r)) return r;
  throw Usage_error("kernel '" + k + "' is listed but not dispatched by subdivide");
}

}  // namespace relgeo::tool
