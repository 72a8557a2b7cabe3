// relgeo/curves/contour.h — closed contours of planar Bezier curves (the
// cross-section of an extruded object, thesis Sec. 3.4.1), and the rotation
// carrying the extrusion direction d to the z axis for 3D input.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/mpfr_number.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/core/rounding.h"
#include "relgeo/curves/bezier_curve.h"
#include "relgeo/kernel/point.h"

namespace relgeo {

/// \brief A closed contour of M >= 1 planar Bezier curves R^0..R^{M-1} with
/// R^m_v = R^{m+1}_0 (indices mod M), as the thesis' extruded objects use.
///
/// Each control point carries a *scale*: the norm its relative input
/// uncertainty refers to (||R^m_i||_2 by default; for a contour projected from
/// 3D input, the norm of the 3D point the user gave).
class Bezier_contour {
 public:
  /// From each curve's control points. The contour must close exactly: the
  /// last control point of curve m equals the first of curve m+1 (mod M).
  /// \throws Invalid_input (no curves, a curve of degree < 1, not closed),
  ///   Non_finite_input (NaN or infinite coordinate).
  static Bezier_contour from_curves(std::vector<std::vector<Point_2<double>>> curves) {
    if (curves.empty()) throw Invalid_input("contour: no curves", Error_code::empty_input);
    Bezier_contour c;
    c.curves_.reserve(curves.size());
    for (std::size_t m = 0; m < curves.size(); ++m) {
      try {
        c.curves_.emplace_back(std::move(curves[m]));
      } catch (const Non_finite_input& e) {
        throw Non_finite_input("contour: curve " + std::to_string(m) + ": " + e.what());
      } catch (const Invalid_input& e) {
        throw Invalid_input("contour: curve " + std::to_string(m) + ": " + e.what());
      }
    }
    const std::size_t M = c.curves_.size();
    for (std::size_t m = 0; m < M; ++m) {
      const auto& a = c.curves_[m];
      const auto& b = c.curves_[(m + 1) % M];
      const Point_2<double>& end = a[a.degree()];
      if (!(end == b[0]))
        throw Invalid_input("contour is not closed: curve " + std::to_string(m) + " ends at (" +
                            std::to_string(end.x) + ", " + std::to_string(end.y) + ") but curve " +
                            std::to_string((m + 1) % M) + " starts at (" + std::to_string(b[0].x) +
                            ", " + std::to_string(b[0].y) + ")");
    }
    c.default_scales();
    return c;
  }

  /// From a closed chain of N = M v points and a degree v: curve m has the
  /// control points chain[m v], ..., chain[m v + v] (indices mod N), so
  /// consecutive curves share their end points by construction.
  /// \throws Invalid_input (degree < 1, N not a positive multiple of v),
  ///   Non_finite_input.
  static Bezier_contour from_chain(std::span<const Point_2<double>> chain, std::size_t degree) {
    if (degree < 1) throw Invalid_input("contour: degree " + std::to_string(degree) + "; the degree must be at least 1");
    if (chain.empty()) throw Invalid_input("contour: no points", Error_code::empty_input);
    if (chain.size() % degree != 0)
      throw Invalid_input("contour: " + std::to_string(chain.size()) +
                          " points do not form a closed chain of degree-" + std::to_string(degree) +
                          " curves (need a multiple of " + std::to_string(degree) + ")");
    std::vector<std::vector<Point_2<double>>> curves(chain.size() / degree);
    for (std::size_t m = 0; m < curves.size(); ++m)
      for (std::size_t i = 0; i <= degree; ++i) curves[m].push_back(chain[(m * degree + i) % chain.size()]);
    return from_curves(std::move(curves));
  }

  /// Number of curves M.
  std::size_t size() const { return curves_.size(); }
  const Bezier_curve_2<double>& curve(std::size_t m) const { return curves_[m]; }
  const Bezier_curve_2<double>& operator[](std::size_t m) const { return curves_[m]; }

  /// The norm the relative uncertainty of control point i of curve m refers to.
  double scale(std::size_t m, std::size_t i) const { return scales_[m][i]; }
  /// Replaces the scales (one per control point, >= 0; curve by curve).
  /// \throws Invalid_input when the shape differs or a scale is negative/NaN.
  void set_scales(std::vector<std::vector<double>> scales) {
    if (scales.size() != curves_.size()) throw Invalid_input("contour: one scale list per curve expected");
    for (std::size_t m = 0; m < scales.size(); ++m) {
      if (scales[m].size() != curves_[m].degree() + 1)
        throw Invalid_input("contour: curve " + std::to_string(m) + ": one scale per control point expected");
      for (double s : scales[m])
        if (!(s >= 0) || !std::isfinite(s)) throw Invalid_input("contour: scales must be finite and >= 0");
    }
    scales_ = std::move(scales);
  }

 private:
  Bezier_contour() = default;  // only through the factories: a contour has at least one curve
  void default_scales() {
    scales_.assign(curves_.size(), {});
    for (std::size_t m = 0; m < curves_.size(); ++m)
      for (const auto& p : curves_[m].control_points()) scales_[m].push_back(norm_up(p.x, p.y));
  }
  std::vector<Bezier_curve_2<double>> curves_;
  std::vector<std::vector<double>> scales_;
};

/// A 3x3 matrix, row-major.
using Matrix_3 = std::array<std::array<double, 3>, 3>;

/// \brief The rotation Q carrying the unit vector d to the z axis (thesis
/// Sec. 3.4.1), by Rodrigues' formula in the form
///     Q = c I + [k]x + k k^T / (1 + c),   k = d x e_z,  c = d . e_z = d_z,
/// which is exact algebra for unit d and well conditioned for c >= 0
/// (1/(1+c) in [1/2, 1]). For d_z < 0 it first applies the half turn about
/// the x axis, diag(1, -1, -1), which maps d to (d_x, -d_y, -d_z) with a
/// nonnegative z: Q = R(d') diag(1, -1, -1). det Q = +1 in both cases.
/// \pre d is a unit vector (see project_along for normalisation).
inline Matrix_3 rotation_to_z(const Point_3<double>& d) {
  const bool flip = d.z < 0;
  const double x = d.x, y = flip ? -d.y : d.y, z = flip ? -d.z : d.z;
  // k = (x, y, z) x (0, 0, 1) = (y, -x, 0); [k]x = [[0, 0, -x], [0, 0, -y], [x, y, 0]].
  const double c = z, f = 1 / (1 + c);
  const double kx = y, ky = -x;
  Matrix_3 r{{{c + kx * kx * f, kx * ky * f, -x}, {kx * ky * f, c + ky * ky * f, -y}, {x, y, c}}};
  if (flip)  // R diag(1, -1, -1): negate columns 1 and 2
    for (auto& row : r) row[1] = -row[1], row[2] = -row[2];
  return r;
}

/// A 3D contour chain projected to the plane orthogonal to d.
struct Plane_projection {
  Point_3<double> direction;  ///< d / ||d||, in double
  Matrix_3 rotation{};        ///< Q (rotation_to_z of `direction`)
  /// (Q x)_x, (Q x)_y of every point x, computed in double.
  std::vector<Point_2<double>> points;
  /// ||x||_2 of every input point, rounded upward (the scale of its uncertainty).
  std::vector<double> norms;
  /// An upper bound, over the points, of |fl(Q x)_xy - (Q* x)_xy|, where Q* is
  /// the exact rotation of Rodrigues' formula for the exact unit vector
  /// d / ||d|| (a posteriori: each image recomputed with 256-bit MPFR, with a
  /// margin for the reference's own error).
  double rotation_error = 0;
  /// The range of d . x over the points (the heights of the points: equal
  /// for points on one plane orthogonal to d).
  double height_min = 0, height_max = 0;
};

/// \brief Projects 3D points to the plane orthogonal to d: the 2D points are
/// the first two coordinates of Q x (the third, d . x, is dropped — the
/// extruded object is defined by the projection x - (d . x) d).
/// \throws Invalid_input (d zero or not finite), Non_finite_input (a point).
inline Plane_projection project_along(std::span<const Point_3<double>> points, const Point_3<double>& d) {
  // The images and their error bound are computed in round to nearest
  // without FTZ/DAZ, whatever the caller's environment (the bound's directed
  // roundings assume it).
  const Default_fp_environment environment;
  if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z))
    throw Non_finite_input("extrusion direction: NaN or infinite component");
  const double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  if (!(len > 0) || !std::isfinite(len)) throw Invalid_input("extrusion direction: the zero vector (or out of range)");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
      throw Non_finite_input("contour point " + std::to_string(i) + " has a NaN or infinite coordinate");
  Plane_projection p;
  p.direction = {d.x / len, d.y / len, d.z / len};
  p.rotation = rotation_to_z(p.direction);
  const Matrix_3& q = p.rotation;

  // The 256-bit reference rotation (rows 0 and 1; row 2 is dropped), from
  // the exact unit vector d / ||d||, by the formula of rotation_to_z.
  using Reference = Mpfr_number<256>;
  Reference dx(d.x), dy(d.y), dz(d.z);  // exact
  Reference n = dx * dx;
  mpfr_fma(n.get(), dy.get(), dy.get(), n.get(), MPFR_RNDN);
  mpfr_fma(n.get(), dz.get(), dz.get(), n.get(), MPFR_RNDN);
  n = sqrt(n);
  dx /= n, dy /= n, dz /= n;
  const bool flip = dz.sign() < 0;
  if (flip) dy = -dy, dz = -dz;
  const Reference& c = dz;
  const Reference f = Reference(1) / (c + Reference(1));
  // kx = y, ky = -x: R00 = c + y^2 f, R01 = R10 = -x y f, R02 = -x;
  // R11 = c + x^2 f, R12 = -y; with the flip, columns 1 and 2 negated.
  Reference ref[2][3] = {{c + dy * dy * f, -(dx * dy * f), -dx}, {Reference(0), c + dx * dx * f, -dy}};
  ref[1][0] = ref[0][1];
  if (flip)
    for (auto& row : ref) row[1] = -row[1], row[2] = -row[2];

  double worst = 0, max_norm = 0;
  p.height_min = std::numeric_limits<double>::infinity();
  p.height_max = -std::numeric_limits<double>::infinity();
  Reference t, u;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point_3<double>& x = points[i];
    const double px = q[0][0] * x.x + q[0][1] * x.y + q[0][2] * x.z;
    const double py = q[1][0] * x.x + q[1][1] * x.y + q[1][2] * x.z;
    const double h = p.direction.x * x.x + p.direction.y * x.y + p.direction.z * x.z;
    p.height_min = std::min(p.height_min, h), p.height_max = std::max(p.height_max, h);
    p.points.push_back({px, py});
    p.norms.push_back(norm_up(x.x, x.y, x.z));
    max_norm = std::max(max_norm, p.norms.back());
    // reference image and the distance to the double one
    double e2 = 0;
    for (int row = 0; row < 2; ++row) {
      mpfr_mul_d(t.get(), ref[row][0].get(), x.x, MPFR_RNDN);
      mpfr_mul_d(u.get(), ref[row][1].get(), x.y, MPFR_RNDN), mpfr_add(t.get(), t.get(), u.get(), MPFR_RNDN);
      mpfr_mul_d(u.get(), ref[row][2].get(), x.z, MPFR_RNDN), mpfr_add(t.get(), t.get(), u.get(), MPFR_RNDN);
      mpfr_sub_d(t.get(), t.get(), row == 0 ? px : py, MPFR_RNDN);
      mpfr_abs(t.get(), t.get(), MPFR_RNDN);
      const double di = upper_double(t);
      e2 += di * di;
    }
    worst = std::max(worst, std::sqrt(e2));
  }
  // Margins: this evaluation's own rounding (relative 2^-50 is ample) and the
  // 256-bit reference's error (relative 2^-240 of ||x||).
  p.rotation_error = add_up(worst * (1 + 0x1p-50), max_norm * 0x1p-240);
  return p;
}

}  // namespace relgeo
