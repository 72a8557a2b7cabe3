// relgeo/kernel/failsafe_kernel.h — Fortune's fail-safe epsilon predicates.
#pragma once

#include <optional>
#include <string>
#include <type_traits>

#include "relgeo/kernel/floating_point.h"
#include "relgeo/kernel/internal/kernel_base.h"
#include "relgeo/kernel/internal/semi_static_filter.h"

namespace relgeo {

/// \brief Floating-point kernel whose predicates refuse to guess: Fortune's
/// epsilon test (S. Fortune, "Stable maintenance of point set triangulations in
/// two dimensions", FOCS 1989; thesis Sec. 3.3.3).
///
/// Each predicate evaluates the same determinant as Naive_kernel<T> and then
/// compares it with an a-priori forward-error bound computed from its operands
/// (semi-static: eps * Mx * My, Mx the largest |x-difference|). Inside the
/// bound it answers `uncertain`; outside, the answer is the exact sign of the
/// determinant of the *given* coordinates. The constants and the proof are in
/// internal/semi_static_filter.h: eps_2 = 8u(1+8u), eps_3 = 49u (u = unit
/// roundoff of T; 8.8817841970012563e-16 and 5.4400928206632e-15 for double).
/// Non-finite coordinates and magnitudes outside the range where the proof
/// holds (for double roughly 2^-468..2^510 in 2D, 2^-306..2^340 in 3D) give
/// `uncertain`. Constructions are plain floating point.
///
/// Stable algorithms (graham_fortune) use the `uncertain` answer to stay
/// consistent and so achieve a provable backward error.
///
/// \tparam T float, double or long double.
template <class T>
  requires std::is_floating_point_v<T>
class Failsafe_kernel : public internal::Kernel_base<Failsafe_kernel<T>, T> {
  using Base = internal::Kernel_base<Failsafe_kernel<T>, T>;
  using C = internal::Orientation_filter_constants<T>;

 public:
  using typename Base::FT;
  using typename Base::Point_2;
  using typename Base::Point_3;

  static std::string name() {
    if constexpr (std::is_same_v<T, float>) return "failsafe<float>";
    else if constexpr (std::is_same_v<T, double>) return "failsafe<double>";
    else return "failsafe<long-double>";
  }
  static constexpr double unit_roundoff = static_cast<double>(unit_roundoff_v<T>);
  static constexpr bool is_certified = true;
  static constexpr bool has_exact_predicates = false;
  static constexpr bool has_exact_constructions = false;
  /// The epsilon of the test: a definite answer is given only when
  /// |det| > eps * Mx * My (* Mz).
  static constexpr std::optional<double> orientation_2_error_bound = round_up_to_double(C::eps_2);
  static constexpr std::optional<double> orientation_3_error_bound = round_up_to_double(C::eps_3);

  static FT from_double(double v) { return static_cast<FT>(v); }
  static Certified_sign compare_ft(const FT& a, const FT& b) {
    return internal::compare_certified(a, b);
  }

  struct Orientation_2 {
    Certified_sign operator()(const Point_2& p, const Point_2& q, const Point_2& r) const {
      return internal::filtered_orientation_2<T>(p.x, p.y, q.x, q.y, r.x, r.y);
    }
  };
  struct Orientation_3 {
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r,
                              const Point_3& s) const {
      return internal::filtered_orientation_3<T>(p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z,
                                                 s.x, s.y, s.z);
    }
  };
  Orientation_2 orientation_2_object() const { return {}; }
  Orientation_3 orientation_3_object() const { return {}; }
};

}  // namespace relgeo
