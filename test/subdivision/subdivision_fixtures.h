// test/subdivision/subdivision_fixtures.h — extra meshes and helpers for the
// subdivision suites.
#pragma once

#include <cmath>
#include <vector>

#include "mesh/mesh_fixtures.h"
#include "relgeo/subdivision.h"

namespace relgeo_test {

/// The rule sets the suites run Loop subdivision under: Hoppe et al.'s
/// creases (the default), Warren's vertex weights, Biermann, Levin and
/// Zorin's creases.
inline const relgeo::Loop_options hoppe{}, warren{.vertex_weights = relgeo::Loop_vertex_weights::warren},
    blz{.crease_rules = relgeo::Loop_crease_rules::biermann_levin_zorin};

/// A disk around vertex 0 of valence n: ring 1 (vertices 1..n, interior), ring
/// 2 (n + 1 .. 2n, the boundary), 3n faces. Vertex 0 is smooth; with
/// creases_at = {0, k}, the edges (0, 1) and (0, 1 + k) are tagged creases, so
/// vertex 0 is a crease vertex with sectors of k and n - k faces whose ring-1
/// vertices are not special (darts or smooth).
inline Mesh_d disk(int n, int crease_k = 0) {
  Mesh_d m;
  const double pi = std::acos(-1.0);
  m.vertices.push_back({0.05, -0.03, 0.2});
  for (int i = 0; i < n; ++i) {
    const double a = 2 * pi * i / n;
    m.vertices.push_back({std::cos(a), std::sin(a), 0.1 * std::sin(3.0 * i + 1)});
  }
  for (int i = 0; i < n; ++i) {
    const double a = 2 * pi * (i + 0.5) / n;
    m.vertices.push_back({2 * std::cos(a), 2 * std::sin(a), 0.2 * std::cos(2.0 * i)});
  }
  for (int i = 0; i < n; ++i) {
    const Index a = Index(1 + i), b = Index(1 + (i + 1) % n), o = Index(1 + n + i);
    m.faces.push_back({0, a, b});
    m.faces.push_back({a, o, b});
    m.faces.push_back({b, o, Index(1 + n + (i + 1) % n)});
  }
  if (crease_k > 0) {
    m.tags.add_crease(0, 1);
    m.tags.add_crease(0, Index(1 + crease_k));
  }
  return m;
}

/// Open fan: vertex 0 with k faces in a half disk (boundary vertex of sector
/// size k), ring vertices 1..k+1.
inline Mesh_d half_fan(int k) {
  Mesh_d m;
  const double pi = std::acos(-1.0);
  m.vertices.push_back({0.02, 0.01, 0.1});
  for (int i = 0; i <= k; ++i) {
    const double a = pi * i / k;
    m.vertices.push_back({std::cos(a), std::sin(a), 0.15 * std::cos(2.0 * i + 0.5)});
  }
  for (int i = 0; i < k; ++i) m.faces.push_back({0, Index(1 + i), Index(2 + i)});
  return m;
}

}  // namespace relgeo_test
