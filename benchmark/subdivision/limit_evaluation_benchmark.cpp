// benchmark/subdivision/limit_evaluation_benchmark.cpp — throughput of exact
// limit-surface evaluation (limit_evaluation.h) and of the error bounds
// (error_bounds.h), single-threaded, with a throughput table at the end.
//
// Benchmarks are named `limit/<subject>`:
//   regular/<kernel>          random points of a jittered all-valence-6 torus
//                             (4032 faces): box spline through the 12 basis
//                             values (double, interval, exact: GMP rationals
//                             on a dyadic torus, mpfr-53);
//   regular-jet/double        the same with derivatives and normal;
//   crease/double             regular crease patches (ghost points) of a
//                             jittered open grid;
//   near-ev-2^-K/double       points at parameter distance ~2^-K from a
//                             valence-5 vertex (icosphere): K local
//                             subdivision steps each (K = 2, 8, 20);
//   corner-2^-8/double        next to the corners of a jittered creased box;
//   bounds/double             Loop_error_bounds::compute, faces per second
//                             (icosphere(2) at level 1: 1280 faces, 60 of
//                             them irregular);
//   bounds/exact              the same in GMP rationals, an icosahedron at
//                             level 0 with shallow depths (20 faces).
// items_per_second is points (faces for bounds) per CPU second. No peer: CGAL
// and OpenMesh evaluate Loop surfaces only by refinement (OpenSubdiv, which
// has patch evaluation, is not packaged on Debian 12).
//
// The table gives, per subject, the best throughput over the repetitions
// (waiting for a core on the shared machine only lowers it) and the project's
// bar: regular patches in double >= 10^6 points per second per core.
// The exit status is 0 whatever the throughput.
#include <benchmark/benchmark.h>

#include "common/command_line.h"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mesh/mesh_fixtures.h"
#include "relgeo/kernel.h"
#include "relgeo/subdivision.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

struct Query {
  Index face;
  double u, v;
};

std::uint64_t rng_state = 0x9E3779B97F4A7C15ull;
double uniform() {
  rng_state ^= rng_state << 13, rng_state ^= rng_state >> 7, rng_state ^= rng_state << 17;
  return double(rng_state >> 11) * 0x1p-53;
}

// Random points of the given faces; dyadic parameters (multiples of 2^-20) so
// every kernel takes them exactly and u + v <= 1 holds exactly.
std::vector<Query> random_queries(const std::vector<Index>& faces, std::size_t n) {
  std::vector<Query> q;
  while (q.size() < n) {
    const double u = std::ldexp(std::floor(uniform() * 0x1p20), -20), v = std::ldexp(std::floor(uniform() * 0x1p20), -20);
    if (u + v > 1) continue;
    q.push_back({faces[std::size_t(uniform() * faces.size()) % faces.size()], u, v});
  }
  return q;
}

template <class K>
std::vector<Index> faces_of_kind(const Loop_limit_surface<K>& s, Loop_patch_kind kind) {
  std::vector<Index> f;
  for (Index i = 0; i < s.number_of_faces(); ++i)
    if (s.patch_kind(i) == kind) f.push_back(i);
  return f;
}

// Loop_error_bounds::compute of `mesh` at `level`, faces of the refined mesh
// per second.
template <class K>
void register_bounds(const std::string& name, Triangle_mesh<typename K::Point_3> mesh, Loop_bound_options depths,
                     unsigned level) {
  auto m = std::make_shared<const Triangle_mesh<typename K::Point_3>>(std::move(mesh));
  benchmark::RegisterBenchmark(name.c_str(), [m, depths, level](benchmark::State& state) {
    const Loop_error_bounds<K> eb(Loop_options{}, depths);
    std::size_t faces = 0;
    for (auto _ : state) {
      auto r = eb.compute(*m, level);
      faces = r.refined.faces.size();
      benchmark::DoNotOptimize(r.basis_range.data());
    }
    state.SetItemsProcessed(state.iterations() * int64_t(faces));
    state.counters["faces"] = double(faces);
  })->Unit(benchmark::kMillisecond);
}

template <class K>
void register_eval(const std::string& name, std::shared_ptr<Loop_limit_surface<K>> s, std::vector<Query> queries,
                   bool jet = false) {
  benchmark::RegisterBenchmark(("limit/" + name).c_str(), [s, queries, jet](benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
      const Query& q = queries[i++ % queries.size()];
      if (jet) {
        auto j = s->evaluate_with_derivatives(q.face, q.u, q.v);
        benchmark::DoNotOptimize(j);
      } else {
        auto p = s->evaluate(q.face, q.u, q.v);
        benchmark::DoNotOptimize(p);
      }
    }
    state.SetItemsProcessed(state.iterations());
  });
}

template <class K>
std::shared_ptr<Loop_limit_surface<K>> surface_of(const Mesh_d& m) {
  using FT = typename K::FT;
  return std::make_shared<Loop_limit_surface<K>>(convert<FT>(m));
}

void register_all() {
  using D = Naive_kernel<double>;
  // Regular patches.
  const Mesh_d tor = jitter(torus(72, 28), 0.01);
  auto sd = std::make_shared<Loop_limit_surface<D>>(tor);
  const auto reg = random_queries(faces_of_kind(*sd, Loop_patch_kind::regular), 4096);
  register_eval<D>("regular/double", sd, reg);
  register_eval<D>("regular-jet/double", sd, reg, true);
  register_eval<Interval_kernel>("regular/interval", surface_of<Interval_kernel>(tor), reg);
  register_eval<Mpfr_kernel<53>>("regular/mpfr-53", surface_of<Mpfr_kernel<53>>(tor), reg);
  const Mesh_d dyadic = dyadic_torus(72, 28);
  register_eval<Exact_kernel>("regular/exact", surface_of<Exact_kernel>(dyadic), reg);
  // Regular crease patches (ghosts).
  {
    const Mesh_d grid = jitter(open_grid(40), 0.01);
    auto s = std::make_shared<Loop_limit_surface<D>>(grid);
    register_eval<D>("crease/double", s, random_queries(faces_of_kind(*s, Loop_patch_kind::regular_crease), 4096));
  }
  // Near a valence-5 vertex: corner 0 of the faces around it, distance ~2^-K.
  {
    const Mesh_d ico = icosphere(1);
    auto s = std::make_shared<Loop_limit_surface<D>>(ico);
    const Mesh_topology& t = s->topology();
    for (int k : {2, 8, 20}) {
      std::vector<Query> q;
      for (Index f = 0; f < ico.faces.size(); ++f)
        for (int c = 0; c < 3; ++c)
          if (t.valence(ico.faces[f][c]) == 5)
            for (int i = 0; i < 8; ++i) {
              const double d = std::ldexp(1.0, -k), a = (0.5 + i) / 8;
              // the point at distance ~d from corner c along a ray into the face
              const double s1 = d * a, s2 = d * (1 - a);
              q.push_back(c == 0 ? Query{f, s1, s2} : c == 1 ? Query{f, 1 - s1 - s2, s1} : Query{f, s2, 1 - s1 - s2});
            }
      register_eval<D>("near-ev-2^-" + std::to_string(k) + "/double", s, q);
    }
  }
  // Next to the corners of a creased box.
  {
    const Mesh_d box = jitter(creased_box(), 0.3);
    auto s = std::make_shared<Loop_limit_surface<D>>(box);
    std::vector<Query> q;
    for (Index f = 0; f < box.faces.size(); ++f)
      for (int i = 0; i < 8; ++i) q.push_back({f, std::ldexp(1.0 + i, -11), std::ldexp(8.0 - i, -11)});
    register_eval<D>("corner-2^-8/double", s, q);
  }
  // Error bounds: in doubles, icosphere(2) at level 1; in GMP rationals, of the
  // control mesh's own limit mesh (level 0) with the shallow depths of the
  // stress run over CGAL's data set, an icosahedron (20 faces, all valence 5).
  register_bounds<D>("limit/bounds/double", icosphere(2), {}, 1);
  register_bounds<Exact_kernel>("limit/bounds/exact", convert<Exact_kernel::FT>(icosphere(0)),
                                {.irregular_depth = 2, .regular_depth = 1, .universal_depth = 2}, 0);
}

class Throughput_reporter : public relgeo_bench::Collecting_reporter {
 public:
  void collect(const Run& r) override {
    const auto it = r.counters.find("items_per_second");
    if (it == r.counters.end()) return;
    auto& best = best_[r.run_name.function_name];
    best = std::max(best, double(it->second));
    if (std::find(order_.begin(), order_.end(), r.run_name.function_name) == order_.end())
      order_.push_back(r.run_name.function_name);
  }
  void print(std::ostream& out) const {
    if (best_.empty()) return;
    const auto get = [&](const std::string& n) {
      auto it = best_.find(n);
      return it == best_.end() ? NAN : it->second;
    };
    const double reg = get("limit/regular/double");
    out << "\nthroughput per core (the best over the repetitions; items = points, faces for bounds):\n";
    out << std::left << std::setw(30) << "subject" << std::right << std::setw(14) << "items/s" << std::setw(14)
        << "/ regular" << "  bar\n";
    for (const std::string& n : order_) {
      const double v = get(n);
      std::string bar;
      if (n == "limit/regular/double") bar = std::string(">= 1e6 points/s ") + (v >= 1e6 ? "PASS" : "MISS");
      out << std::left << std::setw(30) << n.substr(6) << std::right << std::setw(14) << std::setprecision(3) << v
          << std::setw(14) << std::setprecision(3) << v / reg << "  " << bar << "\n";
    }
  }

 private:
  std::map<std::string, double> best_;
  std::vector<std::string> order_;
};

}  // namespace

int main(int argc, char** argv) {
  relgeo_bench::Command_line args(argc, argv);
  args.set_measuring_defaults("0.3");
  if (!args.initialize()) return 1;
  register_all();
  Throughput_reporter reporter;
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print(std::cout);
  return relgeo_bench::finish(ran, "relgeo_limit_evaluation_benchmark");
}
