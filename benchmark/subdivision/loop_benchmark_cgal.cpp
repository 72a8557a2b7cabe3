// CGAL::Subdivision_method_3::Loop_subdivision on Surface_mesh<Epick::Point_3>
// (the usual CGAL set-up; Epick's constructions are plain double).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include "loop_benchmark.h"

namespace relgeo_bench {

void register_cgal(const std::vector<Bench_mesh>& meshes) {
  using SM = CGAL::Surface_mesh<CGAL::Epick::Point_3>;
  const auto build = [](const Mesh_d& m) {
    SM sm;
    for (const auto& p : m.vertices) sm.add_vertex(CGAL::Epick::Point_3(p.x, p.y, p.z));
    for (const auto& f : m.faces) sm.add_face(SM::Vertex_index(f[0]), SM::Vertex_index(f[1]), SM::Vertex_index(f[2]));
    return sm;
  };
  register_peer(meshes, "CGAL", build, [](SM& sm, int level) {
    CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(level));
    benchmark::DoNotOptimize(sm.points().begin());
    return std::size_t(sm.number_of_faces());
  });
}

}  // namespace relgeo_bench
