// relgeo/kernel/kernel_for_number.h — which relgeo kernel to use for a
// coordinate type when the caller names none.
#pragma once

#include <gmpxx.h>

#include <concepts>
#include <optional>
#include <type_traits>

#include "relgeo/core/interval.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/interval_kernel.h"
#include "relgeo/kernel/mpfr_kernel.h"
#include "relgeo/kernel/naive_kernel.h"
#include "relgeo/kernel/point.h"
#include "relgeo/kernel/point_access.h"

namespace relgeo {

/// The kernel computing in FT itself: Naive_kernel<T> for float, double and
/// long double, Interval_kernel, Exact_kernel (mpq_class), Mpfr_kernel<B>.
/// Algorithms that only construct (Loop refinement) use it: every kernel over
/// one number type constructs alike.
template <class FT>
struct Kernel_for_number;
template <class T>
  requires std::is_floating_point_v<T>
struct Kernel_for_number<T> {
  using type = Naive_kernel<T>;
};
template <>
struct Kernel_for_number<Interval> {
  using type = Interval_kernel;
};
template <>
struct Kernel_for_number<mpq_class> {
  using type = Exact_kernel;
};
template <int B>
struct Kernel_for_number<Mpfr_number<B>> {
  using type = Mpfr_kernel<B>;
};

/// The kernel to decide predicates on FT coordinates: exact predicates where
/// relgeo has them (Filtered_exact_kernel for double, Exact_kernel for
/// rationals), otherwise Kernel_for_number (Interval_kernel reports doubt;
/// the naive kernels of float and long double and Mpfr_kernel<B> are not
/// certified: say so when you rely on them).
template <class FT>
struct Predicate_kernel_for_number : Kernel_for_number<FT> {};
template <>
struct Predicate_kernel_for_number<double> {
  using type = Filtered_exact_kernel;
};

/// The kernel to certify predicates on FT coordinates whatever FT is:
/// Exact_kernel for rationals, otherwise Filtered_exact_kernel on the
/// coordinates' nearest doubles (exact for double input).
template <class FT>
struct Certified_kernel_for_number {
  using type = Filtered_exact_kernel;
};
template <>
struct Certified_kernel_for_number<mpq_class> {
  using type = Exact_kernel;
};

/// \brief The kernel an algorithm on points P uses when its caller names
/// none: the rule For_number (Kernel_for_number, Predicate_kernel_for_number
/// or Certified_kernel_for_number) applied to P's coordinate type.
template <template <class> class For_number, class P>
struct Kernel_for_point : For_number<typename internal::Point_access<P>::FT> {};

/// K, or Kernel_for_point<For_number, P> when K is void (an algorithm's
/// `template <KernelOrDefault K = void, class P>`, kernel/concepts.h); the
/// default is only looked at then.
template <KernelOrDefault K, template <class> class For_number, class P>
using Kernel_or_default =
    typename std::conditional_t<std::is_void_v<K>, Kernel_for_point<For_number, P>, std::type_identity<K>>::type;

/// \brief Kernel hook: a faster kernel for input that is doubles.
///
/// A kernel K with exact predicates may name `K::Double_point_kernel`, a
/// kernel over relgeo::Point_2<double> whose predicates answer, on points of
/// doubles, exactly the signs K's predicates answer on the same values, and
/// provide `K::exact_double_point(p)`: p as a Point_2<double> when both of its
/// coordinates are doubles exactly, nullopt otherwise. An algorithm whose
/// result depends only on predicate signs of its input points may then run
/// with Double_point_kernel on the converted input and get K's result: the
/// same answers, so the same output and statistics. Exact_kernel names
/// Filtered_exact_kernel (no rational arithmetic for input read from
/// doubles). The hull algorithms consult the hook once, in their common
/// frame (hull/internal/hull_frame.h).
template <class K>
concept Has_double_point_kernel =
    K::has_exact_predicates && std::default_initializable<typename K::Double_point_kernel> &&
    std::same_as<typename K::Double_point_kernel::Point_2, relgeo::Point_2<double>> &&
    requires(const typename K::Point_2& p) {
      { K::exact_double_point(p) } -> std::same_as<std::optional<relgeo::Point_2<double>>>;
    };

/// \brief The same hook for algorithms that construct implicit points (the
/// mesh Boolean): K also provides `K::from_double_point_kernel(p)`, an
/// implicit point of Double_point_kernel as K's own (its exact value), so an
/// algorithm on input of doubles runs with Double_point_kernel and converts
/// only the points it returns. Exact_kernel models it.
template <class K>
concept Has_implicit_double_point_kernel =
    Has_double_point_kernel<K> && requires(const typename K::Double_point_kernel::Implicit_point_3& p) {
      { K::from_double_point_kernel(p) } -> std::same_as<typename K::Implicit_point_3>;
    };

}  // namespace relgeo
