// relgeo/linear/scalar_traits.h — the scalars of the linear-equation area:
// float, double, long double, relgeo::Mpfr_number<Bits> and GMP's mpq_class,
// made usable in Eigen matrices (Eigen::NumTraits).
//
// What relgeo knows about a scalar (name, unit roundoff, exactness, exact
// conversion to and correctly rounded conversion from rationals) is the
// number layer's Number_traits (relgeo/core/number_traits.h); Mpfr_number
// has the complete arithmetic Eigen needs (compound assignment, <=, >=, abs,
// sqrt). Only what is particular to linear algebra stays here: which scalars
// the area supports, and Eigen's traits of the two that are not built in.
#pragma once

#include <Eigen/Core>
#include <gmpxx.h>
#include <mpfr.h>

#include <type_traits>

#include "relgeo/core/mpfr_number.h"
#include "relgeo/core/number_traits.h"

namespace relgeo {

/// The scalars the linear area supports: binary floating point, MPFR at any
/// precision, GMP rationals.
template <class S>
concept Linear_scalar = Number_traits<S>::kind == Number_kind::floating_point ||
                        Number_traits<S>::kind == Number_kind::mpfr ||
                        Number_traits<S>::kind == Number_kind::rational;

namespace internal {
/// What Eigen's traits of a real scalar that lives on the heap (MPFR, GMP)
/// have in common: its own real and literal type, signed, not an integer,
/// constructed before use, and expensive to read and compute with.
template <class S>
struct Allocating_real_num_traits : Eigen::GenericNumTraits<S> {
  using Real = S;
  using NonInteger = S;
  using Nested = S;
  using Literal = S;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = Eigen::HugeCost,
    AddCost = Eigen::HugeCost,
    MulCost = Eigen::HugeCost
  };
};
}  // namespace internal

}  // namespace relgeo

// ---- Eigen::NumTraits ----------------------------------------------------------

namespace Eigen {

/// Mpfr_number<Bits> in Eigen matrices (LU decompositions, products...).
template <int Bits>
struct NumTraits<relgeo::Mpfr_number<Bits>> : relgeo::internal::Allocating_real_num_traits<relgeo::Mpfr_number<Bits>> {
  using S = relgeo::Mpfr_number<Bits>;
  static inline int digits10() { return static_cast<int>(Bits * 0.30102999566398120); }
  static inline int digits() { return Bits; }
  /// 2^(1 - Bits), the distance from 1 to the next value (Eigen's convention).
  static inline S epsilon() { return ldexp(S(1), 1 - Bits); }
  static inline S dummy_precision() { return ldexp(epsilon(), Bits / 8); }
  static inline S highest() {
    S h = infinity();
    mpfr_nextbelow(h.get());
    return h;
  }
  static inline S lowest() { return -highest(); }
  static inline S infinity() {
    S h;
    mpfr_set_inf(h.get(), 1);
    return h;
  }
  static inline S quiet_NaN() {
    S h;
    mpfr_set_nan(h.get());
    return h;
  }
};

/// GMP rationals in Eigen matrices (exact: epsilon() == 0). Beware of gmpxx
/// expression templates: never store `a * b` in `auto` (STYLE: Eigen's
/// TopicPitfalls applies to gmpxx too).
template <>
struct NumTraits<mpq_class> : relgeo::internal::Allocating_real_num_traits<mpq_class> {
  static inline mpq_class epsilon() { return mpq_class(0); }
  static inline mpq_class dummy_precision() { return mpq_class(0); }
  static inline int digits10() { return 0; }
  static inline mpq_class highest() = delete;
  static inline mpq_class lowest() = delete;
};

}  // namespace Eigen
