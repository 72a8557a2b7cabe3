// tools/relgeo/commands/boolean/intersection_kernels.h — the kernels `relgeo
// boolean` runs: relgeo's own that model IntersectionKernel_3 (and, without
// --levels, CGAL's Epeck: that policy is in dispatch.cpp, the translation
// unit that completes the CGAL types). Included by the boolean dispatch*.cpp
// files only (the compile firewall, kernels/dispatch.h).
#pragma once

#include "kernels/dispatch.h"
#include "relgeo/kernel/concepts.h"

namespace relgeo::tool {

// relgeo's kernels with implicit points (the CGAL adapters' types are never
// completed here). MPFR at 53 and 113 bits only: compile time.
struct Relgeo_intersection_kernels {
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
