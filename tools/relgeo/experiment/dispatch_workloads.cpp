// tools/relgeo/experiment/dispatch_workloads.cpp — predicate workloads under
// every kernel, timed (CGAL Epeck included).
#include <array>
#include <chrono>
#include <string>
#include <vector>

#include "experiment/workloads.h"
#include "kernels/cgal_kernels.h"
#include "kernels/dispatch.h"

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

/// Builds every case's points under the named kernel (not timed), then
/// times `predicate` on them. `points(k, c)` returns the points of case c as
/// an array; `predicate(k)` returns a function of such an array.
template <class Case, class Points, class Predicate>
Workload_measurement measure_workload(std::string_view kernel, std::span<const Case> cases,
                                      std::span<const Certified_sign> exact, double min_seconds, const char* what,
                                      Points points, Predicate predicate) {
  if (cases.size() != exact.size()) throw Precondition_violation(std::string(what) + ": sizes differ");
  return with_kernel(kernel, [&]<class K>(const K& k) {
    using Array = decltype(points(k, cases.front()));
    std::vector<Array> built;
    built.reserve(cases.size());
    for (const auto& c : cases) built.push_back(points(k, c));
    return run_timed(built, exact, min_seconds, predicate(k));
  });
}

}  // namespace

Workload_measurement measure_orientation_2(std::string_view kernel,
                                           std::span<const analysis::Orientation_2_case> cases,
                                           std::span<const Certified_sign> exact, double min_seconds) {
  const auto points = [](const auto& k, const analysis::Orientation_2_case& c) {
    const auto pt = k.construct_point_2_object();
    return std::array{pt(c.px, c.py), pt(c.qx, c.qy), pt(c.rx, c.ry)};
  };
  const auto predicate = [](const auto& k) {
    return [orient = k.orientation_2_object()](const auto& p) { return orient(p[0], p[1], p[2]); };
  };
  return measure_workload(kernel, cases, exact, min_seconds, "measure_orientation_2", points, predicate);
}

Workload_measurement measure_orientation_3(std::string_view kernel,
                                           std::span<const analysis::Orientation_3_case> cases,
                                           std::span<const Certified_sign> exact, double min_seconds) {
  const auto points = [](const auto& k, const analysis::Orientation_3_case& c) {
    const auto pt = k.construct_point_3_object();
    const auto& v = c.c;
    return std::array{pt(v[0], v[1], v[2]), pt(v[3], v[4], v[5]), pt(v[6], v[7], v[8]), pt(v[9], v[10], v[11])};
  };
  const auto predicate = [](const auto& k) {
    return [orient = k.orientation_3_object()](const auto& p) { return orient(p[0], p[1], p[2], p[3]); };
  };
  return measure_workload(kernel, cases, exact, min_seconds, "measure_orientation_3", points, predicate);
}

}  // namespace relgeo::tool
