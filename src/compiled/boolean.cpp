// src/compiled/boolean.cpp — relgeo::compiled: relgeo::boolean instantiated
// once for the compiled kernels (relgeo/kernel/compiled_kernels.h). The
// matching `extern template` declarations are in relgeo/boolean/compiled.h:
// a translation unit that links relgeo::compiled compiles no Boolean engine
// for these kernels; every other kernel is instantiated in place, as in the
// header-only use.
#include "relgeo/boolean.h"

namespace relgeo {

RELGEO_COMPILED_KERNELS(RELGEO_BOOLEAN_INSTANCE, template)

}  // namespace relgeo
