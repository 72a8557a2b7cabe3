// relgeo/kernel/naive_kernel.h — plain floating point: the unreliable baseline.
#pragma once

#include <optional>
#include <string>
#include <type_traits>

#include "relgeo/core/floating_point.h"
#include "relgeo/kernel/internal/determinants.h"
#include "relgeo/kernel/internal/kernel_base.h"
#include "relgeo/kernel/internal/implicit_rounded.h"
#include "relgeo/kernel/internal/semi_static_filter.h"

namespace relgeo {

/// \brief Kernel computing every predicate in the floating-point type T and
/// returning the sign of whatever it computed, right or wrong.
///
/// It never answers `uncertain`: that is its purpose, it shows what happens to
/// an algorithm fed with unreliable predicates (Kettner et al., "Classroom
/// examples of robustness problems in geometric computations", 2008).
/// The determinants are the ones of internal/determinants.h, so with
/// -ffp-contract=off `Naive_kernel<double>` agrees bit for bit with
/// `CGAL::Simple_cartesian<double>`.
///
/// \tparam T float, double or long double.
/// \cgalModels{Kernel}
template <class T>
  requires std::is_floating_point_v<T>
class Naive_kernel : public internal::Kernel_base<Naive_kernel<T>, T>,
                     public internal::Floating_point_kernel_constants<T>,
                     public internal::Implicit_kernel_base<internal::Rounded_implicit_policy<Naive_kernel<T>, T>> {
  using Base = internal::Kernel_base<Naive_kernel<T>, T>;

 public:
  using typename Base::FT;
  using typename Base::Point_2;
  using typename Base::Point_3;

  static std::string name() { return Number_traits<T>::name(); }
  static constexpr bool is_certified = false;
  // unit_roundoff and the orientation error bounds (|computed - exact| <=
  // eps * Mx * My (* Mz): where this kernel *could* be wrong) come from
  // Floating_point_kernel_constants.

  static FT from_double(double v) { return static_cast<FT>(v); }
  static Certified_sign compare_ft(const FT& a, const FT& b) {
    return a < b ? Certified_sign::negative : (b < a ? Certified_sign::positive : Certified_sign::zero);
  }

  struct Orientation_2 {
    Certified_sign operator()(const Point_2& p, const Point_2& q, const Point_2& r) const {
      return sign_of(internal::orientation_2_determinant<T>(p.x, p.y, q.x, q.y, r.x, r.y));
    }
  };
  struct Orientation_3 {
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r,
                              const Point_3& s) const {
      return sign_of(internal::orientation_3_determinant<T>(p.x, p.y, p.z, q.x, q.y, q.z, r.x,
                                                            r.y, r.z, s.x, s.y, s.z));
    }
  };
  Orientation_2 orientation_2_object() const { return {}; }
  Orientation_3 orientation_3_object() const { return {}; }
};

}  // namespace relgeo
