// relgeo/curves/test_contours.h — contours for tests, benchmarks, the tool
// and the manual: well-formed circle-like cubic chains and polygons, and the
// classic failures (a self-intersecting curve, adjacent curves folding back,
// crossing non-adjacent curves, a pinch below the uncertainty).
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/curves/contour.h"

namespace relgeo {

/// \brief A circle of radius r around c as a chain of M cubic Bezier arcs
/// (the standard G1 approximation: inner control points at distance
/// (4/3) tan(pi / (2M)) r along the end tangents). End points are computed
/// once and shared, so the contour is closed exactly. Counterclockwise.
/// \throws Invalid_input for M < 1 or r <= 0.
inline Bezier_contour circle_contour(std::size_t M, double r = 1.0, Point_2<double> c = {0.0, 0.0}) {
  if (M < 1) throw Invalid_input("circle_contour: M must be at least 1");
  if (!(r > 0)) throw Invalid_input("circle_contour: the radius must be positive");
  const double theta = 2 * std::numbers::pi / static_cast<double>(M);
  const double k = 4.0 / 3.0 * std::tan(theta / 4) * r;
  std::vector<Point_2<double>> chain;
  chain.reserve(3 * M);
  for (std::size_t m = 0; m < M; ++m) {
    const double a = theta * static_cast<double>(m), b = theta * static_cast<double>(m + 1);
    const Point_2<double> p{c.x + r * std::cos(a), c.y + r * std::sin(a)};
    const Point_2<double> q{c.x + r * std::cos(b), c.y + r * std::sin(b)};
    chain.push_back(p);
    chain.push_back({p.x - k * std::sin(a), p.y + k * std::cos(a)});
    chain.push_back({q.x + k * std::sin(b), q.y - k * std::cos(b)});
  }
  return Bezier_contour::from_chain(chain, 3);
}

/// A closed polygon v_0 .. v_{n-1} with every edge a straight Bezier curve of
/// degree `degree` (control points evenly spaced on the edge).
inline Bezier_contour polygon_contour(std::span<const Point_2<double>> vertices, std::size_t degree = 3) {
  if (vertices.empty()) throw Invalid_input("polygon_contour: no vertices", Error_code::empty_input);
  if (degree < 1) throw Invalid_input("polygon_contour: degree must be at least 1");
  std::vector<Point_2<double>> chain;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Point_2<double>& a = vertices[i];
    const Point_2<double>& b = vertices[(i + 1) % vertices.size()];
    chain.push_back(a);
    for (std::size_t j = 1; j < degree; ++j) {
      const double t = static_cast<double>(j) / static_cast<double>(degree);
      chain.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  }
  return Bezier_contour::from_chain(chain, degree);
}

/// The circle contour (M >= 3) with curve 0 replaced by a cubic with a loop
/// between the same end points: its inner control points are swapped past
/// each other, so q contains opposite directions (condition 1 fails).
inline Bezier_contour looped_circle_contour(std::size_t M) {
  const Bezier_contour base = circle_contour(M);
  std::vector<std::vector<Point_2<double>>> curves;
  for (std::size_t m = 0; m < M; ++m) {
    const auto cp = base[m].control_points();
    curves.emplace_back(cp.begin(), cp.end());
  }
  auto& c = curves[0];
  const Point_2<double> a = c[0], b = c[3];
  const Point_2<double> d{b.x - a.x, b.y - a.y};
  const Point_2<double> nrm{-d.y, d.x};
  // classic loop: R1 far beyond R3, R2 far before R0, both pushed outward
  c[1] = {b.x + 1.5 * d.x - 0.8 * nrm.x, b.y + 1.5 * d.y - 0.8 * nrm.y};
  c[2] = {a.x - 1.5 * d.x - 0.8 * nrm.x, a.y - 1.5 * d.y - 0.8 * nrm.y};
  return Bezier_contour::from_curves(std::move(curves));
}

/// A contour whose curves 1 and 2 fold back on each other at their shared
/// point P = (1, 0): curve 1 arrives at P from the left, curve 2 leaves P to
/// the left along the same line, so the two curves touch along a segment
/// next to P (condition 2 fails).
inline Bezier_contour folded_contour() {
  std::vector<std::vector<Point_2<double>>> c = {
      {{0, -1}, {0.5, -1}, {1, -1}, {2, -1}},       // 0: bottom, to the right
      {{2, -1}, {2, -0.5}, {0.5, 0}, {1, 0}},       // 1: arrives at P = (1, 0) going right
      {{1, 0}, {0.5, 0}, {0.5, 0.5}, {0, 1}},       // 2: leaves P going left: folds back on 1
      {{0, 1}, {-0.5, 0.5}, {-0.5, -0.5}, {0, -1}}  // 3: closes
  };
  return Bezier_contour::from_curves(std::move(c));
}

/// A bow tie: the polygon (0,0) (1,1) (1,0) (0,1) with straight cubic edges;
/// edges 0 and 2 cross at (1/2, 1/2) (condition 3 fails, 1 and 2 hold).
inline Bezier_contour bow_tie_contour() {
  const std::vector<Point_2<double>> v = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  return polygon_contour(v, 3);
}

/// A thin rectangle (0,0) (1,0) (1,h) (0,h) with straight cubic edges: well
/// formed for every h > 0, but its margins are about h / 3: below a stated
/// uncertainty larger than that, it is not certified.
inline Bezier_contour thin_rectangle_contour(double h) {
  const std::vector<Point_2<double>> v = {{0, 0}, {1, 0}, {1, h}, {0, h}};
  return polygon_contour(v, 3);
}

}  // namespace relgeo
