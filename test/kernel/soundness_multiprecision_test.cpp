// Soundness suite: GMP rationals and MPFR at several precisions.
#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/mpfr_kernel.h"
#include "soundness_suite.h"

namespace relgeo::test {
using Multiprecision_kernels = ::testing::Types<Exact_kernel, Mpfr_kernel<24>, Mpfr_kernel<53>, Mpfr_kernel<113>>;
INSTANTIATE_TYPED_TEST_SUITE_P(Multiprecision, Soundness, Multiprecision_kernels, Kernel_name);
}  // namespace relgeo::test
