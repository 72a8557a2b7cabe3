#include "exact_oracle.h"

#include <gmpxx.h>

#include <cmath>

#include "relgeo/core/dyadic.h"

namespace relgeo::test {
namespace {

Certified_sign sign_of_mpq(const mpq_class& v) {
  const int s = sgn(v);
  return s > 0 ? Certified_sign::positive : (s < 0 ? Certified_sign::negative : Certified_sign::zero);
}

// Expanded form: qx ry - qx py - px ry - qy rx + qy px + py rx (the pivot-free
// expansion of (qx-px)(ry-py) - (qy-py)(rx-px)).
mpq_class orient2_expanded(double px, double py, double qx, double qy, double rx, double ry) {
  const mpq_class Px(px), Py(py), Qx(qx), Qy(qy), Rx(rx), Ry(ry);
  mpq_class v = Qx * Ry;
  v -= Qx * Py;
  v -= Px * Ry;
  v -= Qy * Rx;
  v += Qy * Px;
  v += Py * Rx;
  return v;
}

}  // namespace

Certified_sign oracle_orientation_2(const analysis::Orientation_2_case& c) {
  return sign_of_mpq(orient2_expanded(c.px, c.py, c.qx, c.qy, c.rx, c.ry));
}

Certified_sign oracle_orientation_3(const analysis::Orientation_3_case& c) {
  // (q - p) . ((r - p) x (s - p))
  std::array<mpq_class, 9> d;
  for (int k = 0; k < 3; ++k) {
    const mpq_class p(c.c[k]);
    d[k] = mpq_class(c.c[3 + k]) - p;
    d[3 + k] = mpq_class(c.c[6 + k]) - p;
    d[6 + k] = mpq_class(c.c[9 + k]) - p;
  }
  const mpq_class cx = d[4] * d[8] - d[5] * d[7];
  const mpq_class cy = d[5] * d[6] - d[3] * d[8];
  const mpq_class cz = d[3] * d[7] - d[4] * d[6];
  return sign_of_mpq(d[0] * cx + d[1] * cy + d[2] * cz);
}

Certified_sign oracle_coplanar_orientation_3(const std::array<double, 9>& v) {
  const int planes[3][2] = {{0, 1}, {1, 2}, {0, 2}};
  Certified_sign s = Certified_sign::zero;
  for (const auto& pl : planes) {
    s = sign_of_mpq(orient2_expanded(v[pl[0]], v[pl[1]], v[3 + pl[0]], v[3 + pl[1]],
                                     v[6 + pl[0]], v[6 + pl[1]]));
    if (s != Certified_sign::zero) return s;
  }
  return s;
}

Certified_sign oracle_compare_xy(double x1, double y1, double x2, double y2) {
  const int cx = cmp(mpq_class(x1), mpq_class(x2));
  const int c = cx != 0 ? cx : cmp(mpq_class(y1), mpq_class(y2));
  return c > 0 ? Certified_sign::positive : (c < 0 ? Certified_sign::negative : Certified_sign::zero);
}

bool encloses(const Interval& i, const mpq_class& v) {
  if (std::isnan(i.inf()) || std::isnan(i.sup())) return true;  // NaN claims nothing
  const bool lo_ok = std::isinf(i.inf()) ? i.inf() < 0 : exact_rational(i.inf()) <= v;
  const bool hi_ok = std::isinf(i.sup()) ? i.sup() > 0 : v <= exact_rational(i.sup());
  return lo_ok && hi_ok;
}

}  // namespace relgeo::test
