// relgeo/curves/bezier_curve.h — planar Bezier curves: evaluation (de
// Casteljau), derivatives (hodographs), subdivision.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/kernel/point.h"

namespace relgeo {

/// \brief A planar Bezier curve R(t) = sum_i C(v,i) t^i (1-t)^(v-i) R_i,
/// 0 <= t <= 1, of degree v >= 1 with control points R_0..R_v (thesis Sec. 3.4.1).
///
/// \tparam FT the coordinate type: float, double, long double, or any type
///   with +, -, * and construction from double (Mpfr_number, mpq_class...).
///   Evaluation and subdivision compute in FT (de Casteljau: every
///   intermediate point is a convex combination, the numerically stable way).
template <class FT>
class Bezier_curve_2 {
 public:
  using Point = Point_2<FT>;

  /// \throws Invalid_input for fewer than 2 control points (degree < 1),
  ///   Non_finite_input for a NaN or infinite coordinate (floating FT).
  explicit Bezier_curve_2(std::vector<Point> control_points) : p_(std::move(control_points)) {
    if (p_.size() < 2)
      throw Invalid_input("Bezier curve: degree " + std::to_string(static_cast<long>(p_.size()) - 1) +
                          " (" + std::to_string(p_.size()) +
                          " control points); the degree must be at least 1");
    if constexpr (std::is_floating_point_v<FT>)
      for (std::size_t i = 0; i < p_.size(); ++i)
        if (!std::isfinite(p_[i].x) || !std::isfinite(p_[i].y))
          throw Non_finite_input("Bezier curve: control point " + std::to_string(i) +
                                 " has a NaN or infinite coordinate");
  }

  /// The degree v (number of control points - 1).
  std::size_t degree() const { return p_.size() - 1; }
  std::span<const Point> control_points() const { return p_; }
  const Point& operator[](std::size_t i) const { return p_[i]; }

  /// R(t) by de Casteljau's algorithm (any t; the curve is 0 <= t <= 1).
  Point evaluate(const FT& t) const {
    std::vector<Point> w = p_;
    const FT s = FT(1) - t;
    for (std::size_t r = 1; r < w.size(); ++r)
      for (std::size_t i = 0; i + r < w.size(); ++i)
        w[i] = Point{FT(s * w[i].x + t * w[i + 1].x), FT(s * w[i].y + t * w[i + 1].y)};
    return w[0];
  }
  Point operator()(const FT& t) const { return evaluate(t); }

  /// The hodograph R'(t): degree v-1 with control points v (R_{i+1} - R_i).
  /// \throws Invalid_input for degree 1 (the derivative is constant: use
  ///   derivative(t) or differences()).
  Bezier_curve_2 derivative_curve() const {
    if (degree() < 2)
      throw Invalid_input("Bezier curve: the hodograph of a degree-1 curve is a constant, not a curve");
    std::vector<Point> d;
    d.reserve(p_.size() - 1);
    const FT v(static_cast<double>(degree()));
    for (std::size_t i = 0; i + 1 < p_.size(); ++i)
      d.push_back(Point{FT(v * (p_[i + 1].x - p_[i].x)), FT(v * (p_[i + 1].y - p_[i].y))});
    return Bezier_curve_2(std::move(d));
  }

  /// The k-th derivative at t (k = 0 is R(t); 0 for k > v).
  Point derivative(const FT& t, std::size_t k = 1) const {
    if (k > degree()) return Point{FT(0), FT(0)};
    std::vector<Point> d = p_;
    FT factor(1);
    for (std::size_t r = 0; r < k; ++r) {  // differences, times v (v-1) ... (v-k+1)
      factor = FT(factor * FT(static_cast<double>(degree() - r)));
      for (std::size_t i = 0; i + 1 < d.size(); ++i)
        d[i] = Point{FT(d[i + 1].x - d[i].x), FT(d[i + 1].y - d[i].y)};
      d.pop_back();
    }
    const FT s = FT(1) - t;
    for (std::size_t r = 1; r < d.size(); ++r)
      for (std::size_t i = 0; i + r < d.size(); ++i)
        d[i] = Point{FT(s * d[i].x + t * d[i + 1].x), FT(s * d[i].y + t * d[i + 1].y)};
    return Point{FT(factor * d[0].x), FT(factor * d[0].y)};
  }

  /// The differences q_i = R_{i+1} - R_i, i = 0..v-1 (the set q of the
  /// thesis' condition 1), computed in FT.
  std::vector<Point> differences() const {
    std::vector<Point> q;
    q.reserve(p_.size() - 1);
    for (std::size_t i = 0; i + 1 < p_.size(); ++i)
      q.push_back(Point{FT(p_[i + 1].x - p_[i].x), FT(p_[i + 1].y - p_[i].y)});
    return q;
  }

  /// De Casteljau subdivision at t: the curves R(t s) and R(t + (1-t) s),
  /// 0 <= s <= 1, each of degree v; left.back() == right.front() == R(t).
  std::pair<Bezier_curve_2, Bezier_curve_2> subdivide(const FT& t) const {
    std::vector<Point> w = p_, left, right;
    const std::size_t n = p_.size();
    left.reserve(n), right.resize(n);
    const FT s = FT(1) - t;
    left.push_back(w[0]);
    right[n - 1] = w[n - 1];
    for (std::size_t r = 1; r < n; ++r) {
      for (std::size_t i = 0; i + r < n; ++i)
        w[i] = Point{FT(s * w[i].x + t * w[i + 1].x), FT(s * w[i].y + t * w[i + 1].y)};
      left.push_back(w[0]);
      right[n - 1 - r] = w[n - 1 - r];
    }
    return {Bezier_curve_2(std::move(left)), Bezier_curve_2(std::move(right))};
  }

  /// The same curve with the parameter reversed (u = 1 - t): control points reversed.
  Bezier_curve_2 reversed() const { return Bezier_curve_2(std::vector<Point>(p_.rbegin(), p_.rend())); }

 private:
  std::vector<Point> p_;
};

}  // namespace relgeo
