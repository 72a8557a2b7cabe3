#include "fp_environment_soundness.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "relgeo/core/floating_point.h"
#include "support/exact_oracle.h"

namespace relgeo::test {
namespace {

using analysis::Orientation_2_case;
using analysis::Orientation_3_case;

// m 2^e with a small integer m and e in [e_lo, e_hi]: subnormal for double
// below 2^-1022 (float: 2^-126).
double tiny(std::mt19937_64& g, int e_lo, int e_hi) {
  const int e = e_lo + static_cast<int>(g() % static_cast<unsigned>(e_hi - e_lo + 1));
  const double m = static_cast<double>(static_cast<int>(g() % 15) - 7);
  return std::ldexp(m, e);
}

// Coordinates near 2^e (1 + k 2^-40): differences near 2^(e-40), so with
// e = -500 the determinant's products underflow (below 2^-1022).
double near_power(std::mt19937_64& g, int e) {
  return std::ldexp(1.0 + static_cast<double>(static_cast<int>(g() % 33) - 16) * 0x1p-40, e);
}

template <class Case, class Oracle>
void add(Labelled_cases<Case>& l, const std::string& name, const std::vector<Case>& cases, Oracle oracle) {
  l.family.push_back(name);
  l.begin.push_back(l.cases.size());
  for (const Case& c : cases) {
    l.cases.push_back(c);
    l.exact.push_back(oracle(c));
  }
}

template <class Case>
void close(Labelled_cases<Case>& l) {
  l.begin.push_back(l.cases.size());
}

double rounded(double v, Input_precision p) {
  return p == Input_precision::binary32 ? static_cast<double>(static_cast<float>(v)) : v;
}

Environment_data build(Input_precision p) {
  const bool single = p == Input_precision::binary32;
  const int sub_lo = single ? -149 : -1074, sub_hi = single ? -120 : -1015;
  const int underflow_exponent = single ? -60 : -500;
  const std::size_t n = static_cast<std::size_t>(20000 * test_scale()) + 1;
  const auto o2 = [](const Orientation_2_case& c) { return oracle_orientation_2(c); };
  const auto o3 = [](const Orientation_3_case& c) { return oracle_orientation_3(c); };
  Environment_data d;
  std::mt19937_64 g(20260101);

  // Rounding and the finiteness check are separate loops: GCC 12.2 at -O3
  // (SLP vectorizer) skips the rounding of 2 of 12 coordinates when both are
  // in one loop body (measured; -fno-tree-slp-vectorize avoids it).
  auto finite_rounded_2 = [&](std::vector<Orientation_2_case> cs) {
    std::vector<Orientation_2_case> out;
    for (auto c : cs) {
      for (double* v : {&c.px, &c.py, &c.qx, &c.qy, &c.rx, &c.ry}) *v = rounded(*v, p);
      if (all_finite(c.px, c.py, c.qx, c.qy, c.rx, c.ry)) out.push_back(c);
    }
    return out;
  };
  auto finite_rounded_3 = [&](std::vector<Orientation_3_case> cs) {
    std::vector<Orientation_3_case> out;
    for (auto c : cs) {
      for (double& v : c.c) v = rounded(v, p);
      if (std::all_of(c.c.begin(), c.c.end(), [](double v) { return std::isfinite(v); })) out.push_back(c);
    }
    return out;
  };

  // The example: x-differences 2^-1023 and 2^-1024 (float: 2^-127,
  // 2^-128) both flush to zero, the determinant 2^-1024 (2^-128) does not.
  const double a = single ? 0x1p-127 : 0x1p-1023, b = a / 2;
  add(d.orientation_2, "flushed-differences", {{0, 0, a, 1, b, 1}, {0, 1, a, 0, b, 0}, {b, 0, a, 1, 0, 1}}, o2);
  std::vector<Orientation_2_case> sub2, under2;
  for (std::size_t i = 0; i < n; ++i) {
    sub2.push_back({tiny(g, sub_lo, sub_hi), tiny(g, sub_lo, sub_hi), tiny(g, sub_lo, sub_hi),
                    tiny(g, sub_lo, sub_hi), tiny(g, sub_lo, sub_hi), tiny(g, sub_lo, sub_hi)});
    const int e = underflow_exponent;
    under2.push_back({near_power(g, e), near_power(g, e), near_power(g, e), near_power(g, e), near_power(g, e),
                      near_power(g, e)});
  }
  add(d.orientation_2, "subnormal", finite_rounded_2(sub2), o2);
  add(d.orientation_2, "underflowing-products", finite_rounded_2(under2), o2);
  for (const auto& w : analysis::standard_workloads_2(n, 7))
    if (w.name != "uniform") add(d.orientation_2, w.name, finite_rounded_2(w.cases), o2);
  close(d.orientation_2);

  add(d.orientation_3, "flushed-differences",
      {{{0, 0, 0, a, 1, 0, b, 1, 1, 0, 0, 1}}, {{0, 0, 0, 1, a, 0, 1, b, 1, 0, 0, 1}}}, o3);
  std::vector<Orientation_3_case> sub3, under3;
  for (std::size_t i = 0; i < n; ++i) {
    Orientation_3_case s{}, u{};
    for (double& v : s.c) v = tiny(g, sub_lo, sub_hi);
    for (double& v : u.c) v = near_power(g, single ? -40 : -340);
    sub3.push_back(s);
    under3.push_back(u);
  }
  add(d.orientation_3, "subnormal", finite_rounded_3(sub3), o3);
  add(d.orientation_3, "underflowing-products", finite_rounded_3(under3), o3);
  for (const auto& w : analysis::standard_workloads_3(n, 9))
    if (w.name != "uniform") add(d.orientation_3, w.name, finite_rounded_3(w.cases), o3);
  close(d.orientation_3);

  std::vector<Compare_case> cmp;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = tiny(g, sub_lo, sub_hi), y = tiny(g, sub_lo, sub_hi);
    // Neighbours, equal values, and +0 against -0.
    cmp.push_back({rounded(x, p), rounded(y, p), rounded(i % 3 == 0 ? x : std::nextafter(x, 1.0), p),
                   rounded(i % 5 == 0 ? -y : tiny(g, sub_lo, sub_hi), p)});
  }
  cmp.push_back({0.0, 1.0, -0.0, 1.0});
  add(d.compare_xy, "subnormal", cmp,
      [](const Compare_case& c) { return oracle_compare_xy(c.x1, c.y1, c.x2, c.y2); });
  close(d.compare_xy);
  return d;
}

}  // namespace

const Environment_data& environment_data(Input_precision precision) {
  static const Environment_data binary64 = build(Input_precision::binary64);
  static const Environment_data binary32 = build(Input_precision::binary32);
  return precision == Input_precision::binary32 ? binary32 : binary64;
}

}  // namespace relgeo::test
