// relgeo/kernel/kernel_for_number.h — which relgeo kernel to use for a
// coordinate type when the caller names none.
#pragma once

#include <gmpxx.h>

#include <type_traits>

#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/core/interval.h"
#include "relgeo/kernel/interval_kernel.h"
#include "relgeo/kernel/mpfr_kernel.h"
#include "relgeo/kernel/naive_kernel.h"

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

}  // namespace relgeo
