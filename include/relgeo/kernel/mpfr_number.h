// relgeo/kernel/mpfr_number.h — an MPFR float with a compile-time precision in bits.
//
// Boost.Multiprecision's mpfr_float_backend is parametrised by decimal digits;
// precision sweeps need the exact number of significand bits, so this is a thin
// RAII value type over mpfr_t (round to nearest, ties to even, like IEEE).
#pragma once

#include <mpfr.h>

#include <utility>

namespace relgeo {

template <int Bits>
class Mpfr_number {
  static_assert(Bits >= MPFR_PREC_MIN && Bits <= 1 << 20, "unsupported MPFR precision");

 public:
  static constexpr int precision = Bits;

  Mpfr_number() { mpfr_init2(v_, Bits), mpfr_set_zero(v_, 1); }
  /// Correctly rounded to Bits (exact for Bits >= 53).
  Mpfr_number(double d) { mpfr_init2(v_, Bits), mpfr_set_d(v_, d, MPFR_RNDN); }  // NOLINT: numeric conversion
  Mpfr_number(int i) { mpfr_init2(v_, Bits), mpfr_set_si(v_, i, MPFR_RNDN); }  // NOLINT
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

  double to_double() const { return mpfr_get_d(v_, MPFR_RNDN); }
  int sign() const { return mpfr_sgn(v_); }
  bool is_nan() const { return mpfr_nan_p(v_) != 0; }
  mpfr_srcptr get() const { return v_; }

  friend Mpfr_number operator+(const Mpfr_number& a, const Mpfr_number& b) {
    return apply(mpfr_add, a, b);
  }
  friend Mpfr_number operator-(const Mpfr_number& a, const Mpfr_number& b) {
    return apply(mpfr_sub, a, b);
  }
  friend Mpfr_number operator*(const Mpfr_number& a, const Mpfr_number& b) {
    return apply(mpfr_mul, a, b);
  }
  friend Mpfr_number operator/(const Mpfr_number& a, const Mpfr_number& b) {
    return apply(mpfr_div, a, b);
  }
  friend Mpfr_number operator-(const Mpfr_number& a) {
    Mpfr_number r;
    mpfr_neg(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  friend bool operator==(const Mpfr_number& a, const Mpfr_number& b) { return mpfr_equal_p(a.v_, b.v_); }
  friend bool operator<(const Mpfr_number& a, const Mpfr_number& b) { return mpfr_less_p(a.v_, b.v_); }
  friend bool operator>(const Mpfr_number& a, const Mpfr_number& b) { return mpfr_greater_p(a.v_, b.v_); }

 private:
  template <class Op>
  static Mpfr_number apply(Op op, const Mpfr_number& a, const Mpfr_number& b) {
    Mpfr_number r;
    op(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  mpfr_t v_;
};

}  // namespace relgeo
