// relgeo/kernel/exact_kernel.h — exact rational arithmetic: the ground truth.
#pragma once

#include <gmpxx.h>

#include <cmath>
#include <optional>
#include <string>

#include "relgeo/core/errors.h"
#include "relgeo/kernel/internal/determinants.h"
#include "relgeo/kernel/internal/kernel_base.h"

namespace relgeo {

/// \brief Kernel over GMP rationals (mpq_class): exact predicates and exact
/// constructions. Slow; it is the reference every other kernel is measured
/// against.
///
/// Building a point from a NaN or infinite double throws Non_finite_input
/// (a rational cannot hold it).
class Exact_kernel : public internal::Kernel_base<Exact_kernel, mpq_class> {
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
    return FT(v);  // exact: every finite double is a dyadic rational
  }
  static Certified_sign compare_ft(const FT& a, const FT& b) { return sign_of(cmp(a, b)); }

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
