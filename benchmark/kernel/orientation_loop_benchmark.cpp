// benchmark/kernel/orientation_loop_benchmark.cpp — orientation_3 as a
// caller writes it: a plain loop that builds four points from doubles and
// calls the kernel's functor, relgeo::Filtered_exact_kernel against
// CGAL::Epick's own functor, on uniform random points in [-1, 1]^3 (the
// filter decides every call). Built twice: at the project's optimisation
// level (relgeo_orientation_loop_benchmark) and at -O1
// (relgeo_orientation_loop_benchmark_O1), where the filter's fast path
// used to stay out of line (doc/kernels.md, "A plain loop over the
// functor"). Time per call: the benchmark's time over kCalls.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "relgeo/kernel/filtered_exact_kernel.h"

namespace {

constexpr int kCalls = 1 << 15;

const std::vector<double>& coordinates() {
  static const std::vector<double> c = [] {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> v(12 * std::size_t{kCalls});
    for (double& x : v) x = u(rng);
    return v;
  }();
  return c;
}

void relgeo_filtered(benchmark::State& state) {
  const std::vector<double>& c = coordinates();
  const relgeo::Filtered_exact_kernel k;
  const auto point = k.construct_point_3_object();
  for (auto _ : state) {
    int sum = 0;
    for (int i = 0; i < kCalls; ++i) {
      const double* d = &c[12 * std::size_t(i)];
      sum += static_cast<int>(k.orientation_3_object()(point(d[0], d[1], d[2]), point(d[3], d[4], d[5]),
                                                       point(d[6], d[7], d[8]), point(d[9], d[10], d[11])));
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kCalls);
}

void cgal_epick(benchmark::State& state) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::vector<double>& c = coordinates();
  for (auto _ : state) {
    int sum = 0;
    for (int i = 0; i < kCalls; ++i) {
      const double* d = &c[12 * std::size_t(i)];
      sum += static_cast<int>(K().orientation_3_object()(K::Point_3(d[0], d[1], d[2]), K::Point_3(d[3], d[4], d[5]),
                                                         K::Point_3(d[6], d[7], d[8]), K::Point_3(d[9], d[10], d[11])));
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kCalls);
}

}  // namespace

BENCHMARK(relgeo_filtered)->Name("orientation_3/plain_loop/filtered")->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(cgal_epick)->Name("orientation_3/plain_loop/CGAL::Epick")->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK_MAIN();
