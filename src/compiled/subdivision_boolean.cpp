// src/compiled/subdivision_boolean.cpp — relgeo::compiled: the Boolean of
// Loop subdivision solids instantiated once for the compiled kernels
// (relgeo/kernel/compiled_kernels.h), with its limit meshes, crease fitting
// (Eigen) and validation. Built when Eigen is found; the header declares
// these instances `extern template` under RELGEO_COMPILED_SUBDIVISION_BOOLEAN.
#include "relgeo/boolean/subdivision_boolean.h"

namespace relgeo {

RELGEO_COMPILED_KERNELS(RELGEO_SUBDIVISION_BOOLEAN_INSTANCE, template)

}  // namespace relgeo
