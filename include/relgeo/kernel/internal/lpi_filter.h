// relgeo/kernel/internal/lpi_filter.h — the two queries a Boolean asks most
// of an LPI point, in plain floating point with their magnitudes in closed
// form: its homogeneous coordinates (the first-stage cache of the point) and
// its orientation against the plane of three input points.
//
// Both produce Filtered_value's (filtered_value.h): the values evaluated
// exactly as the generic formulas of implicit_coordinates.h evaluate them,
// and for M (the magnitude of the invariant |v^ - v| <= gamma_k M) an upper
// bound computed from the largest coordinate differences instead of
// operation by operation; k counts the roundings of the longest path, as the
// generic evaluation would. With a = q - p, e = s - r, f = t - r, n = e x f,
// per-coordinate bounds |a_i| <= A, |e_i|, |f_i| <= E, |(r - p)_i| <= R:
//   n_i:   M <= 2 max(E^2, lambda),                    k = 4
//   W, lambda = n . a, n . (r - p):  M <= 3 max(M_n A, lambda), 3 max(M_n R, lambda),  k = 8
//   X_i = W p_i + lambda a_i:  M <= max(M_W |p_i|, lambda) + max(M_lambda |a_i|, lambda),  k = 11
// and for the orientation of (a, b, c, X) with g = b - a, h = c - a (|.| <= G),
// m = g x h and D_i = X_i - a_i W:
//   D_i:   M <= M_Xi + max(|a_i| M_W, lambda),  k = 12;   m_i: M <= 2 max(G^2, lambda), k = 4;
//   m . D: M <= 3 max(M_m max_i M_Di, lambda),  k = 19.
// Each bound is computed in a handful of roundings, fewer than k, so the
// margin of Filtered_value::error_bound covers them. About a tenth of the
// instructions of the operation-by-operation evaluation.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "relgeo/kernel/internal/filtered_value.h"
#include "relgeo/kernel/internal/implicit_coordinates.h"
#include "relgeo/kernel/point.h"

namespace relgeo::internal {

template <class T>
T max_abs(T a, T b, T c) {
  return std::max({std::abs(a), std::abs(b), std::abs(c)});
}

/// The LPI point of line (p, q) and plane (r, s, t) as Filtered_value's.
template <class T>
Homogeneous_3<Filtered_value<T>> lpi_filter(const Point_3<T>& p, const Point_3<T>& q, const Point_3<T>& r,
                                            const Point_3<T>& s, const Point_3<T>& t) {
  constexpr T lambda = std::numeric_limits<T>::min();
  const T ax = q.x - p.x, ay = q.y - p.y, az = q.z - p.z;
  const T ex = s.x - r.x, ey = s.y - r.y, ez = s.z - r.z;
  const T fx = t.x - r.x, fy = t.y - r.y, fz = t.z - r.z;
  const T gx = r.x - p.x, gy = r.y - p.y, gz = r.z - p.z;
  const T nx = ey * fz - ez * fy, ny = ez * fx - ex * fz, nz = ex * fy - ey * fx;
  const T w = (nx * ax + ny * ay) + nz * az;
  const T l = (nx * gx + ny * gy) + nz * gz;
  const T E = std::max(max_abs(ex, ey, ez), max_abs(fx, fy, fz));
  const T Mn = 2 * std::max(E * E, lambda);
  const T Mw = 3 * std::max(Mn * max_abs(ax, ay, az), lambda);
  const T Ml = 3 * std::max(Mn * max_abs(gx, gy, gz), lambda);
  const auto coordinate = [&](T pi, T ai) {
    return Filtered_value<T>(w * pi + l * ai,
                             std::max(Mw * std::abs(pi), lambda) + std::max(Ml * std::abs(ai), lambda), 11);
  };
  return {coordinate(p.x, ax), coordinate(p.y, ay), coordinate(p.z, az), Filtered_value<T>(w, Mw, 8), false};
}

/// orientation_3(a, b, c, x) of input points a, b, c and a point x given by
/// Filtered_value homogeneous coordinates (before the sign correction by W,
/// which the caller applies).
template <class T>
Filtered_value<T> orientation_3_filter(const Point_3<T>& a, const Point_3<T>& b, const Point_3<T>& c,
                                       const Homogeneous_3<Filtered_value<T>>& x) {
  constexpr T lambda = std::numeric_limits<T>::min();
  const T gx = b.x - a.x, gy = b.y - a.y, gz = b.z - a.z;
  const T hx = c.x - a.x, hy = c.y - a.y, hz = c.z - a.z;
  const T mx = gy * hz - gz * hy, my = gz * hx - gx * hz, mz = gx * hy - gy * hx;
  const T w = x.w.value;
  const T dx = x.x.value - a.x * w, dy = x.y.value - a.y * w, dz = x.z.value - a.z * w;
  const T G = std::max(max_abs(gx, gy, gz), max_abs(hx, hy, hz));
  const T Mm = 2 * std::max(G * G, lambda);
  const T Mw = x.w.magnitude;
  const T Md = std::max({x.x.magnitude + std::max(std::abs(a.x) * Mw, lambda),
                         x.y.magnitude + std::max(std::abs(a.y) * Mw, lambda),
                         x.z.magnitude + std::max(std::abs(a.z) * Mw, lambda)});
  const int kd = std::max({x.x.roundings, x.y.roundings, x.z.roundings, x.w.roundings + 1}) + 1;
  // orientation(a, b, c, x) = (g x h) . (x - a) = m . D / W.
  return Filtered_value<T>((mx * dx + my * dy) + mz * dz, 3 * std::max(Mm * Md, lambda), 4 + kd + 1 + 2);
}

}  // namespace relgeo::internal
