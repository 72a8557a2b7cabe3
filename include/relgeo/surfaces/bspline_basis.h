// relgeo/surfaces/bspline_basis.h — B-spline basis functions and their
// derivatives (Cox-de Boor), generic over the number type.
//
// The algorithms are those of Piegl and Tiller, "The NURBS Book" (2nd ed.):
// A2.1 (span), A2.3 (basis functions and derivatives), with one change that
// matters for intervals: the denominators of the recurrences are formed as
// knot differences U[i+r+1] - U[i+1+r-j] directly instead of
// (U[i+r+1] - u) + (u - U[i+1+r-j]), which is the same value in exact
// arithmetic but, for an interval u, a point instead of an interval of twice
// u's width (that could contain 0).
//
// Number types: double (and float, long double), relgeo::Interval (the
// result encloses the exact value for every u in the interval: see
// for_each_span_piece), mpq_class (exact), Mpfr_number<B>.
#pragma once

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "relgeo/core/interval.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/surfaces/surface_errors.h"

namespace relgeo {

/// The largest degree relgeo's splines accept (OpenCASCADE's limit).
inline constexpr int max_spline_degree = 25;

/// \brief Checks a clamped or unclamped knot vector for `count` control
/// points of degree p: 1 <= p <= max_spline_degree, count >= p + 1,
/// knots.size() == count + p + 1, finite, non-decreasing, a non-empty domain
/// [U[p], U[count]], no interior knot (inside the domain) of multiplicity
/// above p. \throws Invalid_spline naming `what` and the defect.
template <class FT>
void check_knot_vector(std::span<const FT> knots, int p, std::size_t count, const std::string& what) {
  if (p < 1 || p > max_spline_degree)
    throw Invalid_spline(what + ": degree " + std::to_string(p) + " outside [1, " +
                         std::to_string(max_spline_degree) + "]");
  if (count < static_cast<std::size_t>(p) + 1)
    throw Invalid_spline(what + ": " + std::to_string(count) + " control points for degree " + std::to_string(p));
  if (knots.size() != count + static_cast<std::size_t>(p) + 1)
    throw Invalid_spline(what + ": " + std::to_string(knots.size()) + " knots, expected " +
                         std::to_string(count + p + 1) + " (control points + degree + 1)");
  for (std::size_t i = 0; i < knots.size(); ++i) {
    if (!is_finite_number(knots[i])) throw Invalid_spline(what + ": knot " + std::to_string(i) + " is not finite");
    if constexpr (is_interval_v<FT>)
      if (!knots[i].is_point())
        throw Invalid_spline(what + ": knot " + std::to_string(i) + " is not a point interval (convert from doubles)");
    if (i > 0 && certainly(certified_sign(FT(knots[i] - knots[i - 1])), Certified_sign::negative))
      throw Invalid_spline(what + ": knots decrease at index " + std::to_string(i));
  }
  if (!certainly(certified_sign(FT(knots[count] - knots[p])), Certified_sign::positive))
    throw Invalid_spline(what + ": empty parameter domain [U[p], U[n]]");
  // Interior multiplicity: a run of equal knots strictly inside the domain.
  std::size_t run = 1;
  for (std::size_t i = 1; i < knots.size(); ++i) {
    run = certainly(certified_sign(FT(knots[i] - knots[i - 1])), Certified_sign::zero) ? run + 1 : 1;
    const bool interior = i > static_cast<std::size_t>(p) && i < count;
    if (interior && run > static_cast<std::size_t>(p))
      throw Invalid_spline(what + ": interior knot of multiplicity " + std::to_string(run) + " > degree " +
                           std::to_string(p) + " (the spline would be discontinuous)");
    if (run > static_cast<std::size_t>(p) + 1)
      throw Invalid_spline(what + ": knot of multiplicity " + std::to_string(run) + " > degree + 1");
  }
}

namespace internal {

/// a < b for knots and point parameters (intervals: point intervals, by
/// their value).
template <class FT>
bool knot_less(const FT& a, const FT& b) {
  if constexpr (is_interval_v<FT>) return a.inf() < b.inf();
  else return a < b;
}

/// Scratch storage: on the stack up to 36 values (degree 5 tables), no
/// allocation on the evaluation path of common degrees.
template <class FT>
using Small_buffer = boost::container::small_vector<FT, 36>;

/// The knot span of a point parameter u: the index k in [p, count-1] with
/// U[k] <= u < U[k+1], the last non-empty span for u >= U[count] and the
/// first for u < U[p] (so parameters slightly outside the domain evaluate
/// the polynomial of the end span: an extrapolation). NURBS Book A2.1.
template <class FT>
std::size_t find_span(int p, std::span<const FT> U, std::size_t count, const FT& u) {
  const std::size_t first = static_cast<std::size_t>(p), last = count - 1;
  if (!knot_less(u, U[count])) {
    std::size_t k = last;
    while (k > first && !knot_less(U[k], U[k + 1])) --k;  // skip empty spans at the end
    return k;
  }
  if (knot_less(u, U[first + 1])) return first;
  std::size_t lo = first, hi = count;  // U[lo] <= u < U[hi]
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (knot_less(u, U[mid])) hi = mid;
    else lo = mid;
  }
  return lo;
}

/// Basis functions of span i and their derivatives up to order d at u:
/// ders[k * (p + 1) + j] = d^k/du^k N_{i-p+j, p}(u), k = 0..d (derivatives
/// above p are 0). NURBS Book A2.3 with knot-difference denominators.
template <class FT>
void basis_derivatives(std::size_t i, const FT& u, int p, int d, std::span<const FT> U, Small_buffer<FT>& ders) {
  const int w = p + 1;
  Small_buffer<FT> ndu(static_cast<std::size_t>(w * w), FT(0)), left(w, FT(0)), right(w, FT(0));
  const auto at = [w](int r, int c) { return static_cast<std::size_t>(r * w + c); };
  ndu[at(0, 0)] = FT(1);
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[i + 1 - j];
    right[j] = U[i + j] - u;
    FT saved(0);
    for (int r = 0; r < j; ++r) {
      ndu[at(j, r)] = U[i + r + 1] - U[i + 1 + r - j];  // = right[r+1] + left[j-r]
      const FT temp = ndu[at(r, j - 1)] / ndu[at(j, r)];
      ndu[at(r, j)] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[at(j, j)] = saved;
  }
  ders.assign(static_cast<std::size_t>((d + 1) * w), FT(0));
  for (int j = 0; j <= p; ++j) ders[j] = ndu[at(j, p)];
  const int dd = std::min(d, p);
  Small_buffer<FT> a(static_cast<std::size_t>(2 * w), FT(0));
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0] = FT(1);
    for (int k = 1; k <= dd; ++k) {
      FT dk(0);
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2 * w] = a[s1 * w] / ndu[at(pk + 1, rk)];
        dk = a[s2 * w] * ndu[at(rk, pk)];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2 * w + j] = (a[s1 * w + j] - a[s1 * w + j - 1]) / ndu[at(pk + 1, rk + j)];
        dk += a[s2 * w + j] * ndu[at(rk + j, pk)];
      }
      if (r <= pk) {
        a[s2 * w + k] = -a[s1 * w + k - 1] / ndu[at(pk + 1, r)];
        dk += a[s2 * w + k] * ndu[at(r, pk)];
      }
      ders[k * w + r] = dk;
      std::swap(s1, s2);
    }
  }
  int factor = p;
  for (int k = 1; k <= dd; ++k) {
    for (int j = 0; j <= p; ++j) ders[k * w + j] *= FT(factor);
    factor *= p - k;
  }
}

/// Calls f(span, piece) for the pieces of the parameter u on which one
/// polynomial applies: for a point type, once with u's own span; for an
/// interval u = [a, b], once per knot span meeting [a, b] with piece =
/// [a, b] restricted to that span (the end spans extend outward:
/// extrapolation). The union of the pieces is u, so the hull of the results
/// encloses the value for every u.
template <class FT, class F>
void for_each_span_piece(int p, std::span<const FT> U, std::size_t count, const FT& u, F&& f) {
  if constexpr (is_interval_v<FT>) {
    const double a = u.inf(), b = u.sup();
    const std::size_t first = find_span<FT>(p, U, count, FT(a));
    const std::size_t last = find_span<FT>(p, U, count, FT(b));
    for (std::size_t k = first; k <= last; ++k) {
      if (k != first && k != last && !(U[k].inf() < U[k + 1].inf())) continue;  // empty span
      const double lo = k == first ? a : std::max(a, U[k].inf());
      const double hi = k == last ? b : std::min(b, U[k + 1].inf());
      if (lo <= hi) f(k, FT(lo, hi));
    }
  } else {
    f(find_span<FT>(p, U, count, u), u);
  }
}

/// Hull of two enclosures (identity for point types: only intervals have
/// several pieces).
template <class FT>
FT hull(const FT& a, const FT& b) {
  if constexpr (is_interval_v<FT>) return FT(std::min(a.inf(), b.inf()), std::max(a.sup(), b.sup()));
  else return b;
}

/// Binomial coefficient (small arguments).
inline int binomial(int n, int k) {
  int r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

}  // namespace internal
}  // namespace relgeo
