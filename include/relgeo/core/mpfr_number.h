// relgeo/core/mpfr_number.h — MPFR values as RAII types: Mpfr_number<Bits>,
// a number type with a compile-time precision (the kernels, linear systems
// and subdivision at a chosen precision), and Mpfr_value, a scratch value
// with a run-time precision (the exact and directed-rounded computations of
// the error measures).
//
// Boost.Multiprecision's mpfr_float_backend is parametrised by decimal digits;
// precision sweeps need the exact number of significand bits. Arithmetic
// rounds to nearest, ties to even, like IEEE. Each type owns its mpfr_t: no
// caller pairs mpfr_init2 with mpfr_clear, and `get()` on a non-const value
// is the writable pointer (no const_cast anywhere).
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <utility>

namespace relgeo {

/// \brief An mpfr_t with a precision chosen at run time (owned, movable).
class Mpfr_value {
 public:
  explicit Mpfr_value(mpfr_prec_t bits) { mpfr_init2(v_, bits); }
  Mpfr_value(mpfr_prec_t bits, double d) : Mpfr_value(bits) { mpfr_set_d(v_, d, MPFR_RNDN); }
  Mpfr_value(const Mpfr_value& o) : Mpfr_value(mpfr_get_prec(o.v_)) { mpfr_set(v_, o.v_, MPFR_RNDN); }
  Mpfr_value(Mpfr_value&& o) noexcept : Mpfr_value(mpfr_get_prec(o.v_)) { mpfr_swap(v_, o.v_); }
  Mpfr_value& operator=(const Mpfr_value& o) {
    if (this != &o) mpfr_set(v_, o.v_, MPFR_RNDN);
    return *this;
  }
  Mpfr_value& operator=(Mpfr_value&& o) noexcept {
    mpfr_swap(v_, o.v_);
    return *this;
  }
  ~Mpfr_value() { mpfr_clear(v_); }

  mpfr_ptr get() noexcept { return v_; }
  mpfr_srcptr get() const noexcept { return v_; }
  mpfr_prec_t precision() const noexcept { return mpfr_get_prec(v_); }

 private:
  mpfr_t v_;
};

/// \brief An MPFR float of exactly `Bits` significand bits, rounding to
/// nearest: the number type of Mpfr_kernel<Bits>, and a scalar of the linear
/// area (Eigen::NumTraits in linear/scalar_traits.h).
template <int Bits>
class Mpfr_number {
  static_assert(Bits >= MPFR_PREC_MIN && Bits <= 1 << 20, "unsupported MPFR precision");

 public:
  static constexpr int precision = Bits;

  Mpfr_number() { mpfr_init2(v_, Bits), mpfr_set_zero(v_, 1); }
  /// Correctly rounded to Bits (exact for Bits >= 53).
  Mpfr_number(double d) { mpfr_init2(v_, Bits), mpfr_set_d(v_, d, MPFR_RNDN); }  // NOLINT: numeric conversion
  Mpfr_number(int i) { mpfr_init2(v_, Bits), mpfr_set_si(v_, i, MPFR_RNDN); }  // NOLINT
  /// The rational q rounded to `Bits` in direction `rnd`.
  explicit Mpfr_number(const mpq_class& q, mpfr_rnd_t rnd = MPFR_RNDN) {
    mpfr_init2(v_, Bits), mpfr_set_q(v_, q.get_mpq_t(), rnd);
  }
  /// Any MPFR value rounded to `Bits` in direction `rnd`.
  explicit Mpfr_number(mpfr_srcptr x, mpfr_rnd_t rnd = MPFR_RNDN) { mpfr_init2(v_, Bits), mpfr_set(v_, x, rnd); }
  Mpfr_number(const Mpfr_number& o) { mpfr_init2(v_, Bits), mpfr_set(v_, o.v_, MPFR_RNDN); }
  Mpfr_number(Mpfr_number&& o) noexcept {
    mpfr_init2(v_, Bits);
    mpfr_swap(v_, o.v_);
  }
  Mpfr_number& operator=(const Mpfr_number& o) {
    mpfr_set(v_, o.v_, MPFR_RNDN);
    return *this;
  }
  Mpfr_number& operator=(Mpfr_number&& o) noexcept {
    mpfr_swap(v_, o.v_);
    return *this;
  }
  ~Mpfr_number() { mpfr_clear(v_); }

  /// Rounded to the nearest double (MPFR's exponent range: see
  /// core/rounding.h for the correctly rounded conversion with subnormals).
  double to_double() const { return mpfr_get_d(v_, MPFR_RNDN); }
  int sign() const { return mpfr_sgn(v_); }
  bool is_nan() const { return mpfr_nan_p(v_) != 0; }
  bool is_finite() const { return mpfr_number_p(v_) != 0; }
  bool is_zero() const { return mpfr_zero_p(v_) != 0; }
  mpfr_srcptr get() const noexcept { return v_; }
  mpfr_ptr get() noexcept { return v_; }

  friend Mpfr_number operator+(const Mpfr_number& a, const Mpfr_number& b) { return apply(mpfr_add, a, b); }
  friend Mpfr_number operator-(const Mpfr_number& a, const Mpfr_number& b) { return apply(mpfr_sub, a, b); }
  friend Mpfr_number operator*(const Mpfr_number& a, const Mpfr_number& b) { return apply(mpfr_mul, a, b); }
  friend Mpfr_number operator/(const Mpfr_number& a, const Mpfr_number& b) { return apply(mpfr_div, a, b); }
  friend Mpfr_number operator-(const Mpfr_number& a) {
    Mpfr_number r;
    mpfr_neg(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  Mpfr_number& operator+=(const Mpfr_number& b) { return update(mpfr_add, b); }
  Mpfr_number& operator-=(const Mpfr_number& b) { return update(mpfr_sub, b); }
  Mpfr_number& operator*=(const Mpfr_number& b) { return update(mpfr_mul, b); }
  Mpfr_number& operator/=(const Mpfr_number& b) { return update(mpfr_div, b); }

  friend bool operator==(const Mpfr_number& a, const Mpfr_number& b) { return mpfr_equal_p(a.v_, b.v_); }
  friend bool operator!=(const Mpfr_number& a, const Mpfr_number& b) { return !(a == b); }
  friend bool operator<(const Mpfr_number& a, const Mpfr_number& b) { return mpfr_less_p(a.v_, b.v_); }
  friend bool operator>(const Mpfr_number& a, const Mpfr_number& b) { return mpfr_greater_p(a.v_, b.v_); }
  friend bool operator<=(const Mpfr_number& a, const Mpfr_number& b) { return mpfr_lessequal_p(a.v_, b.v_); }
  friend bool operator>=(const Mpfr_number& a, const Mpfr_number& b) { return mpfr_greaterequal_p(a.v_, b.v_); }

  /// |a| (exact).
  friend Mpfr_number abs(const Mpfr_number& a) {
    Mpfr_number r;
    mpfr_abs(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  /// Square root, correctly rounded.
  friend Mpfr_number sqrt(const Mpfr_number& a) {
    Mpfr_number r;
    mpfr_sqrt(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  /// a * 2^e (exact unless it overflows or underflows).
  friend Mpfr_number ldexp(const Mpfr_number& a, long e) {
    Mpfr_number r;
    mpfr_mul_2si(r.v_, a.v_, e, MPFR_RNDN);
    return r;
  }

 private:
  template <class Op>
  static Mpfr_number apply(Op op, const Mpfr_number& a, const Mpfr_number& b) {
    Mpfr_number r;
    op(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  template <class Op>
  Mpfr_number& update(Op op, const Mpfr_number& b) {
    op(v_, v_, b.v_, MPFR_RNDN);
    return *this;
  }
  mpfr_t v_;
};

}  // namespace relgeo
