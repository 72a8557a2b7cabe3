#include "implicit_oracle.h"

#include <utility>

namespace relgeo::test {
namespace {

Certified_sign sign_of_mpq(const mpq_class& v) { return static_cast<Certified_sign>(sgn(v)); }

Exact_point exact(const std::array<double, 3>& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }
Exact_point minus(const Exact_point& a, const Exact_point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// Solves M x = rhs (3x3) by Gaussian elimination with row exchanges; nullopt
// when M is singular.
std::optional<Exact_point> solve(std::array<std::array<mpq_class, 3>, 3> m, Exact_point rhs) {
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    while (pivot < 3 && sgn(m[pivot][col]) == 0) ++pivot;
    if (pivot == 3) return std::nullopt;
    std::swap(m[pivot], m[col]);
    std::swap(rhs[pivot], rhs[col]);
    for (int row = col + 1; row < 3; ++row) {
      if (sgn(m[row][col]) == 0) continue;
      const mpq_class f = m[row][col] / m[col][col];
      for (int k = col; k < 3; ++k) m[row][k] -= f * m[col][k];
      rhs[row] -= f * rhs[col];
    }
  }
  Exact_point x;
  for (int row = 2; row >= 0; --row) {
    mpq_class v = rhs[row];
    for (int k = row + 1; k < 3; ++k) v -= m[row][k] * x[k];
    x[row] = v / m[row][row];
  }
  return x;
}

}  // namespace

std::optional<Exact_point> oracle_point(const analysis::Implicit_point_definition& d) {
  switch (d.kind) {
    case Implicit_point_kind::explicit_point: return exact(d.points[0]);
    case Implicit_point_kind::lpi: {
      // alpha (s - r) + beta (t - r) - lambda (q - p) = p - r.
      const Exact_point p = exact(d.points[0]), q = exact(d.points[1]), r = exact(d.points[2]),
                        s = exact(d.points[3]), t = exact(d.points[4]);
      const Exact_point e1 = minus(s, r), e2 = minus(t, r), a = minus(q, p), rhs = minus(p, r);
      std::array<std::array<mpq_class, 3>, 3> m;
      for (int i = 0; i < 3; ++i) m[i] = {e1[i], e2[i], -a[i]};
      const auto x = solve(m, rhs);
      if (!x) return std::nullopt;
      return Exact_point{p[0] + (*x)[2] * a[0], p[1] + (*x)[2] * a[1], p[2] + (*x)[2] * a[2]};
    }
    default: {
      std::array<std::array<mpq_class, 3>, 3> m;
      Exact_point rhs;
      for (int i = 0; i < 3; ++i) {
        const Exact_point a = exact(d.points[3 * i]), u = minus(exact(d.points[3 * i + 1]), a),
                          v = minus(exact(d.points[3 * i + 2]), a);
        m[i] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        rhs[i] = m[i][0] * a[0] + m[i][1] * a[1] + m[i][2] * a[2];
      }
      return solve(m, rhs);
    }
  }
}

Certified_sign oracle_orientation_3(const Exact_point& p, const Exact_point& q, const Exact_point& r,
                                    const Exact_point& s) {
  const Exact_point a = minus(q, p), b = minus(r, p), c = minus(s, p);
  const mpq_class v = a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                      a[2] * (b[0] * c[1] - b[1] * c[0]);
  return sign_of_mpq(v);
}

Certified_sign oracle_orientation_2(const Exact_point& p, const Exact_point& q, const Exact_point& r, int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  // Expanded: qi rj - qi pj - pi rj - qj ri + qj pi + pj ri.
  const mpq_class v = q[i] * r[j] - q[i] * p[j] - p[i] * r[j] - q[j] * r[i] + q[j] * p[i] + p[j] * r[i];
  return sign_of_mpq(v);
}

Certified_sign oracle_compare_xyz(const Exact_point& a, const Exact_point& b) {
  for (int k = 0; k < 3; ++k)
    if (const int c = cmp(a[k], b[k]); c != 0) return c < 0 ? Certified_sign::negative : Certified_sign::positive;
  return Certified_sign::zero;
}

}  // namespace relgeo::test
