// benchmark/hull/hull_benchmark.h — shared machinery of the planar convex-hull
// suite (relgeo_hull_benchmark).
//
// A *subject* is one hull algorithm under one kernel: a relgeo algorithm
// (graham_fortune, monotone_chain, graham_incremental) under a relgeo kernel,
// or a CGAL function (ch_graham_andrew, convex_hull_2) on a CGAL kernel used
// directly. For every input family and size the suite converts the input to
// the subject's point type once (not timed) and times one hull computation per
// iteration. Counters: `hull` (output size), `backward_error` (relgeo::
// hull_backward_error of the output, computed once outside the timed loop;
// identical outputs share one computation), `ns/point`.
//
// Benchmark names are `hull/<family>/<N>/<algorithm>/<kernel>`, e.g.
// `hull/uniform/1000000/graham_fortune/failsafe<double>`; the ratio table of
// hull_benchmark.cpp parses them.
#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "relgeo/kernel/point.h"

namespace relgeo_hull_bench {

/// An input and a key naming it ("uniform/1000000/1"): prepared points are
/// cached under the key (an address can be reused by the next input).
struct Input {
  std::string key;
  std::vector<relgeo::Point_2<double>> points;
};

/// The input families (deterministic, + - * / only):
///   uniform  uniform in [-1, 1]^2 (hull size ~ log N);
///   circle   on the unit circle at the origin, rational parametrisation,
///            rounded (almost every point is a hull vertex);
///   line     on the segment (0.5, 0.5)-(24.25, 17.3), each coordinate then
///            moved by up to 4 ulps (near-degenerate; tiny exact hull).
Input make_input(const std::string& family, std::size_t n, std::uint64_t seed);

/// One subject. `runs(family, n)` says whether it is benchmarked there;
/// `bench(state, input)` is the benchmark body (prepares points, not timed, on
/// first call for a given input); `hull_indices(input)` is the output as
/// indices into the input, computed outside any timing (for the backward
/// error); `memory_probe(n)` builds the subject's own uniform input of n
/// points in place and returns a function computing its hull once (for the
/// peak-memory measurement; input built before the measurement starts).
struct Subject {
  std::string algorithm, kernel;
  std::function<bool(const std::string&, std::size_t)> runs;
  std::function<void(benchmark::State&, const Input&)> bench;
  std::function<std::vector<std::size_t>(const Input&)> hull_indices;
  std::function<std::function<std::size_t()>(std::size_t n, std::size_t* input_bytes)> memory_probe;
  std::function<void()> release;  ///< frees prepared points
};

std::vector<Subject> relgeo_subjects();  // hull_benchmark.cpp
std::vector<Subject> cgal_subjects();    // hull_benchmark_cgal.cpp (Epick, Epeck)

/// Size limits of the suite (the brief of the benchmark):
inline constexpr std::size_t kExactMaxN = 1000000;       ///< Exact_kernel (relgeo)
inline constexpr std::size_t kEpeckMaxN = 1000000;       ///< CGAL Epeck
inline constexpr std::size_t kIncrementalMaxN = 100000;  ///< graham_incremental (uniform only)

/// Times `compute(points)` once per iteration over prebuilt points and sets
/// the counters: hull (size_of(result)), time/point (seconds, shown with an SI
/// prefix: "25n" = 25 ns per input point).
template <class Points, class Compute, class SizeOf>
void time_hull(benchmark::State& state, const Points& points, Compute compute, SizeOf size_of) {
  std::size_t h = 0;
  for (auto _ : state) {
    auto r = compute(points);
    h = size_of(r);
    benchmark::DoNotOptimize(r);
    benchmark::ClobberMemory();
  }
  state.counters["hull"] = benchmark::Counter(static_cast<double>(h));
  state.counters["time/point"] = benchmark::Counter(
      static_cast<double>(points.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

/// Keeps the points of the running benchmark between the library's calls of
/// its body (converting 10^7 points to Epeck takes seconds): one slot, keyed
/// by the input's key.
template <class Points>
class Prepared_slot {
 public:
  template <class Build>
  const Points& get(const Input& in, Build build) {
    if (!points_ || key_ != in.key) {
      points_.reset();  // free first: 10^7 points of one subject at a time
      points_ = std::make_unique<Points>(build(in.points));
      key_ = in.key;
    }
    return *points_;
  }
  void release() { points_.reset(), key_.clear(); }

 private:
  std::unique_ptr<Points> points_;
  std::string key_;
};

}  // namespace relgeo_hull_bench
