// relgeo/joining/compiled_kernels.h — the kernels for which relgeo::compiled
// instantiates join_meshes and naive_sewing (src/compiled/joining.cpp): the
// certified kernels of relgeo with double coordinates that the joiner's
// checks use. With RELGEO_COMPILED_JOINING (defined by the targets that link
// relgeo::compiled, when it was built with CGAL and Eigen), joiner.h and
// naive_sewing.h declare these instantiations `extern template`: a
// translation unit that joins under one of them compiles no joiner (and no
// CGAL Mesh_2 refinement) of its own. Any other kernel is compiled in place.
#pragma once

#if defined(RELGEO_COMPILED_JOINING) && RELGEO_COMPILED_JOINING
#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/failsafe_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/interval_kernel.h"
#endif

/// X(PREFIX, K) for each compiled kernel K (the convention of
/// relgeo/kernel/compiled_kernels.h).
#define RELGEO_JOINING_COMPILED_KERNELS(X, PREFIX) \
  X(PREFIX, Failsafe_kernel<double>)               \
  X(PREFIX, Interval_kernel)                       \
  X(PREFIX, Filtered_exact_kernel)                 \
  X(PREFIX, Exact_kernel)
