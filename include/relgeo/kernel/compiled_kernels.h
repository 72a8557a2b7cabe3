// relgeo/kernel/compiled_kernels.h — the kernels for which relgeo::compiled
// instantiates the heavy algorithms on double meshes (the Boolean, the
// self-intersection test, the mesh and solid checks, the subdivision
// Boolean, Loop subdivision): the filtered exact default, the exact
// rationals and the naive double baseline.
//
// One list of signatures per algorithm, written once in its header as
// X(PREFIX, K). Under RELGEO_COMPILED (defined by the targets that link
// relgeo::compiled) the header ends with
//   RELGEO_COMPILED_KERNELS(X, extern template)
// so a client compiles none of these instances; src/compiled/ repeats the
// same line with `template`, which makes them. Any other kernel is compiled in
// place, as in the header-only use.
#pragma once

#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/naive_kernel.h"

/// X(PREFIX, K) for each compiled kernel K.
#define RELGEO_COMPILED_KERNELS(X, PREFIX) \
  X(PREFIX, Filtered_exact_kernel)         \
  X(PREFIX, Exact_kernel)                  \
  X(PREFIX, Naive_kernel<double>)

/// True in a translation unit that links relgeo::compiled.
#if defined(RELGEO_COMPILED) && RELGEO_COMPILED
#define RELGEO_LINKS_COMPILED 1
#else
#define RELGEO_LINKS_COMPILED 0
#endif
