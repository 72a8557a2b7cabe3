// tools/relgeo/commands/subdivide/dispatch_exact.cpp — run_subdivision
// under the interval, exact (GMP rational) and MPFR kernels, and the exact
// reference samples of the limit surface used by the experiment.
#include "commands/subdivide/run_with.h"

namespace relgeo::tool {

bool run_subdivision_exact_kernels(const Mesh_double& input, const Subdivision_request& rq, Subdivision_result& r) {
  const Kernel_entry& k = find_kernel(rq.kernel);
  if (!admits_kernel<Subdivision_exact_kernels>(k)) return false;
  r = with_kernel<Subdivision_exact_kernels>(k, [&]<class K>(const K&) { return run_subdivision_with<K>(input, rq); });
  return true;
}

bool evaluate_limit_surface_exact_kernels(const std::string& kernel, const Mesh_double& control,
                                          const std::vector<std::int64_t>& faces, const std::vector<double>& u,
                                          const std::vector<double>& v, const Loop_options& options,
                                          std::vector<Point_3<double>>& points) {
  const Kernel_entry& k = find_kernel(kernel);
  if (!admits_kernel<Subdivision_exact_kernels>(k)) return false;
  points = with_kernel<Subdivision_exact_kernels>(
      k, [&]<class K>(const K&) { return evaluate_limit_surface_with<K>(control, faces, u, v, options); });
  return true;
}

void exact_reference(const Mesh_double& input, unsigned levels, const Loop_options& options, int samples,
                     std::vector<Point_3<double>>& surface, std::vector<Point_3<double>>& limit_vertices) {
  using namespace subdivision_detail;
  using P = Exact_kernel::Point_3;
  Triangle_mesh<P> m;
  for (const auto& p : input.vertices) m.vertices.push_back(P{p.x, p.y, p.z});
  m.faces = input.faces;
  m.tags = input.tags;
  Loop_subdivider<Exact_kernel> sub(options);
  const Triangle_mesh<P> R = sub.refine(m, levels);
  const Triangle_mesh<P> L = sub.limit_mesh(m, levels);
  limit_vertices.clear();
  for (const P& p : L.vertices) limit_vertices.push_back(to_double(p));
  const Loop_limit_surface<Exact_kernel> S(R, options);
  const auto grid = dyadic_samples(samples);
  surface.clear();
  surface.reserve(R.faces.size() * grid.size());
  for (Index f = 0; f < R.faces.size(); ++f)
    for (const auto& [u, v] : grid) surface.push_back(to_double(S.evaluate(f, u, v)));
}

}  // namespace relgeo::tool
