#include "soundness_data.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <mutex>

#include "exact_oracle.h"
#include "relgeo/core/floating_point.h"

namespace relgeo::test {
namespace {

using analysis::Orientation_2_case;
using analysis::Orientation_3_case;

double to_precision(double v, Input_precision p) {
  return p == Input_precision::binary32 ? static_cast<double>(static_cast<float>(v)) : v;
}

bool finite(const Orientation_2_case& c) { return relgeo::all_finite(c.px, c.py, c.qx, c.qy, c.rx, c.ry); }
bool finite(const Orientation_3_case& c) {
  for (double v : c.c)
    if (!std::isfinite(v)) return false;
  return true;
}
bool finite(const Coplanar_case& c) {
  for (double v : c.c)
    if (!std::isfinite(v)) return false;
  return true;
}
bool finite(const Compare_case& c) { return relgeo::all_finite(c.x1, c.y1, c.x2, c.y2); }

// Rounding to float can overflow the extreme-magnitude cases: those are dropped
// (the bad-input tests cover non-finite coordinates).
template <class Case, class Round>
void add_family(Labelled_cases<Case>& out, const std::string& name, std::vector<Case> cases,
                Round round) {
  out.family.push_back(name);
  out.begin.push_back(out.cases.size());
  for (auto& c : cases) {
    const Case r = round(c);
    if (finite(r)) out.cases.push_back(r);
  }
}

template <class Case, class Oracle>
void finish(Labelled_cases<Case>& l, Oracle oracle) {
  l.begin.push_back(l.cases.size());
  l.exact.reserve(l.cases.size());
  for (const auto& c : l.cases) l.exact.push_back(oracle(c));
}

Soundness_data build(Input_precision prec) {
  const double scale = test_scale();
  const auto n = [&](double base) { return static_cast<std::size_t>(base * scale) + 1; };
  Soundness_data d;

  auto round2 = [prec](Orientation_2_case c) {
    for (double* v : {&c.px, &c.py, &c.qx, &c.qy, &c.rx, &c.ry}) *v = to_precision(*v, prec);
    return c;
  };
  for (auto& w : analysis::standard_workloads_2(n(201000)))
    add_family(d.orientation_2, w.name, std::move(w.cases), round2);
  for (const auto& t : analysis::kettner_grid_triples())
    add_family(d.orientation_2, "grid-" + t.name, analysis::grid_cases(t), round2);
  finish(d.orientation_2, oracle_orientation_2);

  auto round3 = [prec](Orientation_3_case c) {
    for (double& v : c.c) v = to_precision(v, prec);
    return c;
  };
  for (auto& w : analysis::standard_workloads_3(n(250000)))
    add_family(d.orientation_3, w.name, std::move(w.cases), round3);
  finish(d.orientation_3, oracle_orientation_3);

  // Coplanar orientation: planar cases lifted into space in two ways: onto a
  // plane whose xy projection is the case itself, and onto x = y, whose xy
  // projection is degenerate so that the yz projection decides.
  for (auto& w : analysis::standard_workloads_2(n(125000), 101)) {
    std::vector<Coplanar_case> lifted;
    lifted.reserve(2 * w.cases.size());
    for (const auto& c : w.cases) {
      lifted.push_back({{c.px, c.py, c.px + c.py, c.qx, c.qy, c.qx + c.qy, c.rx, c.ry, c.rx + c.ry}});
      lifted.push_back({{c.px, c.px, c.py, c.qx, c.qx, c.qy, c.rx, c.rx, c.ry}});
    }
    add_family(d.coplanar, w.name, std::move(lifted), [prec](Coplanar_case c) {
      for (double& v : c.c) v = to_precision(v, prec);
      return c;
    });
  }
  finish(d.coplanar, [](const Coplanar_case& c) { return oracle_coplanar_orientation_3(c.c); });

  for (auto& w : analysis::standard_workloads_2(n(250000), 202)) {
    std::vector<Compare_case> pairs;
    pairs.reserve(w.cases.size());
    for (const auto& c : w.cases) pairs.push_back({c.px, c.py, c.qx, c.qy});
    add_family(d.compare_xy, w.name, std::move(pairs), [prec](Compare_case c) {
      for (double* v : {&c.x1, &c.y1, &c.x2, &c.y2}) *v = to_precision(*v, prec);
      return c;
    });
  }
  finish(d.compare_xy, [](const Compare_case& c) { return oracle_compare_xy(c.x1, c.y1, c.x2, c.y2); });
  return d;
}

}  // namespace

double test_scale() {
  const char* s = std::getenv("RELGEO_TEST_SCALE");
  if (!s) return 1.0;
  const double v = std::atof(s);
  return v > 0 ? v : 1.0;
}

const Soundness_data& soundness_data(Input_precision precision) {
  static std::mutex m;
  static std::map<Input_precision, Soundness_data> cache;
  std::lock_guard lock(m);
  auto it = cache.find(precision);
  if (it == cache.end()) it = cache.emplace(precision, build(precision)).first;
  return it->second;
}

}  // namespace relgeo::test
