#include "implicit_oracle.h"

#include <utility>

namespace relgeo::test {
namespace {

using Rational_point = std::array<mpq_class, 3>;

Certified_sign sign_of(const mpz_class& v) { return static_cast<Certified_sign>(sgn(v)); }

Rational_point exact(const std::array<double, 3>& p) { return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])}; }
Rational_point minus(const Rational_point& a, const Rational_point& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

// Over the least common denominator (positive: GMP keeps denominators so).
Exact_point common_denominator(const Rational_point& p) {
  Exact_point e;
  mpz_lcm(e.denominator.get_mpz_t(), p[0].get_den_mpz_t(), p[1].get_den_mpz_t());
  mpz_lcm(e.denominator.get_mpz_t(), e.denominator.get_mpz_t(), p[2].get_den_mpz_t());
  for (int k = 0; k < 3; ++k) e.numerators[k] = p[k].get_num() * (e.denominator / p[k].get_den());
  return e;
}

// (b - a) scaled by the positive a.W b.W, in integers: the signs of the
// predicates' formulas on such differences are those on the exact ones.
std::array<mpz_class, 3> scaled_difference(const Exact_point& b, const Exact_point& a) {
  std::array<mpz_class, 3> d;
  for (int k = 0; k < 3; ++k) d[k] = b.numerators[k] * a.denominator - a.numerators[k] * b.denominator;
  return d;
}

// Solves M x = rhs (3x3) by Gaussian elimination with row exchanges; nullopt
// when M is singular.
std::optional<Rational_point> solve(std::array<std::array<mpq_class, 3>, 3> m, Rational_point rhs) {
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
  Rational_point x;
  for (int row = 2; row >= 0; --row) {
    mpq_class v = rhs[row];
    for (int k = row + 1; k < 3; ++k) v -= m[row][k] * x[k];
    x[row] = v / m[row][row];
  }
  return x;
}

std::optional<Rational_point> rational_point(const analysis::Implicit_point_definition& d) {
  switch (d.kind) {
    case Implicit_point_kind::explicit_point: return exact(d.points[0]);
    case Implicit_point_kind::lpi: {
      // alpha (s - r) + beta (t - r) - lambda (q - p) = p - r.
      const Rational_point p = exact(d.points[0]), q = exact(d.points[1]), r = exact(d.points[2]),
                           s = exact(d.points[3]), t = exact(d.points[4]);
      const Rational_point e1 = minus(s, r), e2 = minus(t, r), a = minus(q, p), rhs = minus(p, r);
      std::array<std::array<mpq_class, 3>, 3> m;
      for (int i = 0; i < 3; ++i) m[i] = {e1[i], e2[i], -a[i]};
      const auto x = solve(m, rhs);
      if (!x) return std::nullopt;
      return Rational_point{p[0] + (*x)[2] * a[0], p[1] + (*x)[2] * a[1], p[2] + (*x)[2] * a[2]};
    }
    default: {
      std::array<std::array<mpq_class, 3>, 3> m;
      Rational_point rhs;
      for (int i = 0; i < 3; ++i) {
        const Rational_point a = exact(d.points[3 * i]), u = minus(exact(d.points[3 * i + 1]), a),
                             v = minus(exact(d.points[3 * i + 2]), a);
        m[i] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        rhs[i] = m[i][0] * a[0] + m[i][1] * a[1] + m[i][2] * a[2];
      }
      return solve(m, rhs);
    }
  }
}

}  // namespace

mpq_class Exact_point::coordinate(int axis) const {
  mpq_class c(numerators[axis], denominator);
  c.canonicalize();
  return c;
}

std::optional<Exact_point> oracle_point(const analysis::Implicit_point_definition& d) {
  const auto p = rational_point(d);
  if (!p) return std::nullopt;
  return common_denominator(*p);
}

Certified_sign oracle_orientation_3(const Exact_point& p, const Exact_point& q, const Exact_point& r,
                                    const Exact_point& s) {
  const auto a = scaled_difference(q, p), b = scaled_difference(r, p), c = scaled_difference(s, p);
  const mpz_class v =
      a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  return sign_of(v);
}

Certified_sign oracle_orientation_2(const Exact_point& p, const Exact_point& q, const Exact_point& r, int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  // (q - p) x (r - p) in the kept axes, each difference scaled by a positive
  // factor (exact_oracle.cpp expands the same determinant).
  const auto a = scaled_difference(q, p), b = scaled_difference(r, p);
  const mpz_class v = a[i] * b[j] - a[j] * b[i];
  return sign_of(v);
}

Certified_sign oracle_compare_xyz(const Exact_point& a, const Exact_point& b) {
  for (int k = 0; k < 3; ++k) {
    const mpz_class d = a.numerators[k] * b.denominator - b.numerators[k] * a.denominator;
    if (const int c = sgn(d); c != 0) return c < 0 ? Certified_sign::negative : Certified_sign::positive;
  }
  return Certified_sign::zero;
}

}  // namespace relgeo::test
