// tools/relgeo/commands/boolean/intersection_kernels.h — the kernels `relgeo
// boolean` runs: those that model IntersectionKernel_3 — relgeo's own and,
// without --levels, CGAL's with exact constructions (Epeck; the translation
// unit must include kernels/cgal_kernels.h to tell). Included by the boolean
// dispatch*.cpp files only (the compile firewall, kernels/dispatch.h).
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

#if defined(RELGEO_TOOL_CGAL_KERNELS_COMPLETE)
// And the CGAL adapters that model IntersectionKernel_3 (Epeck).
struct Intersection_kernels {
  template <class K>
  static constexpr bool check() {
    if constexpr (is_cgal_kernel_v<K>) return IntersectionKernel_3<K>;
    else return Relgeo_intersection_kernels::admits<K>;
  }
  template <class K>
  static constexpr bool admits = check<K>();
};
#endif

}  // namespace relgeo::tool
