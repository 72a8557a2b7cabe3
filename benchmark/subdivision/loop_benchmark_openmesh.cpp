// OpenMesh's Subdivider::Uniform::LoopT on a TriMesh with double points.
#include "loop_benchmark.h"

#ifdef RELGEO_HAS_OPENMESH
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <memory>

namespace relgeo_bench {

namespace {
struct Traits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using Om = OpenMesh::TriMesh_ArrayKernelT<Traits>;
}  // namespace

bool have_openmesh() { return true; }

void register_openmesh(const std::vector<Bench_mesh>& meshes) {
  for (const Bench_mesh& bm : meshes) {
    auto om = std::make_shared<Om>();
    for (const auto& p : bm.mesh.vertices) om->add_vertex(Om::Point(p.x, p.y, p.z));
    for (const auto& f : bm.mesh.faces)
      om->add_face(om->vertex_handle(f[0]), om->vertex_handle(f[1]), om->vertex_handle(f[2]));
    for (int level : bm.levels)
      benchmark::RegisterBenchmark(("loop/" + bm.name + "/L" + std::to_string(level) + "/OpenMesh").c_str(),
                                   [om, level](benchmark::State& state) {
                                     std::size_t faces = 0;
                                     OpenMesh::Subdivider::Uniform::LoopT<Om, double> loop;
                                     for (auto _ : state) {
                                       state.PauseTiming();
                                       auto copy = std::make_unique<Om>(*om);
                                       state.ResumeTiming();
                                       loop.attach(*copy);
                                       loop(static_cast<std::size_t>(level));
                                       loop.detach();
                                       faces = copy->n_faces();
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
#else
namespace relgeo_bench {
bool have_openmesh() { return false; }
void register_openmesh(const std::vector<Bench_mesh>&) {}
}  // namespace relgeo_bench
#endif
