// benchmark/intersection/intersection_benchmark.h — the inputs and the
// registration shared by the intersection benchmark's translation units
// (relgeo's kernels in intersection_benchmark.cpp, CGAL's in
// intersection_benchmark_cgal.cpp, so that neither pays for the other's
// headers).
#pragma once

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "relgeo/analysis/triangle_pair_workloads.h"

namespace relgeo_bench {

/// One LPI query: the line (p, q), the plane (r, s, t) and the plane (a, b, c)
/// the point is tested against.
struct Lpi_query {
  std::array<std::array<double, 3>, 8> v;  // p q r s t a b c
};

/// "random": every point uniform in [-1, 1]^3. "on-plane": a, b, c span the
/// plane (r, s, t), so the LPI point lies on it exactly (the exact stages
/// decide every query).
const std::vector<Lpi_query>& lpi_queries(const std::string& family);
const std::vector<relgeo::analysis::Triangle_pair>& triangle_pairs(const std::string& family);

/// Registers name with the repetitions every subject of this suite uses.
benchmark::internal::Benchmark* register_subject(const std::string& name, void (*f)(benchmark::State&, const std::string&),
                                                 const std::string& family);

/// The CGAL subjects (intersection_benchmark_cgal.cpp).
void register_cgal_subjects();

}  // namespace relgeo_bench
