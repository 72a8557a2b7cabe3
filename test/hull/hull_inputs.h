// test/hull/hull_inputs.h — inputs for the hull suites: the classroom example
// A1 and deterministic generators of small near-degenerate point sets.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/kernel/point.h"

namespace relgeo::test {

using P2 = Point_2<double>;

/// SPEC Sec. 3.1, in insertion order; p4 (index 3) is the extreme point naive
/// graham_incremental loses.
inline std::vector<P2> classroom_a1() {
  return {{7.3000000000000194, 7.3000000000000167}, {24.000000000000068, 24.000000000000071},
          {24.00000000000005, 24.000000000000053},  {0.50000000000001621, 0.50000000000001243},
          {8, 4}, {4, 9}, {15, 27}, {26, 25}, {19, 11}};
}
/// Its exact hull: CCW from the lexicographically smallest vertex.
inline std::vector<std::size_t> classroom_a1_hull() { return {3, 4, 8, 7, 6, 5}; }

/// Inputs on which naive graham_incremental returns the vertex set of the
/// exact hull in a wrong cyclic order (found by search over Kettner et al.'s
/// construction and over points on a segment with ulp noise): an outside
/// point inserted at an edge it only seems to see. Order of insertion as
/// listed.
inline std::vector<std::vector<P2>> wrong_order_inputs() {
  return {
      {{6.4601930396442695, 6.4601930396442686}, {5.5303485778333634, 5.5303485778333661}, {26, 25},
       {4.4404620157362347, 4.4404620157362311}, {6.4601930396442686, 6.4601930396442668}, {15, 27}, {8, 4},
       {6.5294418065642024, 6.5294418065641961}, {4, 9}, {19, 11}},
      {{6.165527609355415, -3.2442776418691448}, {-0.18832501890936984, 1.0164996808368429},
       {-5.0519317868367297, 4.4316705240834544}, {-4.8130477152436999, 4.2639287729204147},
       {-6.1495142367423279, 5.2023807726371603}, {-2.124273686889921, 2.3759014088936641},
       {-1.6163781185574828, 2.019262762072652}, {0.46328061647106894, 0.55894941548206534},
       {0.99477831696503061, 0.18573761267977409}, {0.46328061647106911, 0.55894941548206567},
       {-0.12667673488180595, 0.97321093810058634}, {2.6989733563405593, 6.7797715882814629}},
      {{-0.44534033442928356, 0.81593909871110915}, {0.12503797500278999, -0.16709761477588445},
       {-3.4286782498300719, 5.9576681074752296}, {-0.44534033442928345, 0.81593909871110881},
       {-1.853829578756379, 3.2434448695805047}, {-4.4971006685886028, -9.8256380978307174},
       {0.53685548495544355, -0.87685765446488662}, {-3.0989849617254777, 5.389447680720628},
       {-2.1247672266274678, 3.7104010117035915}, {-0.5410858780185368, -8.8859478276888275}},
  };
}

using analysis::moved_by_ulps;

/// Small near-degenerate point sets, one of four kinds chosen by `kind`:
/// 0 points on a line (rounded) moved by a few ulps, 1 points near a circle
/// far from the origin, 2 clustered duplicates with ulp noise, 3 a few random
/// points plus many on one of their edges (Kettner et al.'s failure pattern).
inline std::vector<P2> near_degenerate_points(std::uint64_t seed, int kind) {
  std::mt19937_64 g(seed);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (static_cast<double>(g() >> 11) * 0x1p-53); };
  auto ulps = [&](int m) { return static_cast<int>(g() % (2 * m + 1)) - m; };
  const int n = 8 + static_cast<int>(g() % 40);
  std::vector<P2> pts;
  switch (kind % 4) {
    case 0: {
      const P2 a{uniform(-10, 10), uniform(-10, 10)}, b{uniform(-10, 10), uniform(-10, 10)};
      for (int i = 0; i < n; ++i) {
        const double t = uniform(-0.2, 1.2);
        pts.push_back({moved_by_ulps(a.x + t * (b.x - a.x), ulps(3)), moved_by_ulps(a.y + t * (b.y - a.y), ulps(3))});
      }
      break;
    }
    case 1: {
      const double c = std::ldexp(1.0, static_cast<int>(g() % 30));
      for (int i = 0; i < n; ++i) {
        const double t = uniform(0, 6.283185307179586);
        pts.push_back({c + std::cos(t), c + std::sin(t)});
      }
      break;
    }
    case 2: {
      std::vector<P2> centres;
      for (int i = 0; i < 3; ++i) centres.push_back({uniform(-1, 1), uniform(-1, 1)});
      for (int i = 0; i < n; ++i) {
        const P2 c = centres[g() % 3];
        pts.push_back({moved_by_ulps(c.x, ulps(2)), moved_by_ulps(c.y, ulps(2))});
      }
      break;
    }
    default: {
      for (int i = 0; i < 4; ++i) pts.push_back({uniform(0, 30), uniform(0, 30)});
      for (int i = 4; i < n; ++i) {
        const P2 a = pts[0], b = pts[1 + g() % 3];
        const double t = uniform(0, 1);
        pts.push_back({moved_by_ulps(a.x + t * (b.x - a.x), ulps(2)), moved_by_ulps(a.y + t * (b.y - a.y), ulps(2))});
      }
    }
  }
  return pts;
}

/// Random points with integer-free coordinates in [-1, 1]^2.
inline std::vector<P2> uniform_points(std::uint64_t seed, int n) {
  std::mt19937_64 g(seed);
  std::vector<P2> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back({static_cast<double>(g() >> 11) * 0x1p-52 - 1, static_cast<double>(g() >> 11) * 0x1p-52 - 1});
  return pts;
}

/// The points converted to kernel K's point type.
template <class K>
std::vector<typename K::Point_2> to_kernel(const std::vector<P2>& pts, const K& k = K{}) {
  std::vector<typename K::Point_2> out;
  out.reserve(pts.size());
  for (const auto& p : pts) out.push_back(k.construct_point_2_object()(p.x, p.y));
  return out;
}

}  // namespace relgeo::test
