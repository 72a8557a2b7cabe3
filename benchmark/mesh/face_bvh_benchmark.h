// benchmark/mesh/face_bvh_benchmark.h — the cases and registration shared by
// the mesh benchmark's translation units (relgeo in face_bvh_benchmark.cpp,
// CGAL in face_bvh_benchmark_cgal.cpp, so neither pays for the other's
// headers).
#pragma once

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo_bench {

using Mesh = relgeo::Triangle_mesh<relgeo::Point_3<double>>;

/// A pair of meshes whose overlapping face boxes are searched.
struct Mesh_pair_case {
  std::string name;
  Mesh a, b;
};

/// The case names: "spheres-20k" (two 20172-face spheres, the second moved
/// by (0.5, 0.37, 0.23)), "elephant" (CGAL's elephant.off against a copy
/// rotated by 0.5 rad about (1, 2, 3) through its box centre), "spheres-1m"
/// (two 1002252-face spheres, moved as the first pair). Empty when the
/// CGAL data set is missing (elephant).
std::vector<std::string> case_names();
const Mesh_pair_case& mesh_pair_case(const std::string& name);
/// Mesh A of a case as an OFF file of the system's temporary folder
/// (written by relgeo::write_mesh on first use): the read_off subjects' input.
std::string off_file(const std::string& case_name);

/// Registers name with the repetitions every subject of this suite uses
/// (fewer on the 10^6-face case).
benchmark::internal::Benchmark* register_subject(const std::string& name,
                                                 void (*f)(benchmark::State&, const std::string&),
                                                 const std::string& case_name);

/// The CGAL subjects of one kind ("pairs", "self_pairs",
/// "self_intersections", "volume", "read_off", "write_off") and case, on one or two threads (two only with TBB)
/// (face_bvh_benchmark_cgal.cpp).
void register_cgal_subjects(const std::string& kind, const std::string& case_name, int threads);

}  // namespace relgeo_bench
