// relgeo/kernel/exact_kernel.h — exact rational arithmetic: the ground truth.
#pragma once

#include <gmpxx.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "relgeo/core/errors.h"
#include "relgeo/core/dyadic.h"
#include "relgeo/kernel/internal/determinants.h"
#include "relgeo/kernel/internal/kernel_base.h"
#include "relgeo/kernel/internal/implicit_rounded.h"

namespace relgeo {

class Filtered_exact_kernel;  // the Double_point_kernel hook below (filtered_exact_kernel.h)

/// \brief Kernel over GMP rationals (mpq_class): exact predicates and exact
/// constructions. Slow; it is the reference every other kernel is measured
/// against.
///
/// Building a point from a NaN or infinite double throws Non_finite_input
/// (a rational cannot hold it).
class Exact_kernel : public internal::Kernel_base<Exact_kernel, mpq_class>,
                     public internal::Implicit_kernel_base<internal::Rounded_implicit_policy<Exact_kernel, mpq_class>> {
 public:
  static std::string name() { return "exact"; }
  static constexpr double unit_roundoff = 0;
  static constexpr bool is_certified = true;
  static constexpr bool has_exact_predicates = true;
  static constexpr bool has_exact_constructions = true;
  static constexpr std::optional<double> orientation_2_error_bound = 0.0;
  static constexpr std::optional<double> orientation_3_error_bound = 0.0;

  static FT from_double(double v) {
    if (!std::isfinite(v)) throw Non_finite_input("exact kernel: coordinate is NaN or infinite");
    // Exact (every finite double is a dyadic rational), from the bits: the
    // same in every floating-point environment.
    return exact_rational(v);
  }
  static Certified_sign compare_ft(const FT& a, const FT& b) { return sign_of(cmp(a, b)); }

  /// v as a double when it is one exactly (a dyadic rational with at most 53
  /// significant bits in double's exponent range, as every value read from a
  /// double is), nullopt otherwise. Bit counts only, no division; one-limb
  /// numerators and denominators (every double in [2^-63, 2^64)) take a
  /// shortcut without GMP calls.
  static std::optional<double> exact_double(const FT& v) {
    mpz_srcptr num = v.get_num_mpz_t(), den = v.get_den_mpz_t();
    if (mpz_sgn(num) == 0) return 0.0;
    if constexpr (GMP_NUMB_BITS == 64) {
      if (mpz_size(num) == 1 && mpz_size(den) == 1) {
        const std::uint64_t n = mpz_getlimbn(num, 0), d = mpz_getlimbn(den, 0);
        if ((d & (d - 1)) != 0) return std::nullopt;  // not a power of two
        if (std::bit_width(n) - std::countr_zero(n) > 53) return std::nullopt;
        // n is exact in double, 2^-scale (scale < 64) a normal double, and
        // so is their product: exact.
        const double magnitude =
            static_cast<double>(n) * std::bit_cast<double>(std::uint64_t(1023 - std::countr_zero(d)) << 52);
        return mpz_sgn(num) < 0 ? -magnitude : magnitude;
      }
    }
    const mp_bitcnt_t scale = mpz_scan1(den, 0);  // den = 2^scale?
    if (mpz_sizeinbase(den, 2) != scale + 1) return std::nullopt;
    const std::size_t bits = mpz_sizeinbase(num, 2);
    if (bits > 1024 || scale > 1100 || bits - mpz_scan1(num, 0) > 53) return std::nullopt;
    const double m = mpz_get_d(num);  // exact: at most 53 significant bits, below 2^1024
    const double d = std::ldexp(m, -static_cast<int>(scale));
    if (std::ldexp(d, static_cast<int>(scale)) != m) return std::nullopt;  // lost to underflow
    return d;
  }
  /// Kernel hook "double-point kernel" (Has_double_point_kernel,
  /// kernel/kernel_for_number.h): on points of doubles, Filtered_exact_kernel
  /// answers every predicate with the exact sign this kernel answers on the
  /// same values, without rational arithmetic. Algorithms whose result
  /// depends only on predicate signs of their input points run there when
  /// every point is exactly a point of doubles (the hulls: 40x faster on 10^6
  /// points).
  using Double_point_kernel = Filtered_exact_kernel;
  /// p as a point of doubles when both coordinates are doubles exactly (the
  /// other half of the hook).
  static std::optional<relgeo::Point_2<double>> exact_double_point(const Point_2& p) {
    const std::optional<double> x = exact_double(p.x), y = exact_double(p.y);
    if (!x || !y) return std::nullopt;
    return relgeo::Point_2<double>{*x, *y};
  }
  /// An implicit point of the Double_point_kernel as this kernel's exact
  /// implicit point (the hook's third part: the Boolean on input of doubles
  /// runs on the filtered kernel and returns this kernel's points). D is the
  /// hook's kernel, named as a template parameter so that it may still be
  /// incomplete here.
  template <class D = Double_point_kernel>
  static Implicit_point_3 from_double_point_kernel(const typename D::Implicit_point_3& p) {
    std::array<mpq_class, 3> c = D::exact_coordinates(p);
    return {Point_3{std::move(c[0]), std::move(c[1]), std::move(c[2])}, p.kind};
  }

  struct Orientation_2 {
    Certified_sign operator()(const Point_2& p, const Point_2& q, const Point_2& r) const {
      return sign_of(sgn(internal::orientation_2_determinant<FT>(p.x, p.y, q.x, q.y, r.x, r.y)));
    }
  };
  struct Orientation_3 {
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r,
                              const Point_3& s) const {
      return sign_of(sgn(internal::orientation_3_determinant<FT>(p.x, p.y, p.z, q.x, q.y, q.z,
                                                                 r.x, r.y, r.z, s.x, s.y, s.z)));
    }
  };
  Orientation_2 orientation_2_object() const { return {}; }
  Orientation_3 orientation_3_object() const { return {}; }
};

}  // namespace relgeo
