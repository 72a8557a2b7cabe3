// Soundness suite: CGAL's Simple_cartesian<double> and Epick through Cgal_kernel.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include "relgeo/kernel/cgal_kernel.h"
#include "soundness_suite.h"

namespace relgeo::test {
using Cgal_inexact_kernels =
    ::testing::Types<Cgal_kernel<CGAL::Simple_cartesian<double>>, Cgal_kernel<CGAL::Epick>>;
INSTANTIATE_TYPED_TEST_SUITE_P(Cgal, Soundness, Cgal_inexact_kernels, Kernel_name);
}  // namespace relgeo::test
