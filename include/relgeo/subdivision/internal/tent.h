// relgeo/subdivision/internal/tent.h — the maximum over a triangle of the
// lower envelope of affine functions (the "tent" of the tangent-plane bound).
#pragma once

#include <cstddef>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/subdivision/internal/bound_ranges.h"

namespace relgeo::internal {

/// An affine function tau + rho a + sigma b of the face coordinates.
template <class FT>
struct Affine_2 {
  FT tau, rho, sigma;
  FT operator()(const FT& a, const FT& b) const { return FT(FT(tau + FT(rho * a)) + FT(sigma * b)); }
};

/// max over D' = {a >= amin, b >= bmin, a + b <= s} of min_k f_k(a, b),
/// from the vertices of the arrangement (D''s corners, crossings of the lines
/// f_k = f_l with D''s edges, points where three f are equal). False when a
/// determinant cannot be certified nonzero-or-zero (intervals).
template <class FT, class Tr>
bool tent_maximum(const std::vector<Affine_2<FT>>& f, const FT& amin, const FT& bmin, const FT& s, double tol,
                  FT& result) {
  struct Line {
    FT p, q, r;  // p a + q b = r
  };
  std::vector<Line> lines{{FT(1), FT(0), amin}, {FT(0), FT(1), bmin}, {FT(1), FT(1), s}};
  const std::size_t nedge = 3;
  for (std::size_t k = 0; k < f.size(); ++k)
    for (std::size_t l = k + 1; l < f.size(); ++l)
      lines.push_back({FT(f[k].rho - f[l].rho), FT(f[k].sigma - f[l].sigma), FT(f[l].tau - f[k].tau)});
  bool have = false, ok = true;
  const auto consider = [&](const FT& a, const FT& b) {
    if (!possibly_le(amin, a, tol) || !possibly_le(bmin, b, tol) || !possibly_le(FT(a + b), s, tol)) return;
    FT v = f[0](a, b);
    for (std::size_t k = 1; k < f.size(); ++k) v = min_of(v, f[k](a, b));
    result = have ? max_of(result, v) : v;
    have = true;
  };
  const auto intersect = [&](const Line& x, const Line& y) {
    const FT det = FT(FT(x.p * y.q) - FT(y.p * x.q));
    const Certified_sign det_sign = certified_sign(det);
    if (certainly(det_sign, Certified_sign::zero)) return;
    if (is_interval_v<FT> && !is_certain(det_sign)) {  // cannot tell: give up the tent
      ok = false;
      return;
    }
    consider(Tr::quotient(FT(FT(x.r * y.q) - FT(y.r * x.q)), det), Tr::quotient(FT(FT(x.p * y.r) - FT(y.p * x.r)), det));
  };
  for (std::size_t i = 0; i < nedge; ++i)
    for (std::size_t j = i + 1; j < lines.size(); ++j) intersect(lines[i], lines[j]);
  // three equal functions: two of the pair lines through a common k
  for (std::size_t k = 0; k < f.size(); ++k)
    for (std::size_t l = k + 1; l < f.size(); ++l)
      for (std::size_t m = l + 1; m < f.size(); ++m)
        intersect(Line{FT(f[k].rho - f[l].rho), FT(f[k].sigma - f[l].sigma), FT(f[l].tau - f[k].tau)},
                  Line{FT(f[k].rho - f[m].rho), FT(f[k].sigma - f[m].sigma), FT(f[m].tau - f[k].tau)});
  return ok && have;
}

}  // namespace relgeo::internal
