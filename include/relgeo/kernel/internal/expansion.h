// relgeo/kernel/internal/expansion.h — exact arithmetic on floating-point
// expansions (Shewchuk, "Adaptive Precision Floating-Point Arithmetic and
// Fast Robust Geometric Predicates", Discrete Comput. Geom. 18, 1997).
//
// An expansion is a sum of doubles x_0 + ... + x_{n-1}, stored in order of
// increasing magnitude, no component zero, and nonoverlapping (the lowest set
// bit of each component lies above the highest set bit of the one before).
// The empty expansion is 0. Nonoverlapping makes the largest component
// dominate the others' sum, so the sign of the value is the sign of the last
// component. Sums, scalings and products are computed exactly from the
// error-free transformations two_sum and two_product (core/internal/error_free.h):
//   grow   e + b          n + 1 components at most
//   sum    e + f          n + m
//   scale  e * b          2n
//   product e * f         2nm
// with zero elimination (a zero component is dropped as it appears).
//
// Preconditions, which callers establish from the magnitudes of their inputs
// (see expansion_orientation_3.h for a derivation):
//  * round to nearest, ties to even, no flush-to-zero or denormals-are-zero:
//    run in a Default_fp_environment (Shewchuk's proof of the merging sum
//    needs ties to even);
//  * no intermediate result overflows;
//  * every two_product is exact: its factors' lowest set bits have exponents
//    summing to -1074 or more (then the product and its error are multiples
//    of 2^-1074 and representable, subnormal or not). Sums are always exact.
//
// Storage is a fixed-capacity array on the stack; capacities follow the
// bounds above at compile time (Expansion<2> * Expansion<8> is an
// Expansion<32>), sizes at run time are usually much smaller. compress()
// shortens an expansion without changing its value.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/errors.h"
#include "relgeo/core/internal/error_free.h"

namespace relgeo::internal {

/// s = fl(a + b) and its exact error, when |a| >= |b| or a == 0 (Dekker's
/// Fast-Two-Sum: 3 operations instead of 6).
inline Two_terms fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

namespace expansion {

// The kernels of the operations, on arrays: h receives the result (it must
// not overlap the inputs and must hold the component bound of the operation);
// the return value is the number of components written.

/// h = e + b (Shewchuk's Grow-Expansion with zero elimination).
inline std::size_t grow(const double* e, std::size_t n, double b, double* h) {
  std::size_t k = 0;
  double q = b;
  for (std::size_t i = 0; i < n; ++i) {
    const Two_terms t = two_sum(q, e[i]);
    q = t.value;
    if (t.error != 0) h[k++] = t.error;
  }
  if (q != 0) h[k++] = q;
  return k;
}

/// h = e + f_sign * f (f_sign = 1 or -1): the components of both merged by
/// magnitude, then added from the smallest up, each error kept (Shewchuk's
/// Fast-Expansion-Sum with zero elimination; every step is a two_sum, so it
/// is exact without the magnitude condition of Fast-Two-Sum).
inline std::size_t sum(const double* e, std::size_t n, const double* f, std::size_t m, double* h,
                       double f_sign = 1.0) {
  if (n == 0 || m == 0) {
    const double* g = n == 0 ? f : e;
    const std::size_t len = n == 0 ? m : n;
    const double s = n == 0 ? f_sign : 1.0;
    for (std::size_t i = 0; i < len; ++i) h[i] = s * g[i];
    return len;
  }
  std::size_t i = 0, j = 0, k = 0;
  // The next component in order of magnitude (ties: e first).
  const auto next = [&]() -> double {
    if (j == m || (i < n && std::abs(e[i]) <= std::abs(f[j]))) return e[i++];
    return f_sign * f[j++];
  };
  double q = next();
  while (i < n || j < m) {
    const Two_terms t = two_sum(q, next());
    q = t.value;
    if (t.error != 0) h[k++] = t.error;
  }
  if (q != 0) h[k++] = q;
  return k;
}

/// h = e * b (Shewchuk's Scale-Expansion with zero elimination).
inline std::size_t scale(const double* e, std::size_t n, double b, double* h) {
  if (n == 0 || b == 0) return 0;
  std::size_t k = 0;
  Two_terms p = two_product(e[0], b);
  double q = p.value;
  if (p.error != 0) h[k++] = p.error;
  for (std::size_t i = 1; i < n; ++i) {
    p = two_product(e[i], b);
    const Two_terms s = two_sum(q, p.error);
    if (s.error != 0) h[k++] = s.error;
    const Two_terms r = fast_two_sum(p.value, s.value);  // |p.value| >= |s.value| (Shewchuk, Thm. 19)
    if (r.error != 0) h[k++] = r.error;
    q = r.value;
  }
  if (q != 0) h[k++] = q;
  return k;
}

/// h = e * f (n and m components), the sum of e scaled by each component of
/// f. Work space: `scaled` for 2n and, when m > 1, `spare` for 2nm doubles;
/// h has room for 2nm.
inline std::size_t product(const double* e, std::size_t n, const double* f, std::size_t m, double* h,
                           double* scaled, double* spare) {
  if (m == 1) return scale(e, n, f[0], h);
  // The partial sums alternate between h and spare, starting so that the
  // last lands in h.
  double* into = m % 2 ? h : spare;
  double* from = m % 2 ? spare : h;
  std::size_t k = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t s = scale(e, n, f[i], scaled);
    k = sum(from, k, scaled, s, into);
    std::swap(into, from);
  }
  return k;
}

/// h = e with every component negated.
inline std::size_t negate(const double* e, std::size_t n, double* h) {
  for (std::size_t i = 0; i < n; ++i) h[i] = -e[i];
  return n;
}

/// h = e, shortened: adjacent components combined where their sum is exact
/// (Shewchuk's Compress). \pre e is a nonoverlapping expansion without zeros.
/// h may be e (each pass writes only components it has already read).
inline std::size_t compress(const double* e, std::size_t n, double* h) {
  if (n == 0) return 0;
  // Downward pass, from the largest component: a running sum q, stored at
  // the top of h whenever the next component does not join it exactly.
  std::size_t bottom = n - 1;
  double q = e[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) {
    const Two_terms t = fast_two_sum(q, e[i]);
    if (t.error != 0) {
      h[bottom--] = t.value;  // at most n - 1 stores: bottom stays >= 0
      q = t.error;
    } else {
      q = t.value;
    }
  }
  // Upward pass over the stored sums, from the smallest, into the bottom of h.
  std::size_t top = 0;
  for (std::size_t i = bottom + 1; i < n; ++i) {
    const Two_terms t = fast_two_sum(h[i], q);
    if (t.error != 0) h[top++] = t.error;
    q = t.value;
  }
  if (q != 0) h[top++] = q;
  return top;
}

}  // namespace expansion

/// \brief An exact sum of at most Capacity doubles (see the file comment).
template <std::size_t Capacity>
class Expansion {
  static_assert(Capacity > 0);

 public:
  static constexpr std::size_t capacity = Capacity;

  Expansion() = default;  ///< zero
  /// The double v (exactly).
  explicit Expansion(double v) {
    if (v != 0) data_[size_++] = v;
  }
  /// The exact sum value + error of an error-free transformation.
  explicit Expansion(Two_terms t)
    requires(Capacity >= 2)
  {
    if (t.error != 0) data_[size_++] = t.error;
    if (t.value != 0) data_[size_++] = t.value;
  }
  /// An expansion of another capacity, copied. \pre e.size() <= Capacity
  /// (checked when C > Capacity: Precondition_violation).
  template <std::size_t C>
    requires(C != Capacity)
  explicit Expansion(const Expansion<C>& e) {
    if constexpr (C > Capacity)
      if (e.size() > Capacity) throw Precondition_violation("Expansion: more components than the capacity");
    for (double x : e) data_[size_++] = x;
  }

  std::size_t size() const { return size_; }
  bool is_zero() const { return size_ == 0; }
  double operator[](std::size_t i) const { return data_[i]; }
  const double* begin() const { return data_.data(); }
  const double* end() const { return data_.data() + size_; }

  /// The exact sign of the value: that of the largest component.
  Certified_sign sign() const {
    return size_ == 0 ? Certified_sign::zero
                      : (data_[size_ - 1] > 0 ? Certified_sign::positive : Certified_sign::negative);
  }
  /// The components added in floating point, from the smallest up: within
  /// (size - 1) u of the sum of their magnitudes (magnitude()).
  double estimate() const {
    double s = 0;
    for (std::size_t i = 0; i < size_; ++i) s += data_[i];
    return s;
  }
  /// The sum of the components' magnitudes, in floating point.
  double magnitude() const {
    double s = 0;
    for (std::size_t i = 0; i < size_; ++i) s += std::abs(data_[i]);
    return s;
  }
  /// The same value in fewer components (expansion::compress).
  void compress() {
    std::array<double, Capacity> h;
    size_ = expansion::compress(data_.data(), size_, h.data());
    for (std::size_t i = 0; i < size_; ++i) data_[i] = h[i];
  }

  Expansion operator-() const {
    Expansion r;
    r.size_ = expansion::negate(data_.data(), size_, r.data_.data());
    return r;
  }

  /// Writes through an operation kernel of namespace expansion (used by the
  /// operators below).
  template <class Operation>
  static Expansion computed(Operation op) {
    Expansion r;
    r.size_ = op(r.data_.data());
    return r;
  }

 private:
  std::array<double, Capacity> data_;  // [0, size_) used; the rest is never read
  std::size_t size_ = 0;
};

template <std::size_t A>
Expansion<A + 1> operator+(const Expansion<A>& e, double b) {
  return Expansion<A + 1>::computed([&](double* h) { return expansion::grow(e.begin(), e.size(), b, h); });
}
template <std::size_t A>
Expansion<A + 1> operator-(const Expansion<A>& e, double b) {
  return e + (-b);
}
template <std::size_t A, std::size_t B>
Expansion<A + B> operator+(const Expansion<A>& e, const Expansion<B>& f) {
  return Expansion<A + B>::computed(
      [&](double* h) { return expansion::sum(e.begin(), e.size(), f.begin(), f.size(), h); });
}
template <std::size_t A, std::size_t B>
Expansion<A + B> operator-(const Expansion<A>& e, const Expansion<B>& f) {
  return e + (-f);
}
template <std::size_t A>
Expansion<2 * A> operator*(const Expansion<A>& e, double b) {
  return Expansion<2 * A>::computed([&](double* h) { return expansion::scale(e.begin(), e.size(), b, h); });
}
/// e * f as the sum of e scaled by each component of f.
template <std::size_t A, std::size_t B>
Expansion<2 * A * B> operator*(const Expansion<A>& e, const Expansion<B>& f) {
  return Expansion<2 * A * B>::computed([&](double* h) {
    std::array<double, 2 * A> scaled;
    std::array<double, 2 * A * B> spare;
    return expansion::product(e.begin(), e.size(), f.begin(), f.size(), h, scaled.data(), spare.data());
  });
}

/// a + b, a - b, a * b exactly as two-component expansions.
inline Expansion<2> exact_sum(double a, double b) { return Expansion<2>(two_sum(a, b)); }
inline Expansion<2> exact_difference(double a, double b) { return Expansion<2>(two_diff(a, b)); }
inline Expansion<2> exact_product(double a, double b) { return Expansion<2>(two_product(a, b)); }

}  // namespace relgeo::internal
