// test/subdivision/limit_test_support.h — helpers shared by the limit-surface
// evaluation and error-bound suites: parameter maps between a face and its
// descendants, dyadic sample grids, extra fixtures.
#pragma once

#include <array>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "subdivision/subdivision_fixtures.h"

namespace relgeo_test {

/// Parameters in face f of level 0 of the point (s, t) of its descendant g at
/// `level` (Loop_subdivider numbering: g's ancestor at level 0 is g / 4^level,
/// the base-4 digits of g are the child indices). Dyadic inputs give exact
/// doubles.
inline std::pair<double, double> ancestor_parameters(Index g, unsigned level, double s, double t) {
  for (unsigned l = 0; l < level; ++l, g /= 4) {
    switch (g % 4) {
      case 0: std::tie(s, t) = std::pair{s / 2, t / 2}; break;
      case 1: std::tie(s, t) = std::pair{1 - s / 2 - t / 2, s / 2}; break;
      case 2: std::tie(s, t) = std::pair{t / 2, 1 - s / 2 - t / 2}; break;
      default: std::tie(s, t) = std::pair{0.5 - t / 2, s / 2 + t / 2}; break;
    }
  }
  return {s, t};
}

/// The points (i / n, j / n), i + j <= n, n a power of two (exact doubles:
/// the evaluator takes parameters exactly and refuses u + v > 1).
inline std::vector<std::pair<double, double>> dyadic_grid(int n) {
  std::vector<std::pair<double, double>> g;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i + j <= n; ++i) g.push_back({double(i) / n, double(j) / n});
  return g;
}

/// disk(n) with the single edge (0, 1) tagged: vertices 0 and 1 are darts.
inline Mesh_d dart_disk(int n) {
  Mesh_d m = disk(n);
  m.tags.add_crease(0, 1);
  return m;
}

/// open_grid(n) with the heights 0.3 sin(2.5 x) sin(1.7 y): saddles and bumps.
inline Mesh_d wavy_grid(int n) {
  Mesh_d m = open_grid(n);
  for (auto& p : m.vertices) p.z = 0.3 * std::sin(2.5 * p.x) * std::sin(1.7 * p.y);
  return m;
}

/// A mesh with smooth extraordinary vertices of every valence 3..12 (one
/// bipyramid apex each), for loops over valences.
inline std::vector<std::pair<int, Mesh_d>> valence_meshes() {
  std::vector<std::pair<int, Mesh_d>> r;
  for (int n = 3; n <= 12; ++n) r.push_back({n, bipyramid(n)});
  return r;
}

}  // namespace relgeo_test
