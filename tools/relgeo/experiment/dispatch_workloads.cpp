// tools/relgeo/workload_eval.cpp — predicate workloads under every kernel,
// timed (instantiates all kernels, CGAL Epeck included).
#include <chrono>
#include <vector>

#include "kernel_dispatch.h"
#include "kernel_runs.h"

namespace relgeo::tool {

namespace {

using Clock = std::chrono::steady_clock;

/// Keeps the compiler from dropping the timed loop.
volatile int sink = 0;

/// Times `eval` over the prebuilt points, repeating the loop until
/// min_seconds have passed (at least once); the time per predicate is that
/// of the fastest pass (least disturbed by other processes on a shared
/// machine).
template <class Points, class Eval>
Workload_measurement run_timed(const std::vector<Points>& points, std::span<const Certified_sign> exact,
                               double min_seconds, Eval eval) {
  Workload_measurement m;
  std::vector<Certified_sign> answers(points.size());
  const auto start = Clock::now();
  double best = -1;
  std::size_t passes = 0;
  for (;;) {
    const auto pass_start = Clock::now();
    int check = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      answers[i] = eval(points[i]);
      check += static_cast<int>(answers[i]);
    }
    const auto now = Clock::now();
    sink = sink + check;
    ++passes;
    const double t = std::chrono::duration<double>(now - pass_start).count();
    if (best < 0 || t < best) best = t;
    if (points.empty() || std::chrono::duration<double>(now - start).count() >= min_seconds) break;
  }
  m.timed_evaluations = passes * points.size();
  m.ns_per_predicate = points.empty() ? 0.0 : best * 1e9 / double(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) m.tally.add(exact[i], answers[i]);
  return m;
}

}  // namespace

Workload_measurement measure_orientation_2(std::string_view kernel,
                                           std::span<const analysis::Orientation_2_case> cases,
                                           std::span<const Certified_sign> exact,
                                           double min_seconds) {
  if (cases.size() != exact.size()) throw Precondition_violation("measure_orientation_2: sizes differ");
  return with_kernel(kernel, [&]<class K>(const K& k) {
    using P = typename K::Point_2;
    struct Triple { P p, q, r; };
    const auto pt = k.construct_point_2_object();
    std::vector<Triple> points;
    points.reserve(cases.size());
    for (const auto& c : cases) points.push_back({pt(c.px, c.py), pt(c.qx, c.qy), pt(c.rx, c.ry)});
    const auto orient = k.orientation_2_object();
    return run_timed(points, exact, min_seconds,
                     [&](const Triple& t) { return orient(t.p, t.q, t.r); });
  });
}

Workload_measurement measure_orientation_3(std::string_view kernel,
                                           std::span<const analysis::Orientation_3_case> cases,
                                           std::span<const Certified_sign> exact,
                                           double min_seconds) {
  if (cases.size() != exact.size()) throw Precondition_violation("measure_orientation_3: sizes differ");
  return with_kernel(kernel, [&]<class K>(const K& k) {
    using P = typename K::Point_3;
    struct Quadruple { P p, q, r, s; };
    const auto pt = k.construct_point_3_object();
    std::vector<Quadruple> points;
    points.reserve(cases.size());
    for (const auto& c : cases) {
      const auto& v = c.c;
      points.push_back({pt(v[0], v[1], v[2]), pt(v[3], v[4], v[5]), pt(v[6], v[7], v[8]),
                        pt(v[9], v[10], v[11])});
    }
    const auto orient = k.orientation_3_object();
    return run_timed(points, exact, min_seconds,
                     [&](const Quadruple& t) { return orient(t.p, t.q, t.r, t.s); });
  });
}

}  // namespace relgeo::tool
