// CGAL::Subdivision_method_3::Loop_subdivision on Surface_mesh<Epick::Point_3>
// (the usual CGAL set-up; Epick's constructions are plain double).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include "loop_benchmark.h"

namespace relgeo_bench {

void register_cgal(const std::vector<Bench_mesh>& meshes) {
  using SM = CGAL::Surface_mesh<CGAL::Epick::Point_3>;
  for (const Bench_mesh& bm : meshes) {
    auto sm = std::make_shared<SM>();
    for (const auto& p : bm.mesh.vertices) sm->add_vertex(CGAL::Epick::Point_3(p.x, p.y, p.z));
    for (const auto& f : bm.mesh.faces)
      sm->add_face(SM::Vertex_index(f[0]), SM::Vertex_index(f[1]), SM::Vertex_index(f[2]));
    for (int level : bm.levels)
      benchmark::RegisterBenchmark(("loop/" + bm.name + "/L" + std::to_string(level) + "/CGAL").c_str(),
                                   [sm, level](benchmark::State& state) {
                                     std::size_t faces = 0;
                                     for (auto _ : state) {
                                       state.PauseTiming();
                                       auto copy = std::make_unique<SM>(*sm);
                                       state.ResumeTiming();
                                       CGAL::Subdivision_method_3::Loop_subdivision(
                                           *copy, CGAL::parameters::number_of_iterations(level));
                                       faces = copy->number_of_faces();
                                       benchmark::DoNotOptimize(copy->points().begin());
                                       state.PauseTiming();
                                       copy.reset();
                                       state.ResumeTiming();
                                     }
                                     state.counters["faces_out"] = double(faces);
                                   })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
  }
}

}  // namespace relgeo_bench
