// benchmark/subdivision/loop_benchmark.h — shared declarations of the Loop
// subdivision benchmark (relgeo_subdivision_benchmark).
#pragma once

#include <benchmark/benchmark.h>

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

/// Registers `loop/<mesh>/L<level>/<subject>` benchmarks for the peers of one
/// translation unit (CGAL in loop_benchmark_cgal.cpp, OpenMesh in
/// loop_benchmark_openmesh.cpp). Each sets the counter faces_out.
void register_cgal(const std::vector<Bench_mesh>& meshes);
void register_openmesh(const std::vector<Bench_mesh>& meshes);  // no-op without OpenMesh
bool have_openmesh();

}  // namespace relgeo_bench
