// tools/relgeo/kernel_dispatch.h — runtime kernel name -> kernel type.
//
// Heavy: includes every kernel, CGAL's Epeck among them. Include it only in
// the translation units that instantiate algorithms under every kernel
// (grid_eval.cpp, workload_eval.cpp); everything else uses
// kernel_names.h and the non-template functions of those units.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <string>
#include <string_view>
#include <utility>

#include "kernel_names.h"
#include "relgeo/kernel.h"
#include "relgeo/kernel/cgal_kernel.h"
#include "tool_common.h"

namespace relgeo::tool {

/// Calls f(K{}) with the kernel type K named `name`:
///   float, double, long-double      Naive_kernel<T>
///   failsafe                        Failsafe_kernel<double>
///   interval                        Interval_kernel
///   filtered                        Filtered_exact_kernel
///   exact                           Exact_kernel
///   mpfr-BITS                       Mpfr_kernel<BITS>, BITS in mpfr_bits
///   cgal-sc, cgal-epick, cgal-epeck Cgal_kernel<Simple_cartesian<double> | Epick | Epeck>
/// f must return the same type for every kernel. An unknown name (or BITS
/// outside mpfr_bits) throws Usage_error listing the valid names.
template <class F>
decltype(auto) with_kernel(std::string_view name, F&& f) {
  validate_kernel_name(name);  // throws Usage_error with the list of names
  if (name == "float") return std::forward<F>(f)(Naive_kernel<float>{});
  if (name == "double") return std::forward<F>(f)(Naive_kernel<double>{});
  if (name == "long-double") return std::forward<F>(f)(Naive_kernel<long double>{});
  if (name == "failsafe") return std::forward<F>(f)(Failsafe_kernel<double>{});
  if (name == "interval") return std::forward<F>(f)(Interval_kernel{});
  if (name == "filtered") return std::forward<F>(f)(Filtered_exact_kernel{});
  if (name == "exact") return std::forward<F>(f)(Exact_kernel{});
  if (name == "mpfr-11") return std::forward<F>(f)(Mpfr_kernel<11>{});
  if (name == "mpfr-24") return std::forward<F>(f)(Mpfr_kernel<24>{});
  if (name == "mpfr-53") return std::forward<F>(f)(Mpfr_kernel<53>{});
  if (name == "mpfr-64") return std::forward<F>(f)(Mpfr_kernel<64>{});
  if (name == "mpfr-80") return std::forward<F>(f)(Mpfr_kernel<80>{});
  if (name == "mpfr-106") return std::forward<F>(f)(Mpfr_kernel<106>{});
  if (name == "mpfr-113") return std::forward<F>(f)(Mpfr_kernel<113>{});
  if (name == "mpfr-128") return std::forward<F>(f)(Mpfr_kernel<128>{});
  if (name == "mpfr-256") return std::forward<F>(f)(Mpfr_kernel<256>{});
  static_assert(mpfr_bits.size() == 9, "keep with_kernel in step with mpfr_bits");
  if (name == "cgal-sc") return std::forward<F>(f)(Cgal_kernel<CGAL::Simple_cartesian<double>>{});
  if (name == "cgal-epick") return std::forward<F>(f)(Cgal_kernel<CGAL::Epick>{});
  if (name == "cgal-epeck") return std::forward<F>(f)(Cgal_kernel<CGAL::Epeck>{});
  // validate_kernel_name and this list disagree: a bug of the tool.
  throw Usage_error("kernel '" + std::string(name) + "' is listed but not dispatched");
}

}  // namespace relgeo::tool
