// relgeo/analysis/predicate_workloads.h — families of predicate inputs, from
// easy to adversarial, shared by the tests, the benchmarks and the experiment.
//
// All generators are deterministic for a given seed (std::mt19937_64 and
// integer-derived doubles, no std::uniform_real_distribution whose output is
// implementation-defined), so a figure measured on one machine is reproducible
// on another.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace relgeo::analysis {

/// Coordinates of an orientation_2 query (p, q, r) as doubles.
struct Orientation_2_case {
  double px, py, qx, qy, rx, ry;
};
/// Coordinates of an orientation_3 query (p, q, r, s) as doubles.
struct Orientation_3_case {
  std::array<double, 12> c;  // px py pz qx qy qz rx ry rz sx sy sz
};

/// A named family of inputs.
template <class Case>
struct Workload {
  std::string name;
  std::vector<Case> cases;
};

/// v moved by k ulps (k may be negative): the perturbation of the near-degenerate families.
inline double moved_by_ulps(double v, int k) {
  const double dir = k > 0 ? std::numeric_limits<double>::infinity()
                           : -std::numeric_limits<double>::infinity();
  for (int i = 0; i < std::abs(k); ++i) v = std::nextafter(v, dir);
  return v;
}

namespace internal_workloads {

/// Uniform double in [lo, hi) from 53 random bits (portable across libraries).
inline double uniform(std::mt19937_64& g, double lo, double hi) {
  const double u = static_cast<double>(g() >> 11) * 0x1p-53;
  return lo + (hi - lo) * u;
}
inline int small_int(std::mt19937_64& g, int lo, int hi) {
  return lo + static_cast<int>(g() % static_cast<std::uint64_t>(hi - lo + 1));
}

/// The family `name` of n cases, case i = make(g, i) with one generator g
/// seeded by `seed` (cases drawn in order: the family depends on the seed only).
template <class Case, class Make>
Workload<Case> generated(const char* name, std::size_t n, std::uint64_t seed, Make make) {
  std::mt19937_64 g(seed);
  Workload<Case> w{name, {}};
  w.cases.reserve(n);
  for (std::size_t i = 0; i < n; ++i) w.cases.push_back(make(g, i));
  return w;
}

/// `base` renamed, each case changed in place by change(g, case), g seeded by `seed`.
template <class Case, class Change>
Workload<Case> changed(Workload<Case> base, const char* name, std::uint64_t seed, Change change) {
  std::mt19937_64 g(seed);
  base.name = name;
  for (Case& c : base.cases) change(g, c);
  return base;
}

}  // namespace internal_workloads

/// The three orientation grids of Kettner et al. (Figs. 2-4), SPEC Sec. 3.1.
struct Orientation_grid_triple {
  std::string name;
  double px, py, qx, qy, rx, ry;
};
inline std::vector<Orientation_grid_triple> kettner_grid_triples() {
  return {{"a", 0.5, 0.5, 12, 12, 24, 24},
          {"b", 0.50000000000002531, 0.5000000000000171, 17.300000000000001, 17.300000000000001,
           24.00000000000005, 24.000000000000053},
          {"c", 0.5, 0.5, 8.8000000000000007, 8.8000000000000007, 12.1, 12.1}};
}

/// The size x size cells p(X,Y) = (px + X u, py + Y u), u = 2^-53, of a grid
/// triple, row-major with Y the row index.
inline std::vector<Orientation_2_case> grid_cases(const Orientation_grid_triple& t,
                                                  int size = 256) {
  std::vector<Orientation_2_case> out;
  out.reserve(static_cast<std::size_t>(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      out.push_back({t.px + x * 0x1p-53, t.py + y * 0x1p-53, t.qx, t.qy, t.rx, t.ry});
  return out;
}

/// Uniform points in [-1, 1]^2: almost never near-degenerate.
inline Workload<Orientation_2_case> uniform_2(std::size_t n, std::uint64_t seed) {
  return internal_workloads::generated<Orientation_2_case>("uniform", n, seed, [](std::mt19937_64& g, std::size_t) {
    auto u = [&] { return internal_workloads::uniform(g, -1, 1); };
    return Orientation_2_case{u(), u(), u(), u(), u(), u()};
  });
}

/// q on the segment pr (rounded), then moved by up to 4 ulps per coordinate;
/// magnitudes from 2^-4 to 2^10.
inline Workload<Orientation_2_case> near_collinear_2(std::size_t n, std::uint64_t seed) {
  using namespace internal_workloads;
  return generated<Orientation_2_case>("near-collinear", n, seed, [](std::mt19937_64& g, std::size_t) {
    const double scale = std::ldexp(1.0, small_int(g, -4, 10));
    const double px = uniform(g, -scale, scale), py = uniform(g, -scale, scale);
    const double rx = uniform(g, -scale, scale), ry = uniform(g, -scale, scale);
    const double t = uniform(g, -0.5, 1.5);
    const double qx = moved_by_ulps(px + t * (rx - px), small_int(g, -4, 4));
    const double qy = moved_by_ulps(py + t * (ry - py), small_int(g, -4, 4));
    return Orientation_2_case{px, py, qx, qy, rx, ry};
  });
}

/// Near-collinear cases scaled by 2^e, e in [-700, 700] (the exact sign is
/// scale-invariant): tests underflow, overflow and the filters' range guards.
/// One case in four also scales r by a further 2^e2, e2 in [-300, 300]
/// (coordinates stay below 2^1011: finite).
inline Workload<Orientation_2_case> extreme_magnitudes_2(std::size_t n, std::uint64_t seed) {
  using namespace internal_workloads;
  return changed(near_collinear_2(n, seed ^ 0x9e3779b97f4a7c15ULL), "extreme-magnitudes", seed,
                 [](std::mt19937_64& g, Orientation_2_case& c) {
                   const int e = small_int(g, -700, 700);
                   for (double* v : {&c.px, &c.py, &c.qx, &c.qy, &c.rx, &c.ry}) *v = std::ldexp(*v, e);
                   if (g() % 4 == 0) {
                     const int e2 = small_int(g, -300, 300);
                     c.rx = std::ldexp(c.rx, e2);
                     c.ry = std::ldexp(c.ry, e2);
                   }
                 });
}

/// Exact degeneracies: repeated points, shared coordinates, points on lines
/// through integer coordinates, axis-parallel lines.
inline Workload<Orientation_2_case> degenerate_2(std::size_t n, std::uint64_t seed) {
  using namespace internal_workloads;
  return generated<Orientation_2_case>("degenerate", n, seed, [](std::mt19937_64& g, std::size_t i) {
    const double px = small_int(g, -1000, 1000), py = small_int(g, -1000, 1000);
    const double dx = small_int(g, -50, 50), dy = small_int(g, -50, 50);
    const int a = small_int(g, -20, 20), b = small_int(g, -20, 20);
    switch (i % 4) {
      case 0: return Orientation_2_case{px, py, px + a * dx, py + a * dy, px + b * dx, py + b * dy};
      case 1: return Orientation_2_case{px, py, px, py, px + dx, py + dy};                      // p == q
      case 2: return Orientation_2_case{px, py, px + a, py, px + b, py};                        // horizontal
      default: return Orientation_2_case{px / 8, py / 8, px / 8, py / 8 + a, px / 8, py / 8 + b};  // vertical
    }
  });
}

/// Uniform points in [-1, 1]^3.
inline Workload<Orientation_3_case> uniform_3(std::size_t n, std::uint64_t seed) {
  return internal_workloads::generated<Orientation_3_case>("uniform", n, seed, [](std::mt19937_64& g, std::size_t) {
    Orientation_3_case c{};
    for (double& v : c.c) v = internal_workloads::uniform(g, -1, 1);
    return c;
  });
}

/// s = p + a (q - p) + b (r - p) rounded, then moved by up to 4 ulps per coordinate.
inline Workload<Orientation_3_case> near_coplanar_3(std::size_t n, std::uint64_t seed) {
  using namespace internal_workloads;
  return generated<Orientation_3_case>("near-coplanar", n, seed, [](std::mt19937_64& g, std::size_t) {
    const double scale = std::ldexp(1.0, small_int(g, -4, 10));
    Orientation_3_case c{};
    for (int k = 0; k < 9; ++k) c.c[k] = uniform(g, -scale, scale);
    const double a = uniform(g, -0.5, 1.5), b = uniform(g, -0.5, 1.5);
    for (int d = 0; d < 3; ++d) {
      const double v = c.c[d] + a * (c.c[3 + d] - c.c[d]) + b * (c.c[6 + d] - c.c[d]);
      c.c[9 + d] = moved_by_ulps(v, small_int(g, -4, 4));
    }
    return c;
  });
}

/// Near-coplanar cases scaled by 2^e, e in [-1000, 1000].
inline Workload<Orientation_3_case> extreme_magnitudes_3(std::size_t n, std::uint64_t seed) {
  using namespace internal_workloads;
  return changed(near_coplanar_3(n, seed ^ 0x9e3779b97f4a7c15ULL), "extreme-magnitudes", seed,
                 [](std::mt19937_64& g, Orientation_3_case& c) {
                   const int e = small_int(g, -1000, 1000);
                   for (double& v : c.c) v = std::ldexp(v, e);
                 });
}

/// Exact degeneracies in space: repeated points, integer coplanar points,
/// axis-parallel planes.
inline Workload<Orientation_3_case> degenerate_3(std::size_t n, std::uint64_t seed) {
  using namespace internal_workloads;
  return generated<Orientation_3_case>("degenerate", n, seed, [](std::mt19937_64& g, std::size_t i) {
    Orientation_3_case c{};
    for (int k = 0; k < 9; ++k) c.c[k] = small_int(g, -1000, 1000);
    const int a = small_int(g, -20, 20), b = small_int(g, -20, 20);
    switch (i % 3) {
      case 0:  // s integer combination of p, q, r: coplanar
        for (int d = 0; d < 3; ++d)
          c.c[9 + d] = c.c[d] + a * (c.c[3 + d] - c.c[d]) + b * (c.c[6 + d] - c.c[d]);
        break;
      case 1:  // s == q
        for (int d = 0; d < 3; ++d) c.c[9 + d] = c.c[3 + d];
        break;
      default:  // all on the plane z = const
        for (int k = 2; k < 12; k += 3) c.c[k] = c.c[2];
        c.c[9] = a, c.c[10] = b;
    }
    return c;
  });
}

/// The generators of the standard workloads, in their order; the k-th
/// draws its cases from seed + k (so one family alone, as a sweep's task
/// makes it, has the cases it has among all).
inline constexpr std::array standard_workload_makers_2{&uniform_2, &near_collinear_2, &extreme_magnitudes_2,
                                                       &degenerate_2};
inline constexpr std::array standard_workload_makers_3{&uniform_3, &near_coplanar_3, &extreme_magnitudes_3,
                                                       &degenerate_3};

namespace internal {
template <class Case, std::size_t N>
std::vector<Workload<Case>> make_workloads(const std::array<Workload<Case> (*)(std::size_t, std::uint64_t), N>& makers,
                                           std::size_t n, std::uint64_t seed) {
  std::vector<Workload<Case>> r;
  for (std::size_t k = 0; k < N; ++k) r.push_back(makers[k](n, seed + k));
  return r;
}
}  // namespace internal

/// The standard orientation_2 workloads with n cases each (grids excluded).
inline std::vector<Workload<Orientation_2_case>> standard_workloads_2(std::size_t n, std::uint64_t seed = 1) {
  return internal::make_workloads(standard_workload_makers_2, n, seed);
}
/// The standard orientation_3 workloads with n cases each.
inline std::vector<Workload<Orientation_3_case>> standard_workloads_3(std::size_t n, std::uint64_t seed = 11) {
  return internal::make_workloads(standard_workload_makers_3, n, seed);
}

}  // namespace relgeo::analysis
