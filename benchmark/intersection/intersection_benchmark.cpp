// relgeo_intersection_benchmark: implicit points and triangle-triangle
// intersection, relgeo's kernels against CGAL in one run.
//  * lpi_orientation/<family>/<subject>: build the LPI point of a line and a
//    plane, then its orientation against another plane (CGAL Epeck: the
//    intersection constructed with CGAL::intersection, then orientation);
//  * exact_stage/<family>/<expansion|gmp>: the two exact stages of
//    Filtered_exact_kernel alone on orientation_3 cases of the implicit-point
//    soundness families (relgeo::analysis::implicit_workloads), ratio to GMP:
//    what decides where the kernel tries expansions before GMP;
//  * triangle_pair/<family>/<subject>: whether two triangles intersect
//    (relgeo: do_intersect_triangles; intersect_triangles for the full
//    classified intersection; CGAL: do_intersect(Triangle_3, Triangle_3)).
// Times are per query. Each subject is measured five times; the table at the
// end gives the minimum of the repetitions and its ratio to CGAL.
#include "intersection_benchmark.h"

#include <cstdio>
#include <map>
#include <optional>
#include <random>

#include "common/command_line.h"
#include "relgeo/analysis/implicit_workloads.h"
#include "relgeo/intersection/triangle_intersection.h"
#include "relgeo/kernel.h"

namespace relgeo_bench {

const std::vector<Lpi_query>& lpi_queries(const std::string& family) {
  static std::map<std::string, std::vector<Lpi_query>> cache;
  auto& out = cache[family];
  if (!out.empty()) return out;
  std::mt19937_64 g(family == "random" ? 1 : 2);
  const auto u = [&] { return relgeo::analysis::internal_workloads::uniform(g, -1, 1); };
  for (int i = 0; i < 4096; ++i) {
    Lpi_query q;
    for (auto& p : q.v) p = {u(), u(), u()};
    if (family == "on-plane") q.v[5] = q.v[2], q.v[6] = q.v[3], q.v[7] = q.v[4];  // a b c = r s t
    out.push_back(q);
  }
  return out;
}

const std::vector<relgeo::analysis::Triangle_pair>& triangle_pairs(const std::string& family) {
  static const auto all = relgeo::analysis::triangle_pair_workloads(4096, 5);
  for (const auto& w : all)
    if (w.name == family) return w.pairs;
  static const std::vector<relgeo::analysis::Triangle_pair> none;
  return none;
}

benchmark::internal::Benchmark* register_subject(const std::string& name, void (*f)(benchmark::State&, const std::string&),
                                                 const std::string& family) {
  return benchmark::RegisterBenchmark(name.c_str(), f, family)
      ->Repetitions(5)
      ->ComputeStatistics("min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); })
      ->ReportAggregatesOnly(false);
}

namespace {

template <class K>
void lpi_orientation(benchmark::State& state, const std::string& family) {
  const K k;
  const auto point = k.construct_point_3_object();
  const auto make = k.construct_implicit_point_3_object();
  const auto orient = k.implicit_orientation_3_object();
  const auto& queries = lpi_queries(family);
  std::vector<std::array<typename K::Point_3, 8>> pts;
  for (const auto& q : queries) {
    std::array<typename K::Point_3, 8> a;
    for (int i = 0; i < 8; ++i) a[i] = point(q.v[i][0], q.v[i][1], q.v[i][2]);
    pts.push_back(a);
  }
  for (auto _ : state)
    for (const auto& a : pts) {
      const auto x = make(a[0], a[1], a[2], a[3], a[4]);
      benchmark::DoNotOptimize(orient(a[5], a[6], a[7], *x));
    }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * pts.size()));
}

// The orientation_3 cases of one implicit-point family, as Filtered_exact_kernel points.
struct Exact_stage_cases {
  std::vector<std::optional<relgeo::Filtered_exact_kernel::Implicit_point_3>> points;
  std::vector<std::array<const relgeo::Filtered_exact_kernel::Implicit_point_3*, 4>> cases;
};
const Exact_stage_cases& exact_stage_cases(const std::string& family) {
  static std::map<std::string, Exact_stage_cases> cache;
  auto [it, fresh] = cache.try_emplace(family);
  if (!fresh) return it->second;
  const relgeo::Filtered_exact_kernel k;
  for (const auto& w : relgeo::analysis::implicit_workloads(3000, 20261126)) {
    if (w.name != family) continue;
    auto& out = it->second;
    for (const auto& d : w.points) out.points.push_back(relgeo::analysis::build_implicit_point(k, d));
    for (const auto& c : w.orientation_3) {
      std::array<const relgeo::Filtered_exact_kernel::Implicit_point_3*, 4> p{};
      bool exists = true;
      for (int i = 0; i < 4; ++i) {
        exists = exists && out.points[c.p[i]].has_value();
        if (exists) p[i] = &*out.points[c.p[i]];
      }
      if (exists) out.cases.push_back(p);
    }
  }
  return it->second;
}

template <bool Expansion>
void exact_stage(benchmark::State& state, const std::string& family) {
  namespace in = relgeo::internal;
  const auto& cases = exact_stage_cases(family).cases;
  const auto sign = [](const auto& h) { return in::orientation_3_sign(h); };
  const relgeo::Default_fp_environment environment;
  for (auto _ : state)
    for (const auto& p : cases) {
      const in::Defining_doubles<4> inputs(p);
      if constexpr (Expansion)
        benchmark::DoNotOptimize(in::expansion_sign(inputs.values(), inputs.degree(), in::implicit_formula(p, sign)));
      else
        benchmark::DoNotOptimize(in::integer_sign(inputs.values(), in::implicit_formula(p, sign)));
    }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cases.size()));
}

template <class K, bool Full>
void triangle_pair(benchmark::State& state, const std::string& family) {
  const K k;
  const auto point = k.construct_point_3_object();
  std::vector<std::array<std::array<typename K::Point_3, 3>, 2>> pairs;
  for (const auto& p : triangle_pairs(family)) {
    std::array<std::array<typename K::Point_3, 3>, 2> t;
    for (int i = 0; i < 3; ++i)
      t[0][i] = point(p.a[i][0], p.a[i][1], p.a[i][2]), t[1][i] = point(p.b[i][0], p.b[i][1], p.b[i][2]);
    pairs.push_back(t);
  }
  for (auto _ : state)
    for (const auto& t : pairs) {
      if constexpr (Full) benchmark::DoNotOptimize(relgeo::intersect_triangles(t[0], t[1], k).kind);
      else benchmark::DoNotOptimize(relgeo::do_intersect_triangles(t[0], t[1], k));
    }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * pairs.size()));
}

// The table: per benchmark family, min time per item and ratio to the CGAL subject.
class Ratio_reporter : public Collecting_reporter {
 public:
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf("\n%-52s %12s %10s\n", "subject (minimum of 5 repetitions)", "ns/query", "vs CGAL");
    for (const auto& [name, ns] : best_) {
      const auto slash = name.rfind('/');
      const std::string group = name.substr(0, slash);
      const std::string peer = group.rfind("lpi_orientation", 0) == 0
                                   ? "CGAL::Epeck"
                                   : (group.rfind("exact_stage", 0) == 0 ? "gmp" : "CGAL::Epick");
      const auto it = best_.find(group + "/" + peer);
      const double ratio = it == best_.end() ? 0 : ns / it->second;
      std::printf("%-52s %12.1f %10.3f\n", name.c_str(), ns, ratio);
    }
  }
  std::size_t ran() const { return best_.size(); }

 protected:
  void collect(const Run& r) override {
    const double items = r.counters.count("items_per_second") ? r.counters.at("items_per_second").value : 0;
    if (items <= 0) return;
    const double ns = 1e9 / items;
    const std::string name = r.run_name.function_name;
    auto [it, fresh] = best_.emplace(name, ns);
    if (!fresh) it->second = std::min(it->second, ns);
  }

 private:
  std::map<std::string, double> best_;
};

void register_relgeo_subjects() {
  for (const std::string family : {"random", "on-plane"}) {
    register_subject("lpi_orientation/" + family + "/filtered", lpi_orientation<relgeo::Filtered_exact_kernel>, family);
    register_subject("lpi_orientation/" + family + "/interval", lpi_orientation<relgeo::Interval_kernel>, family);
    register_subject("lpi_orientation/" + family + "/failsafe", lpi_orientation<relgeo::Failsafe_kernel<double>>, family);
    register_subject("lpi_orientation/" + family + "/exact", lpi_orientation<relgeo::Exact_kernel>, family);
  }
  for (const std::string family : {"random", "on-plane", "same-point", "near-parallel", "collinear", "tpi-point"}) {
    register_subject("exact_stage/" + family + "/expansion", exact_stage<true>, family);
    register_subject("exact_stage/" + family + "/gmp", exact_stage<false>, family);
  }
  for (const std::string family : {"random", "near", "touching", "coplanar"}) {
    register_subject("triangle_pair/" + family + "/filtered do_intersect", triangle_pair<relgeo::Filtered_exact_kernel, false>, family);
    register_subject("triangle_pair/" + family + "/filtered intersect", triangle_pair<relgeo::Filtered_exact_kernel, true>, family);
    register_subject("triangle_pair/" + family + "/failsafe do_intersect", triangle_pair<relgeo::Failsafe_kernel<double>, false>, family);
  }
}

}  // namespace
}  // namespace relgeo_bench

int main(int argc, char** argv) {
  relgeo_bench::Command_line args(argc, argv);
  if (!args.initialize()) return 2;
  relgeo_bench::register_relgeo_subjects();
  relgeo_bench::register_cgal_subjects();
  relgeo_bench::Ratio_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  return relgeo_bench::finish(reporter.ran(), argv[0]);
}
