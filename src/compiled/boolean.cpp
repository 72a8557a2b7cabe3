// src/compiled/boolean.cpp — relgeo::compiled: relgeo::boolean instantiated
// once for the kernels people use (the filtered exact default, the exact
// rationals, the naive double baseline). The matching `extern template`
// declarations are in relgeo/boolean/compiled.h: a translation unit that
// links relgeo::compiled (which defines RELGEO_COMPILED) compiles no Boolean
// engine for these kernels; every other kernel is instantiated in place, as
// in the header-only use.
#include "relgeo/boolean.h"

namespace relgeo {

template Boolean_result<Filtered_exact_kernel> boolean(const Triangle_mesh<Point_3<double>>&,
                                                       const Triangle_mesh<Point_3<double>>&, Boolean_operation,
                                                       const Filtered_exact_kernel&, const Boolean_options&);
template Boolean_result<Exact_kernel> boolean(const Triangle_mesh<Point_3<double>>&,
                                              const Triangle_mesh<Point_3<double>>&, Boolean_operation,
                                              const Exact_kernel&, const Boolean_options&);
template Boolean_result<Naive_kernel<double>> boolean(const Triangle_mesh<Point_3<double>>&,
                                                      const Triangle_mesh<Point_3<double>>&, Boolean_operation,
                                                      const Naive_kernel<double>&, const Boolean_options&);

}  // namespace relgeo
