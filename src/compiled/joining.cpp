// src/compiled/joining.cpp — relgeo::compiled: the Whitney joiner and the
// naive sewing instantiated once for the joiner's certified kernels
// (relgeo/joining/compiled_kernels.h lists them; the headers declare them
// `extern template` under RELGEO_COMPILED_JOINING). Built when CGAL (Mesh_2)
// and Eigen (the projection) are found.
#include "relgeo/joining/joiner.h"
#include "relgeo/joining/naive_sewing.h"

namespace relgeo {

#define RELGEO_JOINING_INSTANCES(K)                                                                         \
  template Join_result join_meshes<K>(const Surface_model&, const std::vector<Triangle_mesh<Point_3<double>>>&, \
                                      const K&, const Join_options&);                                       \
  template Join_result naive_sewing<K>(const Surface_model&, const std::vector<Triangle_mesh<Point_3<double>>>&, \
                                       const K&, const Join_options&);
RELGEO_JOINING_COMPILED_KERNELS(RELGEO_JOINING_INSTANCES)
#undef RELGEO_JOINING_INSTANCES

}  // namespace relgeo
