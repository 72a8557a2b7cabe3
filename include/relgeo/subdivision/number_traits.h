// relgeo/subdivision/number_traits.h — how subdivision weights become numbers
// of a kernel's type: the documented, kernel-controlled hook for every
// constant that is not a small dyadic rational.
//
// Loop's weights involve 1/n, cos(2 pi / n) and quotients. Casting a double
// computed with std::cos into FT (what CGAL's Loop_mask_3 does) silently gives
// an exact kernel rounded weights (STYLE anti-pattern 3). Instead every
// constant goes through Loop_number_traits<FT>:
//
//  * rational(p, q)      the number p / q;
//  * cos_2pi(i, n)       cos(2 pi i / n);
//  * quotient(a, b)      a / b (FT may lack operator/, e.g. relgeo::Interval);
//  * exact_rationals     whether rational() and quotient() are exact;
//  * policy()            one line saying what the approximations are.
//
// cos(2 pi i / n) is rational exactly when the reduced n is 1, 2, 3, 4 or 6
// (Niven's theorem); every specialisation returns those values exactly when
// FT can hold them (1, -1, -1/2, 0, 1/2: also in binary floating point).
// Otherwise:
//  | FT                    | rational(p,q)        | cos_2pi(i,n), irrational case                  |
//  |-----------------------|----------------------|------------------------------------------------|
//  | float/double/long dbl | correctly rounded    | MPFR cospi at 128 bits, rounded to nearest     |
//  | relgeo::Interval      | enclosure (point if exact) | enclosure: MPFR at 256 bits, widened by 2^-240, rounded outward |
//  | mpq_class             | exact                | the exact rational value of MPFR cospi at cos_precision_bits (default 256) bits: |error| <= 2^-256 |
//  | Mpfr_number<B>        | correctly rounded    | MPFR cospi at B + 64 bits, rounded to B bits   |
//  | anything else (CGAL)  | FT(p) / FT(q)        | FT(double), the double of the row above        |
//
// Consequence for an exact kernel: at valences 3, 4, 6 (and with Warren's
// weights at every valence) all refinement and limit weights are the exact
// rationals of the formulas; at other valences Loop's beta is replaced by a
// rational within about 2^-256 of it, and every mask is still *exactly* affine
// (weights summing to exactly 1) and the limit mask is the exact left
// eigenvector of the refinement rule actually applied (so refining and then
// taking limits gives exactly the same limit points). Specialise
// Loop_number_traits for your own number type, or Loop_kernel_number_traits
// for a kernel, to change the policy.
#pragma once

#include <gmpxx.h>
#include <mpfr.h>

#include <numeric>
#include <string>
#include <type_traits>

#include "relgeo/core/errors.h"
#include "relgeo/core/interval.h"
#include "relgeo/core/mpfr_number.h"
#include "relgeo/core/rounding.h"
#include "relgeo/kernel/concepts.h"

namespace relgeo {

namespace internal {

/// cos(2 pi i / n) when it is rational: the value times 2 (an integer in
/// -2..2) and true; false otherwise.
inline bool rational_cos_2pi(long i, long n, int& twice) {
  if (n <= 0) throw Precondition_violation("cos_2pi(i, n): n must be positive");
  i %= n;
  if (i < 0) i += n;
  const long g = std::gcd(i, n);
  const long ni = i / g, nn = n / g;  // angle = 2 pi ni / nn, 0 <= ni < nn
  switch (nn) {
    case 1: twice = 2; return true;
    case 2: twice = -2; return true;
    case 3: twice = -1; return true;
    case 4: twice = 0; return true;
    case 6: twice = (ni == 1 || ni == 5) ? 1 : -1; return true;
    default: return false;
  }
}

/// cos(2 pi i / n) to nearest at `bits` bits (the argument 2i/n is first
/// rounded at bits + 64 bits; the result is correctly rounded but for that
/// relative 2^-(bits+62) perturbation).
inline Mpfr_value mpfr_cos_2pi(long i, long n, mpfr_prec_t bits) {
  Mpfr_value x(bits + 64), c(bits);
  mpfr_set_si(x.get(), 2 * (i % n), MPFR_RNDN);
  mpfr_div_si(x.get(), x.get(), n, MPFR_RNDN);
  mpfr_cospi(c.get(), x.get(), MPFR_RNDN);
  return c;
}

}  // namespace internal

/// The number hook (see the file comment). The primary template serves any
/// number type with +, -, *, / and construction from int and double.
template <class FT, class Enable = void>
struct Loop_number_traits {
  static constexpr bool exact_rationals = false;
  static FT rational(long p, long q) { return FT(FT(static_cast<int>(p)) / FT(static_cast<int>(q))); }
  static FT cos_2pi(long i, long n) {
    int twice = 0;
    if (internal::rational_cos_2pi(i, n, twice)) return FT(FT(twice) / FT(2));
    return FT(round_mpfr<double>(internal::mpfr_cos_2pi(i, n, 128).get()));
  }
  static FT quotient(const FT& a, const FT& b) { return FT(a / b); }
  static std::string policy() { return "generic: p/q in FT, irrational cosines as the nearest double"; }
};

/// Binary floating point.
template <class T>
struct Loop_number_traits<T, std::enable_if_t<std::is_floating_point_v<T>>> {
  static constexpr bool exact_rationals = false;
  static T rational(long p, long q) { return static_cast<T>(p) / static_cast<T>(q); }
  static T cos_2pi(long i, long n) {
    int twice = 0;
    if (internal::rational_cos_2pi(i, n, twice)) return static_cast<T>(twice) / 2;
    return round_mpfr<T>(internal::mpfr_cos_2pi(i, n, 128).get());
  }
  static T quotient(T a, T b) { return a / b; }
  static std::string policy() {
    return "floating point: rationals and cosines correctly rounded (MPFR, 128 bits)";
  }
};

/// relgeo::Interval: every constant is an enclosure of the exact value.
template <>
struct Loop_number_traits<Interval> {
  static constexpr bool exact_rationals = false;
  /// p / q one step outward of the rounded quotient unless it is exact
  /// (core/rounding.h's div_bounds; 0 / q is the point 0).
  static Interval rational(long p, long q) {
    if (p == 0) return Interval(0.0);
    const Double_bounds b = div_bounds(static_cast<double>(p), static_cast<double>(q));
    return Interval(b.lo, b.hi);
  }
  static Interval cos_2pi(long i, long n) {
    int twice = 0;
    if (internal::rational_cos_2pi(i, n, twice)) return Interval(twice / 2.0);
    return widen(internal::mpfr_cos_2pi(i, n, 256));
  }
  /// Interval division (exact quotients of points stay points). \pre b does
  /// not contain 0: throws Precondition_violation.
  static Interval quotient(const Interval& a, const Interval& b) { return a / b; }
  static std::string policy() {
    return "interval: enclosures of every rational and cosine (MPFR, 256 bits, outward)";
  }

 private:
  // [x - 2^-240 |x| - 2^-240, x + ...] rounded outward to doubles.
  static Interval widen(const Mpfr_value& x) {
    Mpfr_value lo(256), hi(256), eps(256);
    mpfr_abs(eps.get(), x.get(), MPFR_RNDU);
    mpfr_add_ui(eps.get(), eps.get(), 1, MPFR_RNDU);
    mpfr_mul_2si(eps.get(), eps.get(), -240, MPFR_RNDU);
    mpfr_sub(lo.get(), x.get(), eps.get(), MPFR_RNDD);
    mpfr_add(hi.get(), x.get(), eps.get(), MPFR_RNDU);
    return Interval(round_mpfr<double>(lo.get(), Rounding::downward), round_mpfr<double>(hi.get(), Rounding::upward));
  }
};

/// GMP rationals: exact rationals; irrational cosines as the exact value of
/// a cos_precision_bits MPFR approximation.
template <>
struct Loop_number_traits<mpq_class> {
  static constexpr bool exact_rationals = true;
  static constexpr int cos_precision_bits = 256;
  static mpq_class rational(long p, long q) {
    mpq_class r(p, q);
    r.canonicalize();
    return r;
  }
  static mpq_class cos_2pi(long i, long n) {
    int twice = 0;
    if (internal::rational_cos_2pi(i, n, twice)) return rational(twice, 2);
    mpq_class r;
    mpfr_get_q(r.get_mpq_t(), internal::mpfr_cos_2pi(i, n, cos_precision_bits).get());  // exact: a dyadic rational
    return r;
  }
  static mpq_class quotient(const mpq_class& a, const mpq_class& b) { return mpq_class(a / b); }
  static std::string policy() {
    return "exact rationals; irrational cosines exact rational values of 256-bit MPFR roundings";
  }
};

/// MPFR numbers of B bits: everything correctly rounded to B bits.
template <int B>
struct Loop_number_traits<Mpfr_number<B>> {
  using FT = Mpfr_number<B>;
  static constexpr bool exact_rationals = false;
  static FT rational(long p, long q) { return FT(static_cast<int>(p)) / FT(static_cast<int>(q)); }
  static FT cos_2pi(long i, long n) {
    int twice = 0;
    if (internal::rational_cos_2pi(i, n, twice)) return FT(twice) / FT(2);
    return FT(internal::mpfr_cos_2pi(i, n, B).get());  // already B bits: copied exactly
  }
  static FT quotient(const FT& a, const FT& b) { return a / b; }
  static std::string policy() {
    return "mpfr-" + std::to_string(B) + ": rationals and cosines correctly rounded to " +
           std::to_string(B) + " bits";
  }
};

/// The per-kernel hook: by default the number traits of the kernel's FT.
/// Specialise it to give one kernel a different policy than its number type.
template <ConstructionKernel_3 K>
struct Loop_kernel_number_traits : Loop_number_traits<typename K::FT> {};

}  // namespace relgeo
