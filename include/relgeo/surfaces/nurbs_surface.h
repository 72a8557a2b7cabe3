// relgeo/surfaces/nurbs_surface.h — tensor-product B-spline and NURBS
// surfaces: evaluation, first and second derivatives, normals; generic over
// the number type.
#pragma once

#include <cstddef>
#include <optional>
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

/// A surface point with its partial derivatives up to `order` (1 or 2; the
/// second derivatives are zero vectors when order is 1).
template <class FT>
struct Surface_derivatives {
  Point_3<FT> point;
  Vector_3<FT> du, dv;
  Vector_3<FT> duu, duv, dvv;
  int order = 1;
};

/// \brief A tensor-product B-spline surface, rational (NURBS) when it has
/// weights.
///
/// S(u,v) = sum_ij N_i,p(u) N_j,q(v) w_ij P_ij / sum_ij N_i,p(u) N_j,q(v) w_ij
/// on [U[p], U[nu]] x [V[q], V[nv]]; control points and weights row-major:
/// index i * nv + j, i along u. Parameters outside the domain evaluate the end
/// spans' polynomials (extrapolation: projection uses it for points just
/// beyond a patch's edge).
///
/// Generic over FT: double (default), relgeo::Interval (point-interval data;
/// every result encloses the exact value for every (u,v) in the argument
/// box), mpq_class (exact), Mpfr_number<B>. Algorithms: NURBS Book A3.6
/// (derivatives of the homogeneous surface) and A4.4 (rational derivatives).
///
/// The constructor validates the data (Invalid_spline) and refuses control
/// nets whose points are all collinear (Degenerate_surface: no tangent plane
/// anywhere).
template <class FT = double>
class Nurbs_surface {
 public:
  using Number = FT;
  using Point = Point_3<FT>;

  Nurbs_surface() = default;
  Nurbs_surface(int degree_u, int degree_v, std::vector<FT> knots_u, std::vector<FT> knots_v, std::size_t count_u,
                std::size_t count_v, std::vector<Point> control_points, std::vector<FT> weights = {})
      : p_(degree_u), q_(degree_v), nu_(count_u), nv_(count_v), U_(std::move(knots_u)), V_(std::move(knots_v)),
        points_(std::move(control_points)), weights_(std::move(weights)) {
    check_knot_vector<FT>(U_, p_, nu_, "NURBS surface (u)");
    check_knot_vector<FT>(V_, q_, nv_, "NURBS surface (v)");
    if (points_.size() != nu_ * nv_)
      throw Invalid_spline("NURBS surface: " + std::to_string(points_.size()) + " control points, expected " +
                           std::to_string(nu_) + " x " + std::to_string(nv_));
    for (std::size_t i = 0; i < points_.size(); ++i)
      if (!is_finite_number(points_[i].x) || !is_finite_number(points_[i].y) || !is_finite_number(points_[i].z))
        throw Invalid_spline("NURBS surface: control point " + std::to_string(i) + " is not finite");
    if (!weights_.empty()) {
      if (weights_.size() != points_.size())
        throw Invalid_spline("NURBS surface: " + std::to_string(weights_.size()) + " weights for " +
                             std::to_string(points_.size()) + " control points");
      for (std::size_t i = 0; i < weights_.size(); ++i)
        if (!is_finite_number(weights_[i]) || !certainly(certified_sign(weights_[i]), Certified_sign::positive))
          throw Invalid_spline("NURBS surface: weight " + std::to_string(i) + " is not finite and positive");
    }
    if (control_net_is_collinear())
      throw Degenerate_surface("NURBS surface: all control points are collinear (no tangent plane anywhere)");
  }

  int degree_u() const { return p_; }
  int degree_v() const { return q_; }
  std::size_t count_u() const { return nu_; }
  std::size_t count_v() const { return nv_; }
  const std::vector<FT>& knots_u() const { return U_; }
  const std::vector<FT>& knots_v() const { return V_; }
  const std::vector<Point>& control_points() const { return points_; }
  const Point& control_point(std::size_t i, std::size_t j) const { return points_[i * nv_ + j]; }
  /// Empty for a non-rational surface.
  const std::vector<FT>& weights() const { return weights_; }
  bool is_rational() const { return !weights_.empty(); }
  std::pair<FT, FT> domain_u() const { return {U_[p_], U_[nu_]}; }
  std::pair<FT, FT> domain_v() const { return {V_[q_], V_[nv_]}; }

  /// S(u,v).
  Point evaluate(const FT& u, const FT& v) const { return derivatives(u, v, 0).point; }

  /// S and its partial derivatives up to `order` (0, 1 or 2) at (u,v).
  Surface_derivatives<FT> derivatives(const FT& u, const FT& v, int order = 1) const {
    RELGEO_precondition(order >= 0 && order <= 2, "Nurbs_surface::derivatives: order 0, 1 or 2");
    Surface_derivatives<FT> result;
    bool first_piece = true;
    internal::for_each_span_piece<FT>(p_, U_, nu_, u, [&](std::size_t su, const FT& pu) {
      internal::for_each_span_piece<FT>(q_, V_, nv_, v, [&](std::size_t sv, const FT& pv) {
        evaluate_piece(su, pu, sv, pv, order, 0, [&](Surface_derivatives<FT>&& r) {
          if (first_piece) result = std::move(r);
          else merge_hull(result, r);
          first_piece = false;
        });
      });
    });
    result.order = order < 1 ? 1 : order;
    return result;
  }

  /// The same surface in another number type (internal::convert_number).
  template <class FT2>
  Nurbs_surface<FT2> convert() const {
    const auto c = [](const FT& x) { return internal::convert_number<FT2>(x); };
    std::vector<FT2> U, V, W;
    for (const FT& k : U_) U.push_back(c(k));
    for (const FT& k : V_) V.push_back(c(k));
    for (const FT& w : weights_) W.push_back(c(w));
    std::vector<Point_3<FT2>> P;
    for (const Point& p : points_) P.push_back({c(p.x), c(p.y), c(p.z)});
    return Nurbs_surface<FT2>(p_, q_, std::move(U), std::move(V), nu_, nv_, std::move(P), std::move(W));
  }

 private:
  // Evaluates one (span, span) piece. For intervals, a rational piece whose
  // denominator enclosure contains 0 (a wide box: the dependency problem of
  // the basis recurrences) is bisected along its wider side until the
  // enclosures are positive (at most 2^24 pieces; beyond, the box is refused).
  template <class Sink>
  void evaluate_piece(std::size_t su, const FT& u, std::size_t sv, const FT& v, int order, int depth, Sink&& sink) const {
    std::optional<Surface_derivatives<FT>> r = derivatives_in_span(su, u, sv, v, order);
    if (r) return sink(std::move(*r));
    if constexpr (is_interval_v<FT>) {
      if (depth < 24) {
        const bool split_u = u.sup() - u.inf() >= v.sup() - v.inf();
        const FT& w = split_u ? u : v;
        const double m = 0.5 * w.inf() + 0.5 * w.sup();
        for (const FT half : {FT(w.inf(), m), FT(m, w.sup())})
          evaluate_piece(su, split_u ? half : u, sv, split_u ? v : half, order, depth + 1, sink);
        return;
      }
    }
    throw Error(Error_code::computation_failure,
                "Nurbs_surface: the weight enclosure of a parameter box contains 0 (box too wide)");
  }

  // Derivative table index (k derivatives in u, l in v), k + l <= 2.
  // Empty when the denominator of a rational surface is not certainly
  // positive (intervals only).
  std::optional<Surface_derivatives<FT>> derivatives_in_span(std::size_t su, const FT& u, std::size_t sv, const FT& v,
                                              int order) const {
    const int d = order;
    internal::Small_buffer<FT> Nu, Nv;
    internal::basis_derivatives<FT>(su, u, p_, d, U_, Nu);
    internal::basis_derivatives<FT>(sv, v, q_, d, V_, Nv);
    const std::size_t iu = su - static_cast<std::size_t>(p_), jv = sv - static_cast<std::size_t>(q_);
    // Homogeneous derivatives: A[k][l] (weighted points) and W[k][l].
    Vector_3<FT> A[3][3], S[3][3];
    FT W[3][3];
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l)
        A[k][l] = internal::zero_vector<FT, 3>(), S[k][l] = A[k][l], W[k][l] = FT(0);
    std::vector<Vector_3<FT>> temp(static_cast<std::size_t>(q_ + 1));
    std::vector<FT> temp_w(static_cast<std::size_t>(q_ + 1));
    for (int k = 0; k <= d; ++k) {
      // temp[s] = sum_r N^(k)_r(u) Pw[iu + r][jv + s]
      for (int s = 0; s <= q_; ++s) {
        temp[s] = internal::zero_vector<FT, 3>();
        temp_w[s] = FT(0);
        for (int r = 0; r <= p_; ++r) {
          const std::size_t idx = (iu + r) * nv_ + jv + s;
          const FT& n = Nu[static_cast<std::size_t>(k * (p_ + 1) + r)];
          if (is_rational()) {
            const FT nw = n * weights_[idx];
            internal::add_scaled<FT, 3>(temp[s], nw, internal::to_vector(points_[idx]));
            temp_w[s] += nw;
          } else {
            internal::add_scaled<FT, 3>(temp[s], n, internal::to_vector(points_[idx]));
          }
        }
      }
      for (int l = 0; l + k <= d; ++l)
        for (int s = 0; s <= q_; ++s) {
          const FT& n = Nv[static_cast<std::size_t>(l * (q_ + 1) + s)];
          internal::add_scaled<FT, 3>(A[k][l], n, temp[s]);
          if (is_rational()) W[k][l] += n * temp_w[s];
        }
    }
    if (!is_rational()) {
      for (int k = 0; k <= d; ++k)
        for (int l = 0; l + k <= d; ++l) S[k][l] = A[k][l];
    } else {
      if (!certainly(certified_sign(W[0][0]), Certified_sign::positive)) return std::nullopt;
      // NURBS Book A4.4.
      for (int k = 0; k <= d; ++k)
        for (int l = 0; l + k <= d; ++l) {
          Vector_3<FT> x = A[k][l];
          for (int j = 1; j <= l; ++j)
            internal::add_scaled<FT, 3>(x, FT(-internal::binomial(l, j)) * W[0][j], S[k][l - j]);
          for (int i = 1; i <= k; ++i) {
            internal::add_scaled<FT, 3>(x, FT(-internal::binomial(k, i)) * W[i][0], S[k - i][l]);
            Vector_3<FT> y = internal::zero_vector<FT, 3>();
            for (int j = 1; j <= l; ++j)
              internal::add_scaled<FT, 3>(y, FT(internal::binomial(l, j)) * W[i][j], S[k - i][l - j]);
            internal::add_scaled<FT, 3>(x, FT(-internal::binomial(k, i)), y);
          }
          for (int c = 0; c < 3; ++c) x[c] = x[c] / W[0][0];
          S[k][l] = x;
        }
    }
    Surface_derivatives<FT> r;
    r.point = internal::to_point(S[0][0]);
    const Vector_3<FT> zero = internal::zero_vector<FT, 3>();
    r.du = d >= 1 ? S[1][0] : zero;
    r.dv = d >= 1 ? S[0][1] : zero;
    r.duu = d >= 2 ? S[2][0] : zero;
    r.duv = d >= 2 ? S[1][1] : zero;
    r.dvv = d >= 2 ? S[0][2] : zero;
    r.order = d;
    return r;
  }

  static void merge_hull(Surface_derivatives<FT>& a, const Surface_derivatives<FT>& b) {
    a.point = {internal::hull(a.point.x, b.point.x), internal::hull(a.point.y, b.point.y),
               internal::hull(a.point.z, b.point.z)};
    const auto h = [](Vector_3<FT>& x, const Vector_3<FT>& y) {
      for (int c = 0; c < 3; ++c) x[c] = internal::hull(x[c], y[c]);
    };
    h(a.du, b.du), h(a.dv, b.dv), h(a.duu, b.duu), h(a.duv, b.duv), h(a.dvv, b.dvv);
  }

  // Whether every control point lies on one line (certainly: an interval
  // kernel that cannot decide does not refuse the surface).
  bool control_net_is_collinear() const {
    const Vector_3<FT> o = internal::to_vector(points_[0]);
    std::size_t a = 1;
    const auto certainly_zero = [](const Vector_3<FT>& w) {
      for (const FT& c : w)
        if (!certainly(certified_sign(c), Certified_sign::zero)) return false;
      return true;
    };
    while (a < points_.size() && certainly_zero(internal::operator_sub<FT, 3>(internal::to_vector(points_[a]), o))) ++a;
    if (a == points_.size()) return true;
    const Vector_3<FT> e = internal::operator_sub<FT, 3>(internal::to_vector(points_[a]), o);
    for (std::size_t b = a + 1; b < points_.size(); ++b)
      if (!certainly_zero(internal::cross(e, internal::operator_sub<FT, 3>(internal::to_vector(points_[b]), o))))
        return false;
    return true;
  }

  int p_ = 1, q_ = 1;
  std::size_t nu_ = 0, nv_ = 0;
  std::vector<FT> U_, V_;
  std::vector<Point> points_;
  std::vector<FT> weights_;
};

/// The (unnormalised) normal direction Su x Sv: exact under exact FT.
template <class FT>
Vector_3<FT> normal_direction(const Surface_derivatives<FT>& d) {
  return internal::cross(d.du, d.dv);
}

/// The unit normal Su x Sv / |Su x Sv| (FT with a square root: double,
/// Interval, Mpfr_number). \throws Degenerate_surface where Su x Sv is
/// (possibly, for intervals) zero.
template <class FT>
  requires internal::has_square_root_v<FT>
Vector_3<FT> unit_normal(const Surface_derivatives<FT>& d) {
  const Vector_3<FT> n = normal_direction(d);
  const FT len2 = internal::dot<FT, 3>(n, n);
  if (!certainly(certified_sign(len2), Certified_sign::positive) || !is_finite_number(len2))
    throw Degenerate_surface("unit_normal: Su x Sv vanishes (or is not finite) at this point");
  const FT len = internal::square_root(len2);
  return {n[0] / len, n[1] / len, n[2] / len};
}

}  // namespace relgeo
