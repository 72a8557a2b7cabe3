// relgeo/kernel/internal/implicit_coordinates.h — the one source of the
// arithmetic of implicit points: homogeneous coordinates of LPI and TPI
// points, and the orientation and comparison determinants on points given
// homogeneously. Every evaluation stage (error-bounded doubles, intervals,
// GMP integers, exact rationals) instantiates these templates.
//
// A point is (X, Y, Z, W) with W != 0, meaning (X/W, Y/W, Z/W); an input
// (explicit) point is (x, y, z, 1) (Attene, "Indirect predicates for
// geometric constructions", CAD 126, 2020, whose formulation this follows):
//  * LPI, the line through p, q crossing the plane through r, s, t:
//      a = q - p, n = (s - r) x (t - r),  W = n . a (degree 3),
//      lambda = n . (r - p) (degree 3),   (X, Y, Z) = W p + lambda a (degree 4);
//  * TPI, three planes through (a_i, b_i, c_i):
//      n_i = (b_i - a_i) x (c_i - a_i), d_i = n_i . a_i,
//      W = n_1 . (n_2 x n_3) (degree 6),
//      (X, Y, Z) = d_1 (n_2 x n_3) + d_2 (n_3 x n_1) + d_3 (n_1 x n_2) (degree 7).
// All are homogeneous polynomials in the input coordinates with integer
// coefficients, so scaling every input by a power of two scales each point's
// coordinates by a positive factor and keeps every sign below: the exact
// stages evaluate them on scaled inputs (filtered_predicate.h).
//
// Predicates multiply through by the W's and correct the sign by sign(W):
//  * orientation of four points, the first explicit (pivot a):
//      sign det[ X_i - a_x W_i, Y_i - a_y W_i, Z_i - a_z W_i ]_{i=2..4} * prod_i sign W_i
//    (the orientation_3 determinant of determinants.h with rows scaled by W_i);
//    with no explicit point, the 4x4 determinant of rows (W_i, X_i, Y_i, Z_i);
//  * in-plane orientation after dropping one axis: the same in 2D;
//  * comparison of one coordinate: sign(X_1 W_2 - X_2 W_1) * sign(W_1 W_2).
// Explicit points are marked (`unit`) so that no product by W = 1 is formed.
#pragma once

#include <array>
#include <cstddef>

#include "relgeo/kernel/point.h"
#include "relgeo/kernel/vector_3.h"

namespace relgeo::internal {

/// Homogeneous coordinates; `unit` when W is exactly 1 (an input point).
template <class NT>
struct Homogeneous_3 {
  NT x{}, y{}, z{}, w{};
  bool unit = false;

  const NT& operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
};

template <class NT>
Homogeneous_3<NT> explicit_coordinates(const Point_3<NT>& p) {
  return {p.x, p.y, p.z, NT(1), true};
}

/// The parts of the LPI point of the line through p, q and the plane
/// through r, s, t: the direction a = q - p, W and lambda (see above).
template <class NT>
struct Lpi_parts {
  Point_3<NT> a;
  NT w, lambda;
};
template <class NT>
Lpi_parts<NT> lpi_parts(const Point_3<NT>& p, const Point_3<NT>& q, const Point_3<NT>& r, const Point_3<NT>& s,
                        const Point_3<NT>& t) {
  const Point_3<NT> n = cross(difference(s, r), difference(t, r));
  // Each part built in place (q - p formed twice: cheaper than a copy).
  return {difference(q, p), dot(n, difference(q, p)), dot(n, difference(r, p))};
}

/// The LPI point of the line through p, q and the plane through r, s, t.
template <class NT>
Homogeneous_3<NT> lpi_coordinates(const Point_3<NT>& p, const Point_3<NT>& q, const Point_3<NT>& r,
                                  const Point_3<NT>& s, const Point_3<NT>& t) {
  const auto [a, w, lambda] = lpi_parts(p, q, r, s, t);
  return {NT(NT(w * p.x) + NT(lambda * a.x)), NT(NT(w * p.y) + NT(lambda * a.y)),
          NT(NT(w * p.z) + NT(lambda * a.z)), w, false};
}

/// The TPI point of the planes through (a[i], b[i], c[i]), i = 0, 1, 2.
template <class NT>
Homogeneous_3<NT> tpi_coordinates(const std::array<Point_3<NT>, 9>& v) {
  std::array<Point_3<NT>, 3> n;
  std::array<NT, 3> d;
  for (int i = 0; i < 3; ++i) {
    n[i] = cross(difference(v[3 * i + 1], v[3 * i]), difference(v[3 * i + 2], v[3 * i]));
    d[i] = dot(n[i], v[3 * i]);
  }
  const Point_3<NT> c23 = cross(n[1], n[2]), c31 = cross(n[2], n[0]), c12 = cross(n[0], n[1]);
  const NT w = dot(n[0], c23);
  const auto coordinate = [&](const NT& a, const NT& b, const NT& c) {
    return NT(NT(NT(d[0] * a) + NT(d[1] * b)) + NT(d[2] * c));
  };
  return {coordinate(c23.x, c31.x, c12.x), coordinate(c23.y, c31.y, c12.y), coordinate(c23.z, c31.z, c12.z), w,
          false};
}

/// h[axis] - c W (or h[axis] - c for an explicit point).
template <class NT>
NT relative_coordinate(const Homogeneous_3<NT>& h, int axis, const NT& c) {
  return h.unit ? NT(h[axis] - c) : NT(h[axis] - NT(c * h.w));
}

/// orientation_3(a, b, c, d) with a explicit: the sign of the determinant
/// (before the W correction, which the caller applies).
template <class NT>
NT orientation_3_with_pivot(const Point_3<NT>& a, const Homogeneous_3<NT>& b, const Homogeneous_3<NT>& c,
                            const Homogeneous_3<NT>& d) {
  const NT a00 = relative_coordinate(b, 0, a.x), a01 = relative_coordinate(c, 0, a.x),
           a02 = relative_coordinate(d, 0, a.x);
  const NT a10 = relative_coordinate(b, 1, a.y), a11 = relative_coordinate(c, 1, a.y),
           a12 = relative_coordinate(d, 1, a.y);
  const NT a20 = relative_coordinate(b, 2, a.z), a21 = relative_coordinate(c, 2, a.z),
           a22 = relative_coordinate(d, 2, a.z);
  // The cofactor order of orientation_3_determinant (determinants.h).
  const NT m01 = NT(a00 * a11) - NT(a10 * a01);
  const NT m02 = NT(a00 * a21) - NT(a20 * a01);
  const NT m12 = NT(a10 * a21) - NT(a20 * a11);
  const NT t = NT(m01 * a22) - NT(m02 * a12);
  return NT(t + NT(m12 * a02));
}

/// 4x4 determinant of the rows (W_i, X_i, Y_i, Z_i): prod W_i times the
/// orientation of the four points (used when none is explicit).
template <class NT>
NT orientation_3_homogeneous(const std::array<const Homogeneous_3<NT>*, 4>& h) {
  // Laplace expansion along the first column, with 2x2 minors of (Y, Z) rows.
  const auto m = [&](int i, int j) { return NT(NT(h[i]->y * h[j]->z) - NT(h[i]->z * h[j]->y)); };
  const NT m01 = m(0, 1), m02 = m(0, 2), m03 = m(0, 3), m12 = m(1, 2), m13 = m(1, 3), m23 = m(2, 3);
  // 3x3 minors of (X, Y, Z) without row i.
  const auto minor3 = [&](int a, int b, int c, const NT& bc, const NT& ac, const NT& ab) {
    return NT(NT(NT(h[a]->x * bc) - NT(h[b]->x * ac)) + NT(h[c]->x * ab));
  };
  const NT c0 = minor3(1, 2, 3, m23, m13, m12);
  const NT c1 = minor3(0, 2, 3, m23, m03, m02);
  const NT c2 = minor3(0, 1, 3, m13, m03, m01);
  const NT c3 = minor3(0, 1, 2, m12, m02, m01);
  return NT(NT(NT(h[0]->w * c0) - NT(h[1]->w * c1)) + NT(NT(h[2]->w * c2) - NT(h[3]->w * c3)));
}

/// In-plane orientation of the projections dropping `axis` (0: onto yz, 1:
/// onto zx, 2: onto xy, the kept axes in cyclic order so that the three
/// projections share the orientation of a normal with a positive component),
/// with a explicit: the orientation_2 determinant with rows scaled by W.
template <class NT>
NT orientation_2_with_pivot(const Point_3<NT>& a, const Homogeneous_3<NT>& b, const Homogeneous_3<NT>& c,
                            int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  const NT ai = i == 0 ? a.x : (i == 1 ? a.y : a.z), aj = j == 0 ? a.x : (j == 1 ? a.y : a.z);
  const NT bi = relative_coordinate(b, i, ai), bj = relative_coordinate(b, j, aj);
  const NT ci = relative_coordinate(c, i, ai), cj = relative_coordinate(c, j, aj);
  return NT(NT(bi * cj) - NT(bj * ci));
}

/// 3x3 determinant of rows (U_k, V_k, W_k) of the projections: prod W_k times
/// the in-plane orientation (used when none is explicit).
template <class NT>
NT orientation_2_homogeneous(const std::array<const Homogeneous_3<NT>*, 3>& h, int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  const auto u = [&](int k) -> const NT& { return (*h[k])[i]; };
  const auto v = [&](int k) -> const NT& { return (*h[k])[j]; };
  const auto w = [&](int k) -> const NT& { return h[k]->w; };
  const NT d0 = NT(NT(v(1) * w(2)) - NT(w(1) * v(2)));
  const NT d1 = NT(NT(v(0) * w(2)) - NT(w(0) * v(2)));
  const NT d2 = NT(NT(v(0) * w(1)) - NT(w(0) * v(1)));
  return NT(NT(NT(u(0) * d0) - NT(u(1) * d1)) + NT(u(2) * d2));
}

/// X_1 W_2 - X_2 W_1 along `axis` (before the W correction).
template <class NT>
NT coordinate_difference(const Homogeneous_3<NT>& a, const Homogeneous_3<NT>& b, int axis) {
  if (a.unit && b.unit) return NT(a[axis] - b[axis]);
  if (b.unit) return NT(a[axis] - NT(b[axis] * a.w));
  if (a.unit) return NT(NT(a[axis] * b.w) - b[axis]);
  return NT(NT(a[axis] * b.w) - NT(b[axis] * a.w));
}

}  // namespace relgeo::internal
