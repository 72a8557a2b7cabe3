// benchmark/linear/linear_benchmark.cpp — solving A x = b in double: relgeo's
// Gaussian elimination without, with partial and with complete pivoting
// against Eigen's PartialPivLU and FullPivLU, n = 10 .. 1000.
//
// Benchmarks are named `solve/<method>/<n>` (method as `relgeo linsolve
// --method` names it). One iteration factors and solves one system, the copy
// of the matrix included for every method (relgeo's lu_decompose takes it by
// value, Eigen's decompositions copy it). Inputs: entries uniform in
// [-1, 1], a fixed seed per n.
// Counters (measured once per benchmark, outside the timed loop, with exact
// arithmetic): `eta` normwise (Rigal-Gaches) and `omega` componentwise
// (Oettli-Prager) backward error of the solution, `eta/nu` = eta / (n u).
// After the runs a "ratios" table divides each method's time by that of
// Eigen's PartialPivLU and lists the backward errors. It is a report: exit
// status 0 whatever the numbers.
//
// Defaults, unless given: --benchmark_min_time=0.2 --benchmark_repetitions=1.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "common/command_line.h"
#include "relgeo/linear.h"

namespace {

using namespace relgeo;

struct Problem {
  Dense_matrix<double> a;
  Dense_vector<double> b;
  std::unique_ptr<Linear_reference> ref;  // built on first use (exact data; costly for n = 1000)
};

Problem& problem(int n) {
  static std::map<int, Problem> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  Problem p{Dense_matrix<double>(n, n), Dense_vector<double>(n), nullptr};
  std::mt19937_64 rng(static_cast<unsigned>(n) * 7919u);
  std::uniform_real_distribution<double> d(-1, 1);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) p.a(i, j) = d(rng);
  for (int i = 0; i < n; ++i) p.b(i) = d(rng);
  return cache.emplace(n, std::move(p)).first->second;
}

const Linear_reference& reference(Problem& p) {
  if (!p.ref)  // exact data; the condition number estimated, no exact solution (n up to 1000)
    p.ref = std::make_unique<Linear_reference>(p.a, p.b, Linear_reference_options{.exact_solution_limit = 0, .exact_condition_limit = 0});
  return *p.ref;
}

struct Row {
  double ns = 0, eta = 0, omega = 0, growth = 0;
};
std::map<std::pair<int, std::string>, Row>& results() {
  static std::map<std::pair<int, std::string>, Row> r;
  return r;
}

void bench_solve(benchmark::State& state, Linear_solver method) {
  const int n = static_cast<int>(state.range(0));
  Problem& p = problem(n);
  Dense_vector<double> x;
  for (auto _ : state) {
    x = solve_linear_system<double>(p.a, p.b, method);
    benchmark::DoNotOptimize(x.data());
    benchmark::ClobberMemory();
  }
  const auto e = measure_solution(reference(p), x);
  const double nu = n * 0x1p-53;
  state.counters["eta"] = e.normwise_backward_error;
  state.counters["omega"] = e.componentwise_backward_error;
  state.counters["eta/nu"] = e.normwise_backward_error / nu;
  Row& row = results()[{n, std::string(to_string(method))}];
  row.eta = e.normwise_backward_error;
  row.omega = e.componentwise_backward_error;
  if (method == Linear_solver::ge_no_pivoting || method == Linear_solver::ge_partial_pivoting ||
      method == Linear_solver::ge_complete_pivoting)
    row.growth = lu_decompose<double>(p.a, method == Linear_solver::ge_no_pivoting ? Pivoting::none
                                                : method == Linear_solver::ge_partial_pivoting ? Pivoting::partial
                                                                                               : Pivoting::complete)
                     .growth_factor;
}

/// Console output plus the per-run real time, for the ratio table.
class Linear_reporter : public relgeo_bench::Collecting_reporter {
  void collect(const Run& r) override {
    const std::string name = r.run_name.function_name + "/" + r.run_name.args;  // solve/<method>/<n>
    const auto a = name.find('/'), b = name.find('/', a + 1);
    const std::string method = name.substr(a + 1, b - a - 1);
    const int n = std::stoi(name.substr(b + 1));
    results()[{n, method}].ns = 1e9 * relgeo_bench::to_seconds(r.GetAdjustedRealTime(), r.time_unit);
  }
};

void print_ratios() {
  std::map<int, std::map<std::string, Row>> by_n;
  for (const auto& [k, v] : results())
    if (v.ns > 0) by_n[k.first][k.second] = v;
  if (by_n.empty()) return;
  std::printf("\nratios: real time per solve (factor + solve) divided by Eigen::PartialPivLU's; eta / omega: the\n"
              "normwise / componentwise backward error of the computed solution (exact), u = 2^-53.\n");
  const char* methods[] = {"none", "partial", "complete", "eigen-partial", "eigen-full"};
  for (const auto& [n, rows] : by_n) {
    std::printf("\nn = %-5d %-14s %12s %10s %11s %11s %10s %10s\n", n, "method", "time", "/eigen-p", "eta", "omega", "eta/(n u)", "growth");
    const auto ref = rows.find("eigen-partial");
    for (const char* m : methods) {
      const auto it = rows.find(m);
      if (it == rows.end()) continue;
      const Row& r = it->second;
      char t[32];
      if (r.ns < 1e3) std::snprintf(t, sizeof t, "%.1f ns", r.ns);
      else if (r.ns < 1e6) std::snprintf(t, sizeof t, "%.2f us", r.ns / 1e3);
      else if (r.ns < 1e9) std::snprintf(t, sizeof t, "%.2f ms", r.ns / 1e6);
      else std::snprintf(t, sizeof t, "%.2f s", r.ns / 1e9);
      char ratio[16] = "n/a";
      if (ref != rows.end()) std::snprintf(ratio, sizeof ratio, "%.2f", r.ns / ref->second.ns);
      char growth[16] = "-";
      if (r.growth > 0) std::snprintf(growth, sizeof growth, "%.3g", r.growth);
      std::printf("          %-14s %12s %10s %11.3g %11.3g %10.3f %10s\n", m, t, ratio, r.eta, r.omega,
                  r.eta / (n * 0x1p-53), growth);
    }
  }
}


}  // namespace

int main(int argc, char** argv) {
  relgeo_bench::Command_line args(argc, argv);
  args.set_measuring_defaults("0.2", "1");
  if (!args.initialize()) return 1;
  for (Linear_solver m : all_linear_solvers) {
    auto* b = benchmark::RegisterBenchmark(("solve/" + std::string(to_string(m))).c_str(),
                                           [m](benchmark::State& s) { bench_solve(s, m); });
    for (int size : {10, 30, 100, 300, 1000}) b->Arg(size);
    b->Unit(benchmark::kMicrosecond);
  }
  Linear_reporter reporter;
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks(&reporter);
  print_ratios();
  return relgeo_bench::finish(ran, "relgeo_linear_benchmark");
}
