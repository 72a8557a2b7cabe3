// Soundness suite: CGAL's Epeck through Cgal_kernel (its own TU: Epeck is the
// most expensive kernel header to compile).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "relgeo/kernel/cgal_kernel.h"
#include "soundness_suite.h"

namespace relgeo::test {
using Cgal_exact_kernels = ::testing::Types<Cgal_kernel<CGAL::Epeck>>;
INSTANTIATE_TYPED_TEST_SUITE_P(CgalExact, Soundness, Cgal_exact_kernels, Kernel_name);
}  // namespace relgeo::test
