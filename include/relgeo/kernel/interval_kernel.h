// relgeo/kernel/interval_kernel.h — interval arithmetic without exact fallback.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "relgeo/core/fp_environment.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/kernel/internal/determinants.h"
#include "relgeo/kernel/internal/kernel_base.h"
#include "relgeo/kernel/internal/implicit_enclosed.h"
#include "relgeo/core/interval.h"

namespace relgeo {

/// \brief Kernel over relgeo::Interval: each predicate is evaluated in interval
/// arithmetic and answers `uncertain` when the resulting interval contains 0
/// (and is not exactly [0,0]). There is no exact fallback, so the rate of
/// `uncertain` answers shows how far interval filtering alone gets.
///
/// Constructions are intervals too, so a constructed point carries an
/// enclosure of the exact point. Non-finite coordinates give `uncertain`.
/// Interval arithmetic needs round to nearest without FTZ/DAZ: the
/// predicates run in that environment whatever the caller set.
class Interval_kernel
    : public internal::Kernel_base<Interval_kernel, Interval>,
      public internal::Implicit_kernel_base<internal::Enclosed_implicit_policy<Point_3<Interval>, Interval>> {
 public:
  static std::string name() { return "interval"; }
  static constexpr double unit_roundoff = unit_roundoff_v<double>;
  static constexpr bool is_certified = true;
  static constexpr bool has_exact_predicates = false;
  static constexpr bool has_exact_constructions = false;
  /// Interval widths depend on the data: no a-priori constant.
  static constexpr std::optional<double> orientation_2_error_bound = std::nullopt;
  static constexpr std::optional<double> orientation_3_error_bound = std::nullopt;

  static FT from_double(double v) { return Interval(v); }
  /// Certified comparison; `uncertain` for a NaN or infinite end (as input,
  /// an infinity stands for no finite number).
  static Certified_sign compare_ft(const FT& a, const FT& b) {
    if (!finite(a) || !finite(b)) return Certified_sign::uncertain;
    return internal::in_default_fp_environment([&] { return compare(a, b); });
  }

  struct Orientation_2 {
    Certified_sign operator()(const Point_2& p, const Point_2& q, const Point_2& r) const {
      if (!finite(p) || !finite(q) || !finite(r)) return Certified_sign::uncertain;
      return internal::in_default_fp_environment([&] {
        return internal::orientation_2_determinant<Interval>(p.x, p.y, q.x, q.y, r.x, r.y).sign();
      });
    }
  };
  struct Orientation_3 {
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r,
                              const Point_3& s) const {
      if (!finite(p) || !finite(q) || !finite(r) || !finite(s)) return Certified_sign::uncertain;
      return internal::in_default_fp_environment([&] {
        return internal::orientation_3_determinant<Interval>(p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y,
                                                             r.z, s.x, s.y, s.z)
            .sign();
      });
    }
  };
  Orientation_2 orientation_2_object() const { return {}; }
  Orientation_3 orientation_3_object() const { return {}; }

 private:
  static bool finite(const Interval& i) { return std::isfinite(i.inf()) && std::isfinite(i.sup()); }
  static bool finite(const Point_2& p) { return finite(p.x) && finite(p.y); }
  static bool finite(const Point_3& p) { return finite(p.x) && finite(p.y) && finite(p.z); }
};

}  // namespace relgeo
