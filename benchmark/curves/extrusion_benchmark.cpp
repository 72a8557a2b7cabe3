// benchmark/curves/extrusion_benchmark.cpp — relgeo::check_extrusion on
// circle chains of M cubic arcs (M = 10^2 .. 10^5), relative uncertainty 1e-9
// (the arcs are ~2 pi / M long: 1e-3 would not be covered for large M).
//
// Benchmarks are named `extrusion/<kernel>/<algorithm>[/no-prune]/<M>`. One
// iteration checks the whole contour: 4M hull problems plus condition 3.
// Subjects: Failsafe_kernel<double> + graham_fortune (the thesis' choice),
// Filtered_exact_kernel + monotone_chain, Naive_kernel<double> +
// graham_fortune, Exact_kernel + monotone_chain (M <= 10^4), CGAL's Epick
// through relgeo's adapter + CGAL::convex_hull_2 (the peer), and failsafe
// without the spatial prune for M <= 10^3 (condition 3 on all M(M-3)/2
// pairs: the quadratic cost the prune avoids).
// Counters: `certified` (1 when the verdict is certified), `pairs` (pairs of
// condition 3 computed exactly). After the runs a table lists the
// time per curve and the ratio to failsafe/graham-fortune at the same M.
// Defaults, unless given: --benchmark_min_time=0.2 --benchmark_repetitions=1.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "common/command_line.h"
#include "relgeo/curves.h"
#include "relgeo/hull/cgal_convex_hull.h"
#include "relgeo/kernel.h"
#include "relgeo/kernel/cgal_kernel.h"
#include "relgeo_fixtures/curves/test_contours.h"

namespace {

using namespace relgeo;

const Bezier_contour& contour(std::size_t M) {
  static std::map<std::size_t, Bezier_contour> cache;
  auto it = cache.find(M);
  if (it == cache.end()) it = cache.emplace(M, circle_contour(M)).first;
  return it->second;
}

struct Cgal_hull {
  template <class K>
  Hull_result<typename K::Point_2> operator()(std::span<const typename K::Point_2> p, const K& k) const {
    return cgal_convex_hull<typename K::Cgal>(p, Cgal_hull_algorithm::convex_hull_2, k);
  }
};

std::map<std::string, std::map<std::size_t, double>>& seconds() {  // subject -> M -> s per check
  static std::map<std::string, std::map<std::size_t, double>> s;
  return s;
}

template <class K, class A>
void bench(benchmark::State& state, bool prune) {
  const auto M = static_cast<std::size_t>(state.range(0));
  const Bezier_contour& c = contour(M);
  Extrusion_options o;
  o.relative_uncertainty = 1e-9;
  o.prune = prune;
  Extrusion_report r;
  for (auto _ : state) {
    r = check_extrusion<K>(c, o, K{}, A{});
    benchmark::DoNotOptimize(r.verdict);
  }
  state.counters["certified"] = r.verdict == Extrusion_verdict::certified ? 1 : 0;
  state.counters["pairs"] = static_cast<double>(r.pairs_computed);
}

class Extrusion_reporter : public relgeo_bench::Collecting_reporter {
  void collect(const Run& r) override {
    const std::string name = r.run_name.function_name;  // extrusion/<kernel>/<algorithm>[/no-prune]
    const double t = relgeo_bench::to_seconds(r.GetAdjustedRealTime(), r.time_unit);
    seconds()[name.substr(name.find('/') + 1)][std::stoul(r.run_name.args)] = t;
  }
};

void print_table() {
  if (seconds().empty()) return;
  const std::string base = "failsafe<double>/graham-fortune";
  std::printf("\nper curve: real time of one check / M, and the ratio to %s at the same M\n", base.c_str());
  std::printf("%-40s %8s %12s %12s %10s\n", "subject", "M", "time", "per curve", "ratio");
  for (const auto& [subject, by_m] : seconds())
    for (const auto& [M, t] : by_m) {
      char ratio[16] = "n/a";
      const auto b = seconds().find(base);
      if (b != seconds().end() && b->second.count(M)) std::snprintf(ratio, sizeof ratio, "%.2f", t / b->second.at(M));
      std::printf("%-40s %8zu %10.4g s %9.3g us %10s\n", subject.c_str(), M, t, t / static_cast<double>(M) * 1e6, ratio);
    }
}


template <class K, class A>
void add(const std::string& name, std::vector<long> sizes, bool prune = true) {
  auto* b = benchmark::RegisterBenchmark(("extrusion/" + name + (prune ? "" : "/no-prune")).c_str(),
                                         [prune](benchmark::State& s) { bench<K, A>(s, prune); });
  for (long m : sizes) b->Arg(m);
  b->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
  relgeo_bench::Command_line args(argc, argv);
  args.set_measuring_defaults("0.2", "1");
  if (!args.initialize()) return 1;
  const std::vector<long> all = {100, 1000, 10000, 100000};
  add<Failsafe_kernel<double>, Graham_fortune_hull>("failsafe<double>/graham-fortune", all);
  add<Filtered_exact_kernel, Monotone_chain_hull>("filtered/monotone-chain", all);
  add<Naive_kernel<double>, Graham_fortune_hull>("double/graham-fortune", all);
  add<Exact_kernel, Monotone_chain_hull>("exact/monotone-chain", {100, 1000, 10000});
  add<Cgal_kernel<CGAL::Epick>, Cgal_hull>("cgal-epick/cgal", all);
  add<Failsafe_kernel<double>, Graham_fortune_hull>("failsafe<double>/graham-fortune", {100, 1000}, false);
  Extrusion_reporter reporter;
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks(&reporter);
  print_table();
  return relgeo_bench::finish(ran, "relgeo_extrusion_benchmark");
}
