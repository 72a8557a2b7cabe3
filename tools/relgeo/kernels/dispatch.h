// tools/relgeo/kernels/dispatch.h — a kernel named at run time -> its type.
//
// The compile firewall: a kernel type is named only in files called
// dispatch*.cpp (and kernels/registry.cpp). Each includes this header, calls
// with_kernel, and exposes a non-template function that takes the kernel's
// name; commands and experiment sections call those functions and compile
// without any kernel. A dispatch over every kernel includes
// kernels/cgal_kernels.h as well; a dispatch over part of the list (Loop
// subdivision: the kernels with constructions) names the part with an
// `Admitted` policy and never completes the CGAL types.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "cli/text.h"
#include "kernels/list.h"
#include "kernels/registry.h"

namespace relgeo::tool {

/// The policy admitting every kernel of the list (include kernels/cgal_kernels.h).
struct Every_kernel {
  template <class K>
  static constexpr bool admits = true;
};

namespace dispatch_internal {  // not "internal": that would hide relgeo::internal here

template <class Admitted, std::size_t... I>
constexpr std::size_t first_admitted(std::index_sequence<I...>) {
  std::size_t first = kernel_count;
  ((first == kernel_count && Admitted::template admits<kernel_at<I>> ? (first = I, 0) : 0), ...);
  return first;
}

template <class K, class... Admitted>
inline constexpr bool admitted_by_any = (Admitted::template admits<K> || ...);

template <class Admitted, class R, std::size_t I, class F>
R dispatch_from(const Kernel_entry& entry, F& f) {
  if constexpr (I == kernel_count) {
    throw Usage_error("kernel '" + entry.label() + "' is not available here");
  } else {
    if constexpr (Admitted::template admits<kernel_at<I>>) {
      if (entry.index == I) return f(kernel_at<I>{});
    }
    return dispatch_from<Admitted, R, I + 1>(entry, f);
  }
}

}  // namespace dispatch_internal

/// Calls f(K{}) with the kernel type K of `entry` (f must return the same type
/// for every admitted kernel). \throws Usage_error when `Admitted` does not
/// admit the kernel.
template <class Admitted = Every_kernel, class F>
decltype(auto) with_kernel(const Kernel_entry& entry, F&& f) {
  constexpr std::size_t first = dispatch_internal::first_admitted<Admitted>(std::make_index_sequence<kernel_count>{});
  static_assert(first < kernel_count, "the policy admits no kernel");
  using R = std::invoke_result_t<F&, kernel_at<first>>;
  return dispatch_internal::dispatch_from<Admitted, R, 0>(entry, f);
}

/// Whether `Admitted` admits the kernel of `entry`.
template <class Admitted>
bool admits_kernel(const Kernel_entry& entry) {
  return [&]<std::size_t... I>(std::index_sequence<I...>) {
    return ((entry.index == I && Admitted::template admits<kernel_at<I>>) || ...);
  }(std::make_index_sequence<kernel_count>{});
}

/// The labels of the kernels that one of the policies admits, in the list's
/// order: what a command offers, and lists when it refuses a kernel.
template <class... Admitted>
std::vector<std::string> admitted_kernel_names() {
  std::vector<std::string> names;
  const auto& registry = kernel_registry();
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    ((dispatch_internal::admitted_by_any<kernel_at<I>, Admitted...> ? names.push_back(registry[I].label()) : void()),
     ...);
  }(std::make_index_sequence<kernel_count>{});
  return names;
}

/// The same for a kernel name (K::name() or its alias).
/// \throws Usage_error for an unknown name (the message lists the valid ones).
template <class Admitted = Every_kernel, class F>
decltype(auto) with_kernel(std::string_view name, F&& f) {
  return with_kernel<Admitted>(find_kernel(name), std::forward<F>(f));
}

}  // namespace relgeo::tool
