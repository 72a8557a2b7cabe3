// benchmark/kernel/predicate_benchmark.h — shared machinery of the predicate
// throughput suite (relgeo_predicate_benchmark).
//
// A *subject* is one way of evaluating orientation predicates: a relgeo kernel
// (through its functors) or a CGAL kernel's own functors used directly. For
// every subject and input family the suite pre-builds a fixed batch of queries
// in the subject's point type (construction is not timed) and times one pass
// over the batch per benchmark iteration. The signs are summed and the sum
// passed to benchmark::DoNotOptimize, so no call can be dropped.
//
// A branch predictor replaying the same batch thousands of times learns its
// sign sequence, and the time of a predicate that branches on the sign (CGAL's
// filters do; relgeo's fast paths do not) then depends on how much it learnt,
// which depends on the batch size, the binary's code layout and what else ran
// on the core: with 4096 queries CGAL::Epick's own functor measured 2.3 ns in
// one build and 5.2 ns in another; on 2026-11-25, 2.6 ns on uniform
// orientation_2 input while the same functor behind relgeo's adapter, whose
// two extra branches dilute the branch history, measured 8.0 ns (a "3x
// adapter cost" that was the predictor's); and with 32768 queries 3.5 ns in
// two full runs and 13 ns in others, same binary. So every pass swaps the
// first two points of a pseudo-random half of the queries, differently in
// each pass (swapped() below): no sign sequence is ever replayed. The batch
// stays large (kDefaultCases = 32768 queries) so that a pass is long against
// the timer; --relgeo_cases=N changes it.
//
// Benchmark names are `<predicate>/<family>/<subject>`, e.g.
// `orientation_2/near-collinear/failsafe<double>`; the ratio table of
// predicate_benchmark.cpp parses them.
#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/core/certified_sign.h"

namespace relgeo_bench {

using relgeo::analysis::Orientation_2_case;
using relgeo::analysis::Orientation_3_case;
using relgeo::analysis::Workload;

/// Default number of queries per family (every iteration evaluates all of them).
inline constexpr std::size_t kDefaultCases = 32768;

using Bench_fn_2 = std::function<void(benchmark::State&, const Workload<Orientation_2_case>&)>;
using Bench_fn_3 = std::function<void(benchmark::State&, const Workload<Orientation_3_case>&)>;

/// One subject: its display name (the last component of the benchmark name),
/// its two benchmark bodies, and `release`, which frees the points they built
/// (called before main returns, so no kernel object outlives the statics of
/// the library it comes from).
struct Subject {
  std::string name;
  Bench_fn_2 orientation_2;
  Bench_fn_3 orientation_3;
  std::function<void()> release;
};

/// The subjects of each translation unit, in display order.
std::vector<Subject> relgeo_subjects();       // predicate_benchmark.cpp
std::vector<Subject> cgal_subjects();         // predicate_benchmark_cgal.cpp (SC<double>, Epick)
std::vector<Subject> cgal_epeck_subjects();   // predicate_benchmark_epeck.cpp

/// Integer value of a predicate answer: -1, 0, 1, and 2 for relgeo's `uncertain`.
inline int sign_value(relgeo::Certified_sign s) { return relgeo::to_int(s); }
template <class CgalSign>
int sign_value(CgalSign s) {
  return static_cast<int>(s);
}

/// Whether query i of pass `pass` swaps its first two points (which negates
/// the orientation): the top bit of a multiplicative hash, computed without a
/// branch, different in every pass. So no two passes present the same
/// sequence of signs, and a branch predictor cannot learn it by replay: a
/// predicate that branches on the sign pays its mispredictions in every
/// pass, however quiet the core (measured: CGAL::Epick's own orientation_2
/// on uniform input read 3.5 ns per call in some full runs of 32768 replayed
/// queries and 13 ns in others, with 80% of its sign branches learnt or not;
/// relgeo's filtered kernel, which does not branch on the sign, 2.8 ns in all).
inline bool swapped(std::uint64_t pass, std::size_t i) {
  return ((static_cast<std::uint64_t>(i) + pass) * 0x9E3779B97F4A7C15ull) >> 63;
}

/// The timed loop shared by every subject: one pass over the batch per
/// iteration; `call(i, swap)` evaluates query i, with its first two points
/// swapped when `swap`, and returns its sign value.
template <class Call>
void time_batch(benchmark::State& state, std::size_t n, Call call, double uncertain_fraction) {
  std::uint64_t pass = 0x5DEECE66Dull;
  for (auto _ : state) {
    int acc = 0;
    pass += 0x2545F4914F6CDD1Dull;
    for (std::size_t i = 0; i < n; ++i) acc += call(i, swapped(pass, i));
    benchmark::DoNotOptimize(acc);
  }
  const auto calls = static_cast<double>(n);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(n));
  // Seconds per call (shown with an SI prefix, e.g. "2.1n" = 2.1 ns).
  state.counters["time/call"] =
      benchmark::Counter(calls, benchmark::Counter::kIsIterationInvariantRate |
                                    benchmark::Counter::kInvert);
  state.counters["uncertain"] = benchmark::Counter(uncertain_fraction);
}

/// The queries of one family in a subject's point types, and the fraction of
/// them the subject answers `uncertain` (relgeo kernels only).
template <class Q>
struct Prepared {
  const void* key = nullptr;
  std::vector<Q> queries;
  double uncertain = 0;
};

/// Benchmark bodies for a subject described by a policy S with
///   typename S::Point_2, S::Point_3;
///   static Point_2 point_2(double x, double y);
///   static Point_3 point_3(double x, double y, double z);
///   an object `S::orientation_2()` callable as o(p, q, r), and `S::orientation_3()`.
/// The points of a family are built on first use and kept (also across the
/// library's trial runs), so lazy kernels keep whatever they cache.
template <class S>
Subject make_subject(std::string name) {
  using P2 = typename S::Point_2;
  using P3 = typename S::Point_3;
  struct Q2 {
    P2 p, q, r;
  };
  struct Q3 {
    P3 p, q, r, s;
  };
  // One Prepared per workload, keyed by its address (each registered
  // benchmark owns one workload).
  using Cache2 = std::vector<std::unique_ptr<Prepared<Q2>>>;
  using Cache3 = std::vector<std::unique_ptr<Prepared<Q3>>>;
  auto cache2 = std::make_shared<Cache2>();
  auto cache3 = std::make_shared<Cache3>();

  // Finds or builds the prepared queries of w; build(case) makes one query.
  auto prepare = [](auto& cache, const auto& w, auto build, auto evaluate) -> const auto& {
    for (const auto& p : cache)
      if (p->key == &w) return *p;
    using Q = typename std::remove_reference_t<decltype(cache)>::value_type::element_type;
    auto p = std::make_unique<Q>();
    p->key = &w;
    p->queries.reserve(w.cases.size());
    for (const auto& c : w.cases) p->queries.push_back(build(c));
    std::size_t uncertain = 0;
    for (const auto& q : p->queries) uncertain += evaluate(q) == 2;
    p->uncertain = p->queries.empty() ? 0.0
                                      : static_cast<double>(uncertain) /
                                            static_cast<double>(p->queries.size());
    cache.push_back(std::move(p));
    return *cache.back();
  };

  Bench_fn_2 b2 = [cache2, prepare](benchmark::State& state,
                                    const Workload<Orientation_2_case>& w) {
    const auto orient = S::orientation_2();
    const auto eval = [&](const Q2& c) { return sign_value(orient(c.p, c.q, c.r)); };
    const auto& prepared = prepare(
        *cache2, w,
        [](const Orientation_2_case& c) {
          return Q2{S::point_2(c.px, c.py), S::point_2(c.qx, c.qy), S::point_2(c.rx, c.ry)};
        },
        eval);
    const Q2* data = prepared.queries.data();
    time_batch(state, prepared.queries.size(),
               [&](std::size_t i, bool swap) {
                 const Q2& c = data[i];
                 const P2& a = swap ? c.q : c.p;  // selected, not branched on
                 const P2& b = swap ? c.p : c.q;
                 return sign_value(orient(a, b, c.r));
               },
               prepared.uncertain);
  };
  Bench_fn_3 b3 = [cache3, prepare](benchmark::State& state,
                                    const Workload<Orientation_3_case>& w) {
    const auto orient = S::orientation_3();
    const auto eval = [&](const Q3& c) { return sign_value(orient(c.p, c.q, c.r, c.s)); };
    const auto& prepared = prepare(
        *cache3, w,
        [](const Orientation_3_case& k) {
          const auto& c = k.c;
          return Q3{S::point_3(c[0], c[1], c[2]), S::point_3(c[3], c[4], c[5]),
                    S::point_3(c[6], c[7], c[8]), S::point_3(c[9], c[10], c[11])};
        },
        eval);
    const Q3* data = prepared.queries.data();
    time_batch(state, prepared.queries.size(),
               [&](std::size_t i, bool swap) {
                 const Q3& c = data[i];
                 const P3& a = swap ? c.q : c.p;
                 const P3& b = swap ? c.p : c.q;
                 return sign_value(orient(a, b, c.r, c.s));
               },
               prepared.uncertain);
  };
  auto release = [cache2, cache3] {
    cache2->clear();
    cache3->clear();
  };
  return Subject{std::move(name), std::move(b2), std::move(b3), std::move(release)};
}

/// Policy for a relgeo kernel K, used through its functors as an algorithm would.
template <class K>
struct Relgeo_policy {
  using Point_2 = typename K::Point_2;
  using Point_3 = typename K::Point_3;
  static Point_2 point_2(double x, double y) { return K().construct_point_2_object()(x, y); }
  static Point_3 point_3(double x, double y, double z) {
    return K().construct_point_3_object()(x, y, z);
  }
  static auto orientation_2() { return K().orientation_2_object(); }
  static auto orientation_3() { return K().orientation_3_object(); }
};
template <class K>
Subject relgeo_subject() {
  return make_subject<Relgeo_policy<K>>(K::name());
}

/// Policy for a CGAL kernel K's own functors, used directly (no relgeo adapter).
template <class K>
struct Cgal_direct_policy {
  using Point_2 = typename K::Point_2;
  using Point_3 = typename K::Point_3;
  static Point_2 point_2(double x, double y) { return Point_2(x, y); }
  static Point_3 point_3(double x, double y, double z) { return Point_3(x, y, z); }
  static auto orientation_2() { return typename K::Orientation_2(); }
  static auto orientation_3() { return typename K::Orientation_3(); }
};

}  // namespace relgeo_bench
