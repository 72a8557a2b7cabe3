// relgeo/analysis/triangle_pair_workloads.h — families of triangle pairs for
// the triangle-triangle intersection tests, benchmarks and experiment.
//
// Deterministic for a seed. The touching and coplanar families are exact:
// their points are small dyadic combinations of a few base points (few
// significand bits), so a vertex put on a face, an edge or a plane is exactly
// there and the zeros are exact zeros.
//  * random         two triangles with vertices uniform in [-1, 1]^3;
//  * near           a triangle and one whose vertex lies a few ulps off the
//                   first's plane (or on it), the rest crossing or not;
//  * touching       a shared vertex, a shared edge, a vertex on the other's
//                   face or edge, an edge through the other's edge;
//  * coplanar       both in one plane: overlapping, nested, sharing edges or
//                   vertices, disjoint;
//  * grid           vertices on the integer grid {-2..2}^3: every exact
//                   degeneracy at once (two vertices on the other's plane,
//                   an edge in it, shared and collinear edges), unplanned.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/kernel/filtered_exact_kernel.h"

namespace relgeo::analysis {

using Triangle_coordinates = std::array<std::array<double, 3>, 3>;

struct Triangle_pair {
  Triangle_coordinates a, b;
};

struct Triangle_pair_workload {
  std::string name;
  std::vector<Triangle_pair> pairs;
};

namespace internal_workloads {

using Vec3 = std::array<double, 3>;

inline Vec3 uniform_point(std::mt19937_64& g) { return {uniform(g, -1, 1), uniform(g, -1, 1), uniform(g, -1, 1)}; }

/// Integers in [-2^bits, 2^bits) times 2^-bits.
inline Vec3 dyadic_vec(std::mt19937_64& g, int bits) {
  const auto c = [&] {
    return std::ldexp(static_cast<double>(static_cast<std::int64_t>(g() >> (63 - bits)) - (std::int64_t{1} << bits)),
                      -bits);
  };
  return {c(), c(), c()};
}

/// o + s u + t v (exact for the small dyadic values used here).
inline Vec3 combination(const Vec3& o, const Vec3& u, const Vec3& v, double s, double t) {
  return {o[0] + s * u[0] + t * v[0], o[1] + s * u[1] + t * v[1], o[2] + s * u[2] + t * v[2]};
}

/// A weight in {-2, -1.5, ..., 2} (multiples of 1/8 for finer ones).
inline double weight(std::mt19937_64& g, int eighths = 16) {
  return small_int(g, -eighths, eighths) / 8.0;
}

/// Whether three points are collinear (exactly): such a triangle is not
/// an input of the intersection test.
inline bool is_degenerate(const Triangle_coordinates& t) {
  const Filtered_exact_kernel k;
  const auto p = k.construct_point_3_object();
  return certainly(k.coplanar_orientation_3_object()(p(t[0][0], t[0][1], t[0][2]), p(t[1][0], t[1][1], t[1][2]),
                                                     p(t[2][0], t[2][1], t[2][2])),
                   Certified_sign::zero);
}

}  // namespace internal_workloads

/// The five families with `n` pairs each.
inline std::vector<Triangle_pair_workload> triangle_pair_workloads(std::size_t n, std::uint64_t seed = 1) {
  using namespace internal_workloads;
  std::vector<Triangle_pair_workload> out;
  {
    Triangle_pair_workload w{"random", {}};
    std::mt19937_64 g(seed);
    while (w.pairs.size() < n)
      w.pairs.push_back({{uniform_point(g), uniform_point(g), uniform_point(g)},
                         {uniform_point(g), uniform_point(g), uniform_point(g)}});
    out.push_back(std::move(w));
  }
  {
    Triangle_pair_workload w{"near", {}};
    std::mt19937_64 g(seed + 1);
    while (w.pairs.size() < n) {
      // b0 on a's plane (a dyadic combination of a's points), then moved by
      // a few ulps or not; b1, b2 random (across the plane or not).
      const Vec3 o = dyadic_vec(g, 20), u = dyadic_vec(g, 20), v = dyadic_vec(g, 20);
      const Triangle_coordinates a{o, combination(o, u, v, 1, 0), combination(o, u, v, 0, 1)};
      Vec3 b0 = combination(o, u, v, weight(g, 8), weight(g, 8));
      const int k = small_int(g, -3, 3), axis = small_int(g, 0, 2);
      b0[axis] = moved_by_ulps(b0[axis], k);
      const Triangle_pair pair{a, {b0, uniform_point(g), uniform_point(g)}};
      if (!is_degenerate(pair.a) && !is_degenerate(pair.b)) w.pairs.push_back(pair);
    }
    out.push_back(std::move(w));
  }
  {
    Triangle_pair_workload w{"touching", {}};
    std::mt19937_64 g(seed + 2);
    for (std::size_t i = 0; w.pairs.size() < n; ++i) {
      const Vec3 o = dyadic_vec(g, 20), u = dyadic_vec(g, 20), v = dyadic_vec(g, 20), n3 = dyadic_vec(g, 20);
      const Triangle_coordinates a{o, combination(o, u, v, 1, 0), combination(o, u, v, 0, 1)};
      const auto off = [&] {  // a point off a's plane (almost surely)
        return combination(combination(o, u, v, weight(g), weight(g)), n3, n3, weight(g), 0);
      };
      Triangle_coordinates b;
      switch (i % 5) {
        case 0: b = {a[small_int(g, 0, 2)], off(), off()}; break;            // shared vertex
        case 1: b = {a[0], a[1], off()}; break;                              // shared edge
        case 2: {                                                            // vertex on a's face (inside or not)
          const double s = small_int(g, 0, 8) / 8.0, t = small_int(g, 0, 8 - static_cast<int>(8 * s)) / 8.0;
          b = {combination(o, u, v, s, t), off(), off()};
          break;
        }
        case 3: b = {combination(o, u, v, small_int(g, 0, 8) / 8.0, 0), off(), off()}; break;  // on an edge line
        default: {  // an edge of b through a's edge 0 (crossing the line of a's edge at a dyadic point)
          const Vec3 x = combination(o, u, v, small_int(g, 1, 7) / 8.0, 0);
          const Vec3 d = dyadic_vec(g, 4);
          b = {combination(x, d, d, -1, 0), combination(x, d, d, 1, 0), off()};
        }
      }
      if (!is_degenerate(a) && !is_degenerate(b)) w.pairs.push_back({a, b});
    }
    out.push_back(std::move(w));
  }
  {
    Triangle_pair_workload w{"coplanar", {}};
    std::mt19937_64 g(seed + 3);
    for (std::size_t i = 0; w.pairs.size() < n; ++i) {
      const Vec3 o = dyadic_vec(g, 20), u = dyadic_vec(g, 20), v = dyadic_vec(g, 20);
      const auto in_plane = [&] { return combination(o, u, v, weight(g), weight(g)); };
      const Triangle_coordinates a{o, combination(o, u, v, 1, 0), combination(o, u, v, 0, 1)};
      Triangle_coordinates b;
      switch (i % 4) {
        case 0: b = {in_plane(), in_plane(), in_plane()}; break;
        case 1: b = {a[0], a[1], in_plane()}; break;  // sharing an edge
        case 2: b = {a[small_int(g, 0, 2)], in_plane(), in_plane()}; break;
        default: b = {a[1], a[2], a[0]}; break;  // identical, rotated
      }
      if (!is_degenerate(a) && !is_degenerate(b)) w.pairs.push_back({a, b});
    }
    out.push_back(std::move(w));
  }
  {
    Triangle_pair_workload w{"grid", {}};
    std::mt19937_64 g(seed + 4);
    const auto grid_point = [&] {
      return Vec3{double(small_int(g, -2, 2)), double(small_int(g, -2, 2)), double(small_int(g, -2, 2))};
    };
    while (w.pairs.size() < n) {
      const Triangle_coordinates a{grid_point(), grid_point(), grid_point()}, b{grid_point(), grid_point(), grid_point()};
      if (!is_degenerate(a) && !is_degenerate(b)) w.pairs.push_back({a, b});
    }
    out.push_back(std::move(w));
  }
  return out;
}

}  // namespace relgeo::analysis
