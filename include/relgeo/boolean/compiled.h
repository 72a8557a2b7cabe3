// relgeo/boolean/compiled.h — relgeo::boolean declared, without its engine.
// A client that links relgeo::compiled includes this header instead of
// relgeo/boolean.h and calls the Boolean under the kernels compiled there
// (Filtered_exact_kernel, the default; Exact_kernel; Naive_kernel<double>):
// it parses the result types only (1.5 s instead of 14 s for a
// translation unit with one call, doc/boolean.md "Compile time"). Another
// kernel needs the definition: include relgeo/boolean.h (header-only).
#pragma once

#include "relgeo/boolean/boolean_types.h"
#include "relgeo/kernel/compiled_kernels.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// \brief The regularised Boolean `op` of the solids bounded by closed
/// triangle meshes `a` and `b` (double coordinates), under kernel K.
///
/// Requires an IntersectionKernel_3. Exact under kernels with exact
/// predicates (Filtered_exact_kernel, the default, and Exact_kernel): the
/// result's exact_vertex(i) are the exact points, its mesh their doubles
/// (rounding_error says how far): the nearest ones, repaired where rounding
/// made the mesh cross itself or a face degenerate (options.rounding; a
/// repair that cannot converge fails the Boolean), and validated
/// (Boolean_result::validation). Fail-safe and interval kernels
/// give the same result or a failure naming the face pairs they cannot
/// decide (no vertex is moved: doc/boolean.md, "The kernels"); naive
/// kernels give what their arithmetic gives, never a crash.
/// \throws Invalid_operand when an operand is open, non-manifold,
/// inconsistently oriented, degenerate, non-finite or self-intersecting
/// (options.check_operands), before any other work.
template <IntersectionKernel_3 K = Filtered_exact_kernel>
Boolean_result<K> boolean(const Triangle_mesh<Point_3<double>>& a, const Triangle_mesh<Point_3<double>>& b,
                          Boolean_operation op, const K& k = K{}, const Boolean_options& options = {});

// The instances relgeo::compiled makes (src/compiled/boolean.cpp).
#define RELGEO_BOOLEAN_INSTANCE(PREFIX, K)                                                                    \
  PREFIX Boolean_result<K> boolean(const Triangle_mesh<Point_3<double>>&, const Triangle_mesh<Point_3<double>>&, \
                                   Boolean_operation, const K&, const Boolean_options&);
#if RELGEO_LINKS_COMPILED
RELGEO_COMPILED_KERNELS(RELGEO_BOOLEAN_INSTANCE, extern template)
#endif

}  // namespace relgeo
