// Surfaces and curves the surface tests share: random B-spline/NURBS data
// (degrees, knots with interior multiplicities, weights) and the exact
// rational quarter circle.
#pragma once

#include <algorithm>
#include <random>
#include <vector>

#include "relgeo/surfaces/nurbs_curve.h"
#include "relgeo/surfaces/nurbs_surface.h"

namespace relgeo_test {

/// A clamped knot vector for `count` control points of degree p on [a, b]:
/// random interior knots, some repeated (multiplicity up to p), all dyadic
/// (exact in every number type).
inline std::vector<double> random_knots(std::mt19937_64& rng, int p, std::size_t count, double a = 0, double b = 1) {
  const std::size_t interior = count - static_cast<std::size_t>(p) - 1;
  std::vector<int> cells(255);
  for (int i = 0; i < 255; ++i) cells[i] = i + 1;
  std::shuffle(cells.begin(), cells.end(), rng);  // distinct knot values
  std::vector<double> inner;
  for (std::size_t next = 0; inner.size() < interior; ++next) {
    const double k = a + (b - a) * cells[next % cells.size()] / 256.0;
    const int mult = std::uniform_int_distribution<int>(1, std::max(1, std::min(p, 2)))(rng);
    for (int m = 0; m < mult && inner.size() < interior; ++m) inner.push_back(k);
  }
  std::sort(inner.begin(), inner.end());
  std::vector<double> U(static_cast<std::size_t>(p) + 1, a);
  U.insert(U.end(), inner.begin(), inner.end());
  U.insert(U.end(), static_cast<std::size_t>(p) + 1, b);
  return U;
}

/// A random B-spline surface (NURBS when `rational`) with coordinates and
/// weights on a dyadic grid.
inline relgeo::Nurbs_surface<double> random_surface(std::mt19937_64& rng, int p, int q, std::size_t nu,
                                                    std::size_t nv, bool rational) {
  std::uniform_int_distribution<int> c(-512, 512), w(64, 512);
  std::vector<relgeo::Point_3<double>> P;
  std::vector<double> W;
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      P.push_back({static_cast<double>(i) + c(rng) / 1024.0, static_cast<double>(j) + c(rng) / 1024.0, c(rng) / 256.0});
      if (rational) W.push_back(w(rng) / 128.0);
    }
  return relgeo::Nurbs_surface<double>(p, q, random_knots(rng, p, nu), random_knots(rng, q, nv, -1, 2), nu, nv,
                                       std::move(P), std::move(W));
}

template <int D>
relgeo::Nurbs_curve<double, D> random_curve(std::mt19937_64& rng, int p, std::size_t n, bool rational) {
  std::uniform_int_distribution<int> c(-512, 512), w(64, 512);
  using Curve = relgeo::Nurbs_curve<double, D>;
  std::vector<typename Curve::Point> P;
  std::vector<double> W;
  for (std::size_t i = 0; i < n; ++i) {
    relgeo::Vector_nd<double, D> v;
    for (int k = 0; k < D; ++k) v[k] = c(rng) / 256.0;
    P.push_back(relgeo::internal::to_point(v));
    if (rational) W.push_back(w(rng) / 128.0);
  }
  return Curve(p, random_knots(rng, p, n, 0, 3), std::move(P), std::move(W));
}

/// The quarter unit circle from (1,0) to (0,1) as a rational quadratic with
/// rational weights (1, 1, 2): x = (1-t^2)/(1+t^2), y = 2t/(1+t^2).
inline relgeo::Nurbs_curve_2<double> quarter_circle() {
  return relgeo::Nurbs_curve_2<double>(2, {0, 0, 0, 1, 1, 1}, {{1, 0}, {1, 1}, {0, 1}}, {1, 1, 2});
}

/// A quarter cylinder x^2 + y^2 = 1, 0 <= z <= 2 (u: around, v: along z),
/// with rational weights: exact under mpq_class.
inline relgeo::Nurbs_surface<double> quarter_cylinder() {
  return relgeo::Nurbs_surface<double>(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, 3, 2,
                                       {{1, 0, 0}, {1, 0, 2}, {1, 1, 0}, {1, 1, 2}, {0, 1, 0}, {0, 1, 2}},
                                       {1, 1, 1, 1, 2, 2});
}

}  // namespace relgeo_test
