// tools/relgeo/experiment/hull_inputs.cpp
#include "experiment/hull_inputs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "commands/hull/facade.h"
#include "relgeo/error/convex_polygon.h"
#include "relgeo/error/hull_error.h"

namespace relgeo::tool {

namespace {

using P = Point_2<double>;

/// Uniform double in [lo, hi) from 53 random bits.
double uniform(std::mt19937_64& g, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(g() >> 11) * 0x1p-53);
}
int small_int(std::mt19937_64& g, int lo, int hi) {
  return lo + static_cast<int>(g() % static_cast<std::uint64_t>(hi - lo + 1));
}
/// v moved by k ulps.
double ulps(double v, int k) {
  const double dir = k > 0 ? std::numeric_limits<double>::infinity()
                           : -std::numeric_limits<double>::infinity();
  for (int i = 0; i < std::abs(k); ++i) v = std::nextafter(v, dir);
  return v;
}
/// Fisher-Yates with the generator's integers (std::shuffle's use of the
/// generator is implementation-defined).
void shuffle(std::vector<P>& v, std::mt19937_64& g) {
  for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[g() % i]);
}

}  // namespace

Hull_input classroom_a1_input() {
  return {"classroom-a1",
          "classroom example A1 of Kettner et al. (SPEC 3.1), 9 points in insertion order", 0,
          classroom_example_a1()};
}

Hull_input kettner_construction_input(Kettner_failure failure, std::uint64_t base_seed,
                                      std::size_t max_attempts) {
  const char* what = failure == Kettner_failure::lost_point   ? "lost"
                     : failure == Kettner_failure::non_convex ? "nonconvex"
                                                              : "loop";
  Hull_input in{std::string("kettner-") + what, "", 0, {}};
  const std::vector<P> outer = {{8, 4}, {4, 9}, {15, 27}, {26, 25}, {19, 11}};
  for (std::size_t attempt = 0; attempt < max_attempts; ++attempt) {
    const std::uint64_t seed = base_seed + attempt;
    std::mt19937_64 g(seed);
    std::vector<P> pts;
    for (int i = 0; i < 4; ++i) {
      const double t = i == 3 ? uniform(g, 0, 0.05) : uniform(g, 0.2, 1.0);
      const double v = 0.5 + t * 23.5;
      const double x = ulps(v, small_int(g, -8, 8));
      const double y = ulps(v, small_int(g, -8, 8));
      pts.push_back({x, y});
    }
    pts.insert(pts.end(), outer.begin(), outer.end());
    const Hull_run r = run_hull("graham-incremental", "double", pts);
    const bool ok = r.status == Hull_status::ok;
    bool hit = false;
    if (failure == Kettner_failure::non_termination) {
      hit = !ok;
    } else if (ok) {
      const bool convex = is_ccw_strictly_convex_polygon(points_at(pts, r.indices));
      if (failure == Kettner_failure::non_convex) hit = !convex;
      else hit = convex && r.indices != run_hull("monotone-chain", "filtered", pts).indices;
    }
    if (!hit) continue;
    in.seed = seed;
    in.points = std::move(pts);
    in.description = std::string("Kettner et al.'s construction (4 points on a segment + ulps, then "
                                 "A1's outer points), first seed >= ") +
                     std::to_string(base_seed) + " where graham-incremental/double " +
                     (failure == Kettner_failure::lost_point   ? "loses an extreme point"
                      : failure == Kettner_failure::non_convex ? "returns a non-convex hull"
                                                               : "does not terminate") +
                     ": seed " + std::to_string(seed);
    return in;
  }
  in.description = "Kettner et al.'s construction: no failure found";
  return in;
}

Hull_input line_ulps_input(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  Hull_input in{"line-ulps",
                std::to_string(n) + " points on the segment (0.5,0.5)-(24.25,17.3), rounded, +-4 ulps per coordinate",
                seed, {}};
  in.points.reserve(n);
  const double ax = 0.5, ay = 0.5, bx = 24.25, by = 17.3;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = uniform(g, 0, 1);
    const double x = ax + t * (bx - ax), y = ay + t * (by - ay);
    in.points.push_back({ulps(x, small_int(g, -4, 4)), ulps(y, small_int(g, -4, 4))});
  }
  return in;
}

Hull_input circle_input(std::size_t n, int centre_exponent, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  const std::string e = std::to_string(centre_exponent);
  Hull_input in{"circle-2^" + e,
                std::to_string(n) + " points on the circle of radius 1 centred at (2^" + e + ", 2^" + e +
                    "), rounded to double",
                seed, {}};
  in.points.reserve(n);
  const double c = std::ldexp(1.0, centre_exponent);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = uniform(g, -1, 1);
    const double d = 1 + t * t;
    double x = (1 - t * t) / d;
    const double y = 2 * t / d;
    if (i % 2) x = -x;
    in.points.push_back({c + x, c + y});
  }
  shuffle(in.points, g);
  return in;
}

Hull_input clustered_input(std::size_t n, std::size_t clusters, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  Hull_input in{"clustered",
                std::to_string(n) + " points: copies of " + std::to_string(clusters) +
                    " random points, half exact duplicates, half moved by +-2 ulps",
                seed, {}};
  std::vector<P> base;
  for (std::size_t i = 0; i < clusters; ++i) base.push_back({uniform(g, 0, 1), uniform(g, 0, 1)});
  in.points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    P p = base[i % clusters];  // every cluster gets points
    if (g() % 2) p = {ulps(p.x, small_int(g, -2, 2)), ulps(p.y, small_int(g, -2, 2))};
    in.points.push_back(p);
  }
  shuffle(in.points, g);
  return in;
}

Hull_input large_range_input(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  Hull_input in{"large-range",
                std::to_string(n / 2) + " points (x, 0.7x), |x| <= 1e12, and " +
                    std::to_string(n - n / 2) + " points in [-1e-3, 1e-3]^2",
                seed, {}};
  in.points.reserve(n);
  for (std::size_t i = 0; i < n / 2; ++i) {
    const double x = uniform(g, -1e12, 1e12);
    in.points.push_back({x, 0.7 * x});
  }
  for (std::size_t i = n / 2; i < n; ++i) in.points.push_back({uniform(g, -1e-3, 1e-3), uniform(g, -1e-3, 1e-3)});
  shuffle(in.points, g);
  return in;
}

}  // namespace relgeo::tool
