// relgeo/kernel/failsafe_kernel.h — Fortune's fail-safe epsilon predicates.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include "relgeo/core/fp_environment.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/kernel/internal/kernel_base.h"
#include "relgeo/kernel/internal/implicit_enclosed.h"
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
/// internal/semi_static_filter.h: eps_2 = 16u(1+16u), eps_3 = 97u (u = unit
/// roundoff of T; 1.7763568394002532e-15 and 1.0769163338864018e-14 for
/// double), proven for every rounding mode and under flush-to-zero /
/// denormals-are-zero, so no caller's floating-point environment can make a
/// definite answer wrong (for long double on x86, an x87 precision control
/// below 64 bits is detected and the test then runs in the default
/// environment). Exact degeneracies (all points sharing one
/// coordinate) are answered `zero`. Non-finite coordinates and magnitudes
/// outside the range where the proof holds (for double roughly 2^-450..2^510
/// in 2D, 2^-297..2^340 in 3D) give `uncertain`. Constructions are plain
/// floating point.
///
/// Stable algorithms (graham_fortune) use the `uncertain` answer to stay
/// consistent and so achieve a provable backward error.
///
/// \tparam T float, double or long double.
template <class T>
  requires std::is_floating_point_v<T>
class Failsafe_kernel
    : public internal::Kernel_base<Failsafe_kernel<T>, T>,
      public internal::Floating_point_kernel_constants<T>,
      public internal::Implicit_kernel_base<internal::Enclosed_implicit_policy<Point_3<T>, internal::Filtered_value<T>>> {
  using Base = internal::Kernel_base<Failsafe_kernel<T>, T>;

 public:
  using typename Base::FT;
  using typename Base::Point_2;
  using typename Base::Point_3;

  static std::string name() { return "failsafe<" + Number_traits<T>::name() + ">"; }
  static constexpr bool is_certified = true;
  // unit_roundoff and the orientation error bounds, which are the epsilons of
  // the test (a definite answer only when |det| > eps * Mx * My (* Mz)), come
  // from Floating_point_kernel_constants.

  /// v rounded to T. A value in T's subnormal range is not flushed to zero
  /// even under flush-to-zero (converted again in the default environment).
  static FT from_double(double v) {
    const FT r = static_cast<FT>(v);
    if constexpr (sizeof(FT) < sizeof(double))
      if (r == 0 && v != 0) [[unlikely]]
        return internal::in_default_fp_environment([&] { return static_cast<FT>(v); });
    return r;
  }
  static Certified_sign compare_ft(const FT& a, const FT& b) {
    return internal::compare_certified(a, b);
  }

  struct Orientation_2 {
    Certified_sign operator()(const Point_2& p, const Point_2& q, const Point_2& r) const {
      return at_full_precision([&] { return internal::filtered_orientation_2<T>(p.x, p.y, q.x, q.y, r.x, r.y); });
    }
  };
  struct Orientation_3 {
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r,
                              const Point_3& s) const {
      return at_full_precision([&] {
        return internal::filtered_orientation_3<T>(p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z, s.x, s.y, s.z);
      });
    }
  };
  Orientation_2 orientation_2_object() const { return {}; }
  Orientation_3 orientation_3_object() const { return {}; }

 private:
  // The constants are derived for T's own precision (u = 2^-64 for x87 long
  // double), in every rounding mode and under FTZ/DAZ, but not for an x87
  // precision control set to 53 or 24 bits: then the test runs in the
  // default environment (measured before: 672 wrong answers on Kettner's
  // 256x256 grid with the control at 53 bits). float and double need no check.
  static constexpr bool computes_on_x87 = std::is_same_v<T, long double> && std::numeric_limits<T>::digits == 64;
  template <class F>
  static Certified_sign at_full_precision(const F& f) {
    if constexpr (computes_on_x87)
      if (!long_double_at_full_precision()) [[unlikely]]
        return internal::call_in_default_fp_environment(f);
    return f();
  }
};

}  // namespace relgeo
