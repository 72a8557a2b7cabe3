// src/compiled/joining.cpp — relgeo::compiled: the Whitney joiner and the
// naive sewing instantiated once for the joiner's certified kernels
// (relgeo/joining/compiled_kernels.h lists them; the headers declare them
// `extern template` under RELGEO_COMPILED_JOINING). Built when CGAL (Mesh_2)
// and Eigen (the projection) are found.
#include "relgeo/joining/joiner.h"
#include "relgeo/joining/naive_sewing.h"

namespace relgeo {

RELGEO_JOINING_COMPILED_KERNELS(RELGEO_JOIN_MESHES_INSTANCE, template)
RELGEO_JOINING_COMPILED_KERNELS(RELGEO_NAIVE_SEWING_INSTANCE, template)

}  // namespace relgeo
