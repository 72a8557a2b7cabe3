// tools/relgeo/commands/boolean/intersection_kernels.h — the kernels `relgeo
// boolean` runs (with and without --levels): relgeo's own that model
// IntersectionKernel_3. Included by the boolean dispatch*.cpp files only
// (the compile firewall, kernels/dispatch.h).
#pragma once

#include "kernels/dispatch.h"
#include "relgeo/kernel/concepts.h"

namespace relgeo::tool {

// The CGAL adapters have no implicit points (their types are never completed
// here). MPFR at 53 and 113 bits only: compile time.
struct Intersection_kernels {
  template <class K>
  static constexpr bool check() {
    if constexpr (is_cgal_kernel_v<K>) return false;
    else if constexpr (mpfr_bits_v<K> > 0) return mpfr_bits_v<K> == 53 || mpfr_bits_v<K> == 113;
    else return IntersectionKernel_3<K>;
  }
  template <class K>
  static constexpr bool admits = check<K>();
};

}  // namespace relgeo::tool
