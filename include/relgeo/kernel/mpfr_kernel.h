// relgeo/kernel/mpfr_kernel.h — naive evaluation at any binary precision.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "relgeo/core/errors.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/kernel/internal/determinants.h"
#include "relgeo/kernel/internal/kernel_base.h"
#include "relgeo/kernel/internal/implicit_rounded.h"
#include "relgeo/kernel/internal/semi_static_filter.h"
#include "relgeo/core/mpfr_number.h"

namespace relgeo {

/// \brief Kernel computing in MPFR floats of `Bits` significand bits and
/// returning the sign of the computed value (a naive kernel at that precision:
/// never `uncertain`). Precision sweeps with it show how many bits a case
/// needs before its answers agree with the exact kernel.
///
/// Points built from doubles are rounded to `Bits` (exact for Bits >= 53).
/// Non-finite coordinates throw Non_finite_input at construction.
template <int Bits>
class Mpfr_kernel
    : public internal::Kernel_base<Mpfr_kernel<Bits>, Mpfr_number<Bits>>,
      public internal::Implicit_kernel_base<internal::Rounded_implicit_policy<Mpfr_kernel<Bits>, Mpfr_number<Bits>>> {
  using Base = internal::Kernel_base<Mpfr_kernel<Bits>, Mpfr_number<Bits>>;

 public:
  using typename Base::FT;
  using typename Base::Point_2;
  using typename Base::Point_3;

  static std::string name() { return "mpfr-" + std::to_string(Bits); }
  static constexpr double unit_roundoff = internal::power_of_two<double>(-Bits);
  static constexpr bool is_certified = false;
  static constexpr bool has_exact_predicates = false;
  static constexpr bool has_exact_constructions = false;
  /// Same derivation as for IEEE types with u = 2^-Bits (MPFR's exponent range
  /// is wide enough that underflow does not occur for double input).
  static constexpr std::optional<double> orientation_2_error_bound =
      8 * unit_roundoff * (1 + 8 * unit_roundoff);
  static constexpr std::optional<double> orientation_3_error_bound = 49 * unit_roundoff;

  static FT from_double(double v) {
    if (!std::isfinite(v)) throw Non_finite_input("mpfr kernel: coordinate is NaN or infinite");
    return FT(v);
  }
  static Certified_sign compare_ft(const FT& a, const FT& b) {
    return a < b ? Certified_sign::negative : (b < a ? Certified_sign::positive : Certified_sign::zero);
  }

  struct Orientation_2 {
    Certified_sign operator()(const Point_2& p, const Point_2& q, const Point_2& r) const {
      return sign_of(internal::orientation_2_determinant<FT>(p.x, p.y, q.x, q.y, r.x, r.y).sign());
    }
  };
  struct Orientation_3 {
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r,
                              const Point_3& s) const {
      return sign_of(internal::orientation_3_determinant<FT>(p.x, p.y, p.z, q.x, q.y, q.z, r.x,
                                                             r.y, r.z, s.x, s.y, s.z)
                         .sign());
    }
  };
  Orientation_2 orientation_2_object() const { return {}; }
  Orientation_3 orientation_3_object() const { return {}; }
};

}  // namespace relgeo
