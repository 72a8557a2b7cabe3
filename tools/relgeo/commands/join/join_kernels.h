// tools/relgeo/commands/join/join_kernels.h — which kernels `join` runs under
// (its dispatch and the OpenCASCADE plug-in's, plugins/occt/plugin.cpp).
#pragma once

#include <type_traits>

#include "relgeo/kernel.h"

namespace relgeo::tool {

/// Certified kernels of relgeo with double coordinates (the joiner's checks
/// take (u,v) points as doubles): failsafe, interval, filtered, exact.
struct Join_kernels {
  template <class K>
  static constexpr bool admits = std::is_same_v<K, Failsafe_kernel<double>> || std::is_same_v<K, Interval_kernel> ||
                                 std::is_same_v<K, Filtered_exact_kernel> || std::is_same_v<K, Exact_kernel>;
};

}  // namespace relgeo::tool
