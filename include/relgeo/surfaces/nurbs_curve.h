// relgeo/surfaces/nurbs_curve.h — B-spline and NURBS curves in the plane
// (trim curves in a surface's (u,v) domain) and in space (edge curves),
// generic over the number type.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "relgeo/core/assertions.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/kernel/point.h"
#include "relgeo/surfaces/bspline_basis.h"
#include "relgeo/surfaces/internal/vector_ops.h"
#include "relgeo/surfaces/surface_errors.h"

namespace relgeo {

/// \brief A B-spline curve, rational (NURBS) when it has weights, of
/// dimension 2 or 3 over the number type FT.
///
/// C(t) = sum_i N_{i,p}(t) w_i P_i / sum_i N_{i,p}(t) w_i for t in the domain
/// [U[p], U[n]] (n control points); without weights all w_i = 1. Parameters
/// outside the domain evaluate the end spans' polynomials (extrapolation).
///
/// Exact under mpq_class; under relgeo::Interval (point-interval knots) the
/// results enclose the exact values for every parameter in the argument.
/// The constructor validates everything (Invalid_spline).
template <class FT, int Dim>
class Nurbs_curve {
  static_assert(Dim == 2 || Dim == 3, "Nurbs_curve: dimension 2 or 3");

 public:
  using Number = FT;
  using Point = std::conditional_t<Dim == 2, Point_2<FT>, Point_3<FT>>;
  using Vector = Vector_nd<FT, Dim>;
  static constexpr int dimension = Dim;

  Nurbs_curve() = default;
  /// \throws Invalid_spline for inconsistent data (see check_knot_vector),
  /// non-finite control points, weights of the wrong count, non-finite or
  /// not positive.
  Nurbs_curve(int degree, std::vector<FT> knots, std::vector<Point> control_points, std::vector<FT> weights = {})
      : degree_(degree), knots_(std::move(knots)), points_(std::move(control_points)), weights_(std::move(weights)) {
    check_knot_vector<FT>(knots_, degree_, points_.size(), "NURBS curve");
    for (std::size_t i = 0; i < points_.size(); ++i)
      for (const FT& c : internal::to_vector(points_[i]))
        if (!is_finite_number(c))
          throw Invalid_spline("NURBS curve: control point " + std::to_string(i) + " is not finite");
    if (!weights_.empty()) {
      if (weights_.size() != points_.size())
        throw Invalid_spline("NURBS curve: " + std::to_string(weights_.size()) + " weights for " +
                             std::to_string(points_.size()) + " control points");
      for (std::size_t i = 0; i < weights_.size(); ++i)
        if (!is_finite_number(weights_[i]) || !certainly(certified_sign(weights_[i]), Certified_sign::positive))
          throw Invalid_spline("NURBS curve: weight " + std::to_string(i) + " is not finite and positive");
    }
  }

  int degree() const { return degree_; }
  const std::vector<FT>& knots() const { return knots_; }
  const std::vector<Point>& control_points() const { return points_; }
  /// Empty for a non-rational curve.
  const std::vector<FT>& weights() const { return weights_; }
  bool is_rational() const { return !weights_.empty(); }
  std::size_t number_of_control_points() const { return points_.size(); }
  /// The parameter domain [U[p], U[n]].
  std::pair<FT, FT> domain() const { return {knots_[degree_], knots_[points_.size()]}; }

  /// C(t).
  Point evaluate(const FT& t) const { return internal::to_point(derivatives(t, 0)[0]); }

  /// C(t) and its derivatives up to order d: result[k] = C^(k)(t), k = 0..d.
  std::vector<Vector> derivatives(const FT& t, int d) const {
    std::vector<Vector> result;
    bool first_piece = true;
    internal::for_each_span_piece<FT>(degree_, knots_, points_.size(), t, [&](std::size_t span, const FT& piece) {
      evaluate_piece(span, piece, d, 0, [&](std::vector<Vector>&& r) {
        if (first_piece) result = std::move(r);
        else
          for (int k = 0; k <= d; ++k)
            for (int c = 0; c < Dim; ++c) result[k][c] = internal::hull(result[k][c], r[k][c]);
        first_piece = false;
      });
    });
    return result;
  }

  /// The same curve in another number type (internal::convert_number: exact
  /// where FT2 holds FT's values, e.g. double -> mpq_class or Interval).
  template <class FT2>
  Nurbs_curve<FT2, Dim> convert() const {
    const auto c = [](const FT& x) { return internal::convert_number<FT2>(x); };
    std::vector<FT2> knots, weights;
    for (const FT& k : knots_) knots.push_back(c(k));
    for (const FT& w : weights_) weights.push_back(c(w));
    std::vector<typename Nurbs_curve<FT2, Dim>::Point> pts;
    for (const Point& p : points_) {
      const Vector v = internal::to_vector(p);
      Vector_nd<FT2, Dim> w;
      for (int i = 0; i < Dim; ++i) w[i] = c(v[i]);
      pts.push_back(internal::to_point(w));
    }
    return Nurbs_curve<FT2, Dim>(degree_, std::move(knots), std::move(pts), std::move(weights));
  }

 private:
  // One span piece; a rational interval piece whose weight enclosure
  // contains 0 is bisected (as Nurbs_surface does).
  template <class Sink>
  void evaluate_piece(std::size_t span, const FT& t, int d, int depth, Sink&& sink) const {
    std::optional<std::vector<Vector>> r = derivatives_in_span(span, t, d);
    if (r) return sink(std::move(*r));
    if constexpr (is_interval_v<FT>) {
      if (depth < 24) {
        const double m = 0.5 * t.inf() + 0.5 * t.sup();
        evaluate_piece(span, FT(t.inf(), m), d, depth + 1, sink);
        evaluate_piece(span, FT(m, t.sup()), d, depth + 1, sink);
        return;
      }
    }
    throw Error(Error_code::computation_failure,
                "Nurbs_curve: the weight enclosure of a parameter interval contains 0 (too wide)");
  }

  std::optional<std::vector<Vector>> derivatives_in_span(std::size_t span, const FT& t, int d) const {
    const int p = degree_;
    internal::Small_buffer<FT> N;
    internal::basis_derivatives<FT>(span, t, p, d, knots_, N);
    const std::size_t first = span - static_cast<std::size_t>(p);
    // Homogeneous derivatives A^(k) (weighted points) and w^(k).
    std::vector<Vector> A(static_cast<std::size_t>(d) + 1, internal::zero_vector<FT, Dim>());
    std::vector<FT> W(static_cast<std::size_t>(d) + 1, FT(0));
    for (int k = 0; k <= d; ++k)
      for (int j = 0; j <= p; ++j) {
        const FT& n = N[static_cast<std::size_t>(k * (p + 1) + j)];
        const Vector P = internal::to_vector(points_[first + j]);
        if (is_rational()) {
          const FT nw = n * weights_[first + j];
          internal::add_scaled<FT, Dim>(A[k], nw, P);
          W[k] += nw;
        } else {
          internal::add_scaled<FT, Dim>(A[k], n, P);
        }
      }
    if (!is_rational()) return A;
    if (!certainly(certified_sign(W[0]), Certified_sign::positive)) return std::nullopt;
    // C^(k) = (A^(k) - sum_{i=1..k} binom(k,i) w^(i) C^(k-i)) / w (NURBS Book A4.2).
    std::vector<Vector> C(static_cast<std::size_t>(d) + 1);
    for (int k = 0; k <= d; ++k) {
      Vector v = A[k];
      for (int i = 1; i <= k; ++i) internal::add_scaled<FT, Dim>(v, FT(-internal::binomial(k, i)) * W[i], C[k - i]);
      for (int c = 0; c < Dim; ++c) v[c] = v[c] / W[0];
      C[k] = v;
    }
    return C;
  }

  int degree_ = 1;
  std::vector<FT> knots_;
  std::vector<Point> points_;
  std::vector<FT> weights_;
};

template <class FT = double>
using Nurbs_curve_2 = Nurbs_curve<FT, 2>;
template <class FT = double>
using Nurbs_curve_3 = Nurbs_curve<FT, 3>;

}  // namespace relgeo
