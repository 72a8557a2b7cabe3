// src/compiled/mesh_checks.cpp — relgeo::compiled: the mesh checks
// (check_mesh, the exact self-intersection test, check_solid) and the solid
// validation on double meshes, instantiated once for the compiled kernels
// (relgeo/kernel/compiled_kernels.h). Every Boolean checks its operands and
// validates its output with them under Filtered_exact_kernel, whatever its
// own kernel: with these compiled, a Boolean under another kernel compiles
// only its engine.
#include "relgeo/mesh/solid_validation.h"

namespace relgeo {

RELGEO_COMPILED_KERNELS(RELGEO_CHECK_MESH_INSTANCE, template)
RELGEO_COMPILED_KERNELS(RELGEO_SELF_INTERSECTION_INSTANCE, template)
RELGEO_COMPILED_KERNELS(RELGEO_VALIDATE_SOLID_INSTANCE, template)

}  // namespace relgeo
