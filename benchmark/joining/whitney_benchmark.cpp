// benchmark/joining/whitney_benchmark.cpp — the Whitney extension (thesis
// Sec. 4.3.1) alone: n query points (the mesh vertices to reproject) against
// sigma boundary samples, through the kd-tree and by brute force (every
// sample for every point: the n x sigma cost the thesis reports).
//
// Benchmarks are named `whitney/<index|brute-force>/<data>/<sigma>/<n>`; one
// iteration builds the extension (L over all sample pairs, the tree) and
// evaluates every point. Data: samples on a wobbly closed curve in [0,1]^2,
// heights a smooth trend plus noise of 1e-4 ("noisy") or none ("smooth");
// points on a grid inside. Counters: `cones` (cone pairs evaluated per
// point), `fallbacks` (points decided by the MPFR stage). The table after the
// runs gives the time per point and per point and sample, the ratio of brute
// force to the index, and checks the bar: 10^5 points, 10^3 samples, < 1 s.
// Times are CPU times, the minimum over repetitions.
// Defaults, unless given: --benchmark_min_time=0.1 --benchmark_repetitions=1.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "common/command_line.h"
#include "relgeo/joining/whitney_extension.h"

namespace {

using namespace relgeo;

std::vector<Whitney_sample> samples(std::size_t sigma, double noise) {
  std::mt19937_64 rng(sigma);
  std::uniform_real_distribution<double> r(-1, 1);
  std::vector<Whitney_sample> s;
  for (std::size_t i = 0; i < sigma; ++i) {
    const double t = 2 * M_PI * static_cast<double>(i) / static_cast<double>(sigma);
    const double rad = 0.4 * (1 + 0.15 * std::sin(5 * t));
    s.push_back({{0.5 + rad * std::cos(t), 0.5 + rad * std::sin(t)}, 1e-3 * std::sin(3 * t) + noise * r(rng)});
  }
  return s;
}
std::vector<Point_2<double>> grid_points(std::size_t n) {
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  std::vector<Point_2<double>> p;
  for (std::size_t i = 0; i < side && p.size() < n; ++i)
    for (std::size_t j = 0; j < side && p.size() < n; ++j)
      p.push_back({0.2 + 0.6 * (i + 0.5) / side, 0.2 + 0.6 * (j + 0.5) / side});
  return p;
}

using Key = std::tuple<std::string, std::string, long, long>;  // method, data, sigma, n
std::map<Key, double>& seconds() {
  static std::map<Key, double> s;
  return s;
}

void bench(benchmark::State& state, bool index, double noise) {
  const auto sigma = static_cast<std::size_t>(state.range(0)), n = static_cast<std::size_t>(state.range(1));
  const auto s = samples(sigma, noise);
  const auto p = grid_points(n);
  std::size_t cones = 0, fallbacks = 0;
  for (auto _ : state) {
    const Whitney_extension w(s, {.use_index = index});
    const auto v = w.evaluate_all(p);
    benchmark::DoNotOptimize(v.data());
    cones = fallbacks = 0;
    for (const auto& x : v) cones += x.cones, fallbacks += x.fallback;
  }
  state.counters["cones"] = static_cast<double>(cones) / static_cast<double>(n);
  state.counters["fallbacks"] = static_cast<double>(fallbacks);
}

class Whitney_reporter : public relgeo_bench::Collecting_reporter {
  void collect(const Run& r) override {
    const std::string name = r.run_name.function_name;  // whitney/<method>/<data>
    const std::string rest = name.substr(name.find('/') + 1);
    const std::string method = rest.substr(0, rest.find('/')), data = rest.substr(rest.find('/') + 1);
    const std::string args = r.run_name.args;  // sigma/n
    const long sigma = std::stol(args.substr(0, args.find('/'))), n = std::stol(args.substr(args.find('/') + 1));
    // The minimum over repetitions (the machine is shared).
    const double t = relgeo_bench::to_seconds(r.GetAdjustedCPUTime(), r.time_unit);
    const auto [it, inserted] = seconds().emplace(Key{method, data, sigma, n}, t);
    if (!inserted) it->second = std::min(it->second, t);
  }
};

void print_table() {
  if (seconds().empty()) return;
  std::printf("\nWhitney extension: one build + n evaluations (CPU time of the benchmark thread)\n");
  std::printf("%-12s %-7s %7s %8s %11s %12s %14s %9s\n", "method", "data", "sigma", "n", "time", "per point",
              "per n*sigma", "brute/idx");
  for (const auto& [key, t] : seconds()) {
    const auto& [method, data, sigma, n] = key;
    char ratio[16] = "";
    const auto b = seconds().find({"brute-force", data, sigma, n});
    if (method == "index" && b != seconds().end()) std::snprintf(ratio, sizeof ratio, "%.1f", b->second / t);
    std::printf("%-12s %-7s %7ld %8ld %9.4g s %9.3g us %11.3g ns %9s\n", method.c_str(), data.c_str(), sigma, n, t,
                t / static_cast<double>(n) * 1e6, t / (static_cast<double>(n) * static_cast<double>(sigma)) * 1e9, ratio);
  }
  for (const char* data : {"noisy", "smooth"}) {
    const auto it = seconds().find({"index", data, 1000, 100000});
    if (it != seconds().end())
      std::printf("bar (%s): 10^5 points x 10^3 samples in %.3f s: %s\n", data, it->second,
                  it->second < 1.0 ? "met (< 1 s)" : "NOT met");
  }
}

void add(const char* method, const char* data, std::vector<std::pair<long, long>> sizes) {
  const bool index = std::string(method) == "index";
  const double noise = std::string(data) == "noisy" ? 1e-4 : 0.0;
  auto* b = benchmark::RegisterBenchmark((std::string("whitney/") + method + "/" + data).c_str(),
                                         [index, noise](benchmark::State& s) { bench(s, index, noise); });
  for (const auto& [sigma, n] : sizes) b->Args({sigma, n});
  b->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  relgeo_bench::Command_line args(argc, argv);
  args.set_measuring_defaults("0.1", "1");
  if (!args.initialize()) return 1;
  std::vector<std::pair<long, long>> grid;
  for (long sigma : {80, 1000, 10000})
    for (long n : {2100, 10000, 100000, 1000000}) grid.push_back({sigma, n});
  std::vector<std::pair<long, long>> small;  // brute force up to n sigma = 10^8
  for (const auto& [sigma, n] : grid)
    if (static_cast<double>(sigma) * static_cast<double>(n) <= 1e8) small.push_back({sigma, n});
  for (const char* data : {"noisy", "smooth"}) {
    add("index", data, grid);
    add("brute-force", data, small);
  }
  Whitney_reporter reporter;
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks(&reporter);
  print_table();
  return relgeo_bench::finish(ran, "relgeo_whitney_benchmark");
}
