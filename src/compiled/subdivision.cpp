// src/compiled/subdivision.cpp — relgeo::compiled: the Loop subdivider of
// double meshes (loop_subdivide's and loop_limit_mesh's default kernel),
// made once; relgeo/subdivision/loop_subdivision.h declares it `extern`.
#include "relgeo/subdivision/loop_subdivision.h"

namespace relgeo {

template class Loop_subdivider<Naive_kernel<double>>;

}  // namespace relgeo
