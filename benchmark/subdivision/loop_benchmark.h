// benchmark/subdivision/loop_benchmark.h — shared declarations of the Loop
// subdivision benchmark (relgeo_subdivision_benchmark).
#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo_bench {

using Mesh_d = relgeo::Triangle_mesh<relgeo::Point_3<double>>;

/// An input mesh and the refinement levels it is benchmarked at.
struct Bench_mesh {
  std::string name;
  Mesh_d mesh;
  std::vector<int> levels;
};

/// The benchmarks `loop/<mesh>/L<level>/<peer>` of one peer: for each mesh, `build(mesh)` makes the peer's
/// mesh once; each iteration copies it (untimed), runs `subdivide(copy,
/// level)`, which returns the faces out, and frees the copy (untimed).
template <class Build, class Subdivide>
void register_peer(const std::vector<Bench_mesh>& meshes, const std::string& peer, Build build, Subdivide subdivide) {
  for (const Bench_mesh& bm : meshes) {
    using Peer_mesh = decltype(build(bm.mesh));
    auto original = std::make_shared<const Peer_mesh>(build(bm.mesh));
    for (int level : bm.levels)
      benchmark::RegisterBenchmark(("loop/" + bm.name + "/L" + std::to_string(level) + "/" + peer).c_str(),
                                   [original, level, subdivide](benchmark::State& state) {
                                     std::size_t faces = 0;
                                     for (auto _ : state) {
                                       state.PauseTiming();
                                       auto copy = std::make_unique<Peer_mesh>(*original);
                                       state.ResumeTiming();
                                       faces = subdivide(*copy, level);
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

/// Registers the benchmarks of the peers of one translation unit (CGAL in
/// loop_benchmark_cgal.cpp, OpenMesh in loop_benchmark_openmesh.cpp), through
/// register_peer. Each sets the counter faces_out.
void register_cgal(const std::vector<Bench_mesh>& meshes);
void register_openmesh(const std::vector<Bench_mesh>& meshes);  // no-op without OpenMesh
bool have_openmesh();

}  // namespace relgeo_bench
