// tools/relgeo/kernels/list.h — THE list of kernels the tool offers: one row
// per kernel type, in the order of the help text and the experiment tables.
//
// A kernel is known by its own name, K::name() ("double", "failsafe<double>",
// "mpfr-53", "cgal-epick"): kernels/registry.h builds the run-time registry
// from this list, and kernels/dispatch.h turns a registry entry back into the
// type. Two kernels have a shorter alias that users type and reports print
// (failsafe = failsafe<double>, cgal-sc = cgal-sc-double); both names work.
//
// Only relgeo's light headers are included: the CGAL kernel types are named
// here but are complete only where kernels/cgal_kernels.h is included.
#pragma once

#include <cstddef>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "relgeo/kernel/cgal_kernel.h"
#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/failsafe_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/interval_kernel.h"
#include "relgeo/kernel/mpfr_kernel.h"
#include "relgeo/kernel/naive_kernel.h"

namespace relgeo::tool {

/// One kernel of the list: its type and what the tool says about it.
template <class K>
struct Kernel_row {
  using kernel_type = K;
  std::string_view alias;        ///< command-line alias ("" when K::name() is short enough)
  std::string_view description;  ///< one line for the help text ("" for Mpfr_kernel: generated)
  bool slow = false;             ///< `relgeo experiment --quick` gives it n/10 cases of each workload
};

inline constexpr std::tuple kernel_list{
    Kernel_row<Naive_kernel<float>>{"", "Naive_kernel<float>: sign of the float value (coordinates rounded to float)"},
    Kernel_row<Naive_kernel<double>>{"", "Naive_kernel<double>: sign of the double value (the unreliable baseline)"},
    Kernel_row<Naive_kernel<long double>>{"", "Naive_kernel<long double>: sign of the long double value"},
    Kernel_row<Failsafe_kernel<double>>{"failsafe", "Failsafe_kernel<double>: Fortune's epsilon test, 'uncertain' near zero"},
    Kernel_row<Interval_kernel>{"", "Interval_kernel: interval arithmetic, 'uncertain' when 0 is enclosed"},
    Kernel_row<Filtered_exact_kernel>{"", "Filtered_exact_kernel: semi-static filter, intervals, exact fallback"},
    Kernel_row<Exact_kernel>{"", "Exact_kernel: GMP rationals, the ground truth", true},
    // half, single, double, x87 extended, 80, double-double, quadruple, 128, 256 bits
    Kernel_row<Mpfr_kernel<11>>{"", "", true},
    Kernel_row<Mpfr_kernel<24>>{"", "", true},
    Kernel_row<Mpfr_kernel<53>>{"", "", true},
    Kernel_row<Mpfr_kernel<64>>{"", "", true},
    Kernel_row<Mpfr_kernel<80>>{"", "", true},
    Kernel_row<Mpfr_kernel<106>>{"", "", true},
    Kernel_row<Mpfr_kernel<113>>{"", "", true},
    Kernel_row<Mpfr_kernel<128>>{"", "", true},
    Kernel_row<Mpfr_kernel<256>>{"", "", true},
    Kernel_row<Cgal_kernel<CGAL::Simple_cartesian<double>>>{"cgal-sc", "Cgal_kernel<CGAL::Simple_cartesian<double>>: CGAL, naive double"},
    Kernel_row<Cgal_kernel<CGAL::Epick>>{"", "Cgal_kernel<CGAL::Epick>: CGAL, filtered exact predicates"},
    Kernel_row<Cgal_kernel<CGAL::Epeck>>{"", "Cgal_kernel<CGAL::Epeck>: CGAL, lazy exact", true},
};

inline constexpr std::size_t kernel_count = std::tuple_size_v<std::remove_const_t<decltype(kernel_list)>>;

/// The kernel type of row I.
template <std::size_t I>
using kernel_at = typename std::tuple_element_t<I, std::remove_const_t<decltype(kernel_list)>>::kernel_type;

/// Cgal_kernel<...>: recognised without completing the CGAL type.
template <class K>
inline constexpr bool is_cgal_kernel_v = false;
template <class C>
inline constexpr bool is_cgal_kernel_v<Cgal_kernel<C>> = true;

/// Mpfr_kernel<Bits>: its precision (0 for other kernels).
template <class K>
inline constexpr int mpfr_bits_v = 0;
template <int Bits>
inline constexpr int mpfr_bits_v<Mpfr_kernel<Bits>> = Bits;

}  // namespace relgeo::tool
