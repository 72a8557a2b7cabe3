// relgeo/kernel/internal/filtered_predicate.h — the generic filtered
// predicate of Filtered_exact_kernel: a formula written once as a template
// over the number type (determinants.h, implicit_predicates.h) is evaluated
// in arithmetics of increasing cost until one certifies its sign:
//   1. intervals (relgeo::Interval),
//   2. floating-point expansions (dynamic_expansion.h), when the inputs'
//      range allows them to be exact (Expansion_scaling) and the caller
//      asks for them,
//   3. GMP integers, which always decide.
// The fast stage before these is each predicate's own (the semi-static
// epsilon test, the error-bounded coordinates of implicit points, the
// specialised expansions of orientation_2 and orientation_3).
//
// The formula is called as `evaluate(to_nt)`, to_nt converting one input
// double to the stage's number type. Stages 2 and 3 scale every input by
// one power of two (to keep expansions in range, to make integers). So a
// formula must be a product of signs of homogeneous polynomials in the
// inputs with integer coefficients (the signs do not change under that
// scaling) of degree at most `degree`, and, with every input below M in
// magnitude, no value it forms may exceed 2^6 max(1, (4M)^degree) (the
// orientation determinants and the implicit-point formulas meet this:
// Expansion_scaling).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <utility>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/dyadic.h"
#include "relgeo/core/interval.h"
#include "relgeo/kernel/internal/dynamic_expansion.h"

namespace relgeo {

/// Which stage of Filtered_exact_kernel decided a predicate.
enum class Filter_stage {
  semi_static,  ///< Fortune's epsilon test (or the error-bounded coordinates of implicit points)
  interval,     ///< interval arithmetic
  expansion,    ///< floating-point expansions (exact; inputs of moderate range)
  exact,        ///< GMP integers
  undecidable   ///< NaN or infinite input
};

namespace internal {

/// The certified sign of a value of each stage's number type (and of exact
/// rationals), for formulas generic over it.
inline Certified_sign certified_sign_of(const Interval& v) { return v.sign(); }
inline Certified_sign certified_sign_of(const mpz_class& v) { return static_cast<Certified_sign>(sgn(v)); }
inline Certified_sign certified_sign_of(const mpq_class& v) { return static_cast<Certified_sign>(sgn(v)); }

/// The inputs as integers scaled by one common power of two (2^-emin, emin
/// the smallest exponent of their binary parts m 2^e, |m| < 2^53).
class Scaled_integers {
 public:
  explicit Scaled_integers(std::span<const double> inputs) {
    for (const double v : inputs) {
      const Binary_parts b = binary_parts(v);
      if (b.mantissa != 0) emin_ = std::min(emin_, b.exponent);
    }
  }
  /// z = v 2^-emin, an integer (into z's storage: no allocation once it is large enough).
  void set(mpz_ptr z, double v) const {
    const Binary_parts b = binary_parts(v);
    set_mpz(z, b.mantissa);
    if (b.mantissa != 0) mpz_mul_2exp(z, z, static_cast<mp_bitcnt_t>(b.exponent - emin_));
  }
  mpz_class operator()(double v) const {
    mpz_class z;
    set(z.get_mpz_t(), v);
    return z;
  }
  /// The scaling's exponent: each input is its integer times 2^emin (INT_MAX when every input is 0).
  int emin() const { return emin_; }

 private:
  int emin_ = INT_MAX;
};

/// The power of two 2^shift by which the expansion stage scales the inputs
/// of a formula of degree D (file comment), and whether it is then exact.
/// * Products are exact when each is a multiple of 2^-1074: with the lowest
///   set bit of every scaled input at 2^L or above, every value is a multiple
///   of 2^(D min(0, L)), so D min(0, L) >= -1074 suffices (Dekker's product,
///   like every sum, is exact on multiples of 2^-1074: expansion.h).
/// * No overflow: with every scaled input below M = 2^H, every value is below
///   2^6 max(1, (4M)^D) (the formula's precondition), so D (H + 2) <= 994
///   keeps every value below 2^1000.
/// The shift is the largest that meets the second condition; the stage is
/// exact when the first holds then, i.e. when the inputs' bits (from the
/// lowest set bit to the largest magnitude) span at most about 2068 / D - 2
/// positions: 687 for orientation_3 (D = 3), 293 for an LPI point against an
/// input plane (D = 7: implicit_staged.h), 71 for four TPI points (D = 28).
class Expansion_scaling {
 public:
  Expansion_scaling(std::span<const double> inputs, int degree) {
    int lowest = INT_MAX, highest = INT_MIN;
    for (const double v : inputs) {
      const Binary_parts b = binary_parts(v);  // v = m 2^e, |m| < 2^53
      if (b.mantissa == 0) continue;
      const auto m = static_cast<std::uint64_t>(std::abs(b.mantissa));
      lowest = std::min(lowest, b.exponent + std::countr_zero(m));
      highest = std::max(highest, b.exponent + static_cast<int>(std::bit_width(m)));  // |v| < 2^highest
    }
    if (highest == INT_MIN) return;  // every input 0: nothing to scale
    shift_ = 994 / degree - 2 - highest;
    exact_ = degree * std::min(0, lowest + shift_) >= -1074;
  }
  /// Whether the expansions are exact on these inputs.
  bool exact() const { return exact_; }
  /// The scaling's exponent: inputs are multiplied by 2^shift().
  int shift() const { return shift_; }
  /// v scaled (exact: the scaled value's bits lie in the range above).
  Dynamic_expansion operator()(double v) const { return Dynamic_expansion(std::ldexp(v, shift_)); }

 private:
  int shift_ = 0;
  bool exact_ = true;
};

/// Stage 2 alone: the sign in floating-point expansions, or `uncertain`
/// when the inputs' range does not allow them. \pre finite inputs; default
/// floating-point environment.
template <class Evaluate>
Certified_sign expansion_sign(std::span<const double> inputs, int degree, const Evaluate& evaluate) {
  const Expansion_scaling scaled(inputs, degree);
  if (!scaled.exact()) return Certified_sign::uncertain;
  return evaluate(scaled);  // uncertain only if a value overflowed: the safeguard of dynamic_expansion.h
}

/// Stage 3 alone: the exact sign in GMP integers. \pre finite inputs.
template <class Evaluate>
Certified_sign integer_sign(std::span<const double> inputs, const Evaluate& evaluate) {
  return evaluate(Scaled_integers(inputs));
}

/// Stages 1-3 in turn: the exact sign of the formula and the stage that
/// decided it. \pre finite inputs; default floating-point environment.
template <class Evaluate>
std::pair<Certified_sign, Filter_stage> filtered_exact_sign(std::span<const double> inputs, int degree,
                                                            bool try_expansion, const Evaluate& evaluate) {
  const Certified_sign by_intervals = evaluate([](double v) { return Interval(v); });
  if (is_certain(by_intervals)) return {by_intervals, Filter_stage::interval};
  if (try_expansion)
    if (const Certified_sign s = expansion_sign(inputs, degree, evaluate); is_certain(s))
      return {s, Filter_stage::expansion};
  return {integer_sign(inputs, evaluate), Filter_stage::exact};
}

}  // namespace internal
}  // namespace relgeo
