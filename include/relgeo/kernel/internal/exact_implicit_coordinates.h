// relgeo/kernel/internal/exact_implicit_coordinates.h — the exact rational
// coordinates of an LPI or TPI point of double inputs: how
// Filtered_exact_kernel's points become Exact_kernel's (the exact Boolean
// converts every new vertex this way).
//
// The inputs are scaled by one power of two to integers, the homogeneous
// coordinates of implicit_coordinates.h formed (an LPI point's in GMP
// integers that each thread keeps between calls: no allocation once they
// have grown), and each X / W reduced. The reduction is most of the cost: a
// gcd of two 200-bit numbers takes GMP about 1.3 us. For an LPI point
// X = W p + lambda a, so
//   gcd(X, W) = gcd(lambda a, W) = g gcd(a, W / g),  g = gcd(lambda, W)
// (lambda / g and W / g are coprime): one gcd of full size and three
// against a difference of two inputs (one limb when their exponents are
// close) instead of three of full size. On CGAL's elephant against its
// rotated copy (1,029 LPI points) the conversion took 9.2 ms with
// mpz_class expressions and mpq canonicalisation, 4.0 ms this way.
#pragma once

#include <gmpxx.h>

#include <array>
#include <climits>
#include <cstddef>
#include <span>

#include "relgeo/core/errors.h"
#include "relgeo/kernel/internal/filtered_predicate.h"
#include "relgeo/kernel/internal/implicit_coordinates.h"
#include "relgeo/kernel/point.h"

namespace relgeo::internal {

class Exact_implicit_coordinates {
 public:
  /// The point where the line through v[0], v[1] crosses the plane through
  /// v[2], v[3], v[4]. \pre finite inputs; \throws Precondition_violation
  /// when the line is parallel to the plane (W = 0: no such point). The
  /// formula of lpi_coordinates (implicit_coordinates.h), each step into
  /// the workspace: with mpz_class expressions its temporaries took a
  /// third of the time.
  static std::array<mpq_class, 3> lpi(std::span<const Point_3<double>, 5> v) {
    Workspace& s = workspace();
    const int emin = s.scale(v);
    for (int k = 0; k < 3; ++k) {
      mpz_sub(s.u[k].get_mpz_t(), s.in(3, k), s.in(2, k));  // s - r
      mpz_sub(s.v[k].get_mpz_t(), s.in(4, k), s.in(2, k));  // t - r
      mpz_sub(s.a[k].get_mpz_t(), s.in(1, k), s.in(0, k));  // q - p
      mpz_sub(s.d[k].get_mpz_t(), s.in(2, k), s.in(0, k));  // r - p
    }
    cross(s.n.data(), s.u.data(), s.v.data());
    dot(s.w, s.n.data(), s.a.data());
    dot(s.lambda, s.n.data(), s.d.data());
    if (sgn(s.w) == 0) throw Precondition_violation("exact LPI coordinates: the line is parallel to the plane");
    mpz_gcd(s.g_lambda.get_mpz_t(), s.lambda.get_mpz_t(), s.w.get_mpz_t());
    mpz_divexact(s.w_reduced.get_mpz_t(), s.w.get_mpz_t(), s.g_lambda.get_mpz_t());
    std::array<mpq_class, 3> c;
    for (int k = 0; k < 3; ++k) {
      mpz_mul(s.x[k].get_mpz_t(), s.w.get_mpz_t(), s.in(0, k));
      mpz_addmul(s.x[k].get_mpz_t(), s.lambda.get_mpz_t(), s.a[k].get_mpz_t());
      mpz_gcd(s.g.get_mpz_t(), s.a[k].get_mpz_t(), s.w_reduced.get_mpz_t());
      mpz_mul(s.g.get_mpz_t(), s.g.get_mpz_t(), s.g_lambda.get_mpz_t());
      set_reduced(c[k], s.x[k], s.w, s.g, emin);
    }
    return c;
  }

  /// The point common to the planes through v[3i], v[3i+1], v[3i+2], i = 0,
  /// 1, 2. \pre finite inputs; \throws Precondition_violation when the
  /// planes meet in no single point (W = 0). Rare in the Booleans: the
  /// formula of implicit_coordinates.h as it stands, three full gcds.
  static std::array<mpq_class, 3> tpi(std::span<const Point_3<double>, 9> v) {
    std::array<double, 27> values;
    for (std::size_t i = 0; i < 9; ++i) values[3 * i] = v[i].x, values[3 * i + 1] = v[i].y, values[3 * i + 2] = v[i].z;
    const Scaled_integers to_integer(values);
    std::array<Point_3<mpz_class>, 9> p;
    for (std::size_t i = 0; i < 9; ++i) p[i] = {to_integer(v[i].x), to_integer(v[i].y), to_integer(v[i].z)};
    const Homogeneous_3<mpz_class> h = tpi_coordinates(p);
    if (sgn(h.w) == 0) throw Precondition_violation("exact TPI coordinates: the planes meet in no single point");
    std::array<mpq_class, 3> c;
    mpz_class g;
    for (int k = 0; k < 3; ++k) {
      mpz_gcd(g.get_mpz_t(), h[k].get_mpz_t(), h.w.get_mpz_t());
      set_reduced(c[k], h[k], h.w, g, to_integer.emin());
    }
    return c;
  }

 private:
  // The integers of one LPI conversion; `inputs` holds the scaled
  // coordinates, three per defining point.
  struct Workspace {
    std::array<mpz_class, 15> inputs;
    std::array<mpz_class, 3> u, v, a, d, n, x;
    mpz_class w, lambda, g, g_lambda, w_reduced;

    mpz_srcptr in(int point, int axis) const { return inputs[3 * point + axis].get_mpz_t(); }
    // inputs = the points' coordinates as integers scaled by 2^-emin;
    // returns emin (INT_MAX when all are 0).
    int scale(std::span<const Point_3<double>, 5> points) {
      std::array<double, 15> values;
      for (std::size_t i = 0; i < 5; ++i)
        values[3 * i] = points[i].x, values[3 * i + 1] = points[i].y, values[3 * i + 2] = points[i].z;
      const Scaled_integers to_integer(values);
      for (std::size_t k = 0; k < values.size(); ++k) to_integer.set(inputs[k].get_mpz_t(), values[k]);
      return to_integer.emin();
    }
  };
  static Workspace& workspace() {
    thread_local Workspace s;
    return s;
  }

  static void cross(mpz_class* out, const mpz_class* a, const mpz_class* b) {
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      mpz_mul(out[k].get_mpz_t(), a[i].get_mpz_t(), b[j].get_mpz_t());
      mpz_submul(out[k].get_mpz_t(), a[j].get_mpz_t(), b[i].get_mpz_t());
    }
  }
  static void dot(mpz_class& out, const mpz_class* a, const mpz_class* b) {
    mpz_mul(out.get_mpz_t(), a[0].get_mpz_t(), b[0].get_mpz_t());
    mpz_addmul(out.get_mpz_t(), a[1].get_mpz_t(), b[1].get_mpz_t());
    mpz_addmul(out.get_mpz_t(), a[2].get_mpz_t(), b[2].get_mpz_t());
  }
  // q = (x / g) / (w / g) 2^emin, canonical: g = gcd(x, w) > 0, and x / w
  // has degree 1 in the scaled inputs.
  static void set_reduced(mpq_class& q, const mpz_class& x, const mpz_class& w, const mpz_class& g, int emin) {
    mpq_ptr r = q.get_mpq_t();
    mpz_divexact(mpq_numref(r), x.get_mpz_t(), g.get_mpz_t());
    mpz_divexact(mpq_denref(r), w.get_mpz_t(), g.get_mpz_t());
    if (mpz_sgn(mpq_denref(r)) < 0) {
      mpz_neg(mpq_numref(r), mpq_numref(r));
      mpz_neg(mpq_denref(r), mpq_denref(r));
    }
    if (emin == INT_MAX) return;
    if (emin > 0)
      mpq_mul_2exp(r, r, static_cast<mp_bitcnt_t>(emin));
    else if (emin < 0)
      mpq_div_2exp(r, r, static_cast<mp_bitcnt_t>(-emin));
  }
};

}  // namespace relgeo::internal
