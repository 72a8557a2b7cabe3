// Soundness suite: the floating-point certified kernels (fail-safe, interval, filtered).
#include "relgeo/kernel/failsafe_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/interval_kernel.h"
#include "soundness_suite.h"

namespace relgeo::test {
using Float_certified_kernels =
    ::testing::Types<Failsafe_kernel<float>, Failsafe_kernel<double>, Failsafe_kernel<long double>,
                     Interval_kernel, Filtered_exact_kernel>;
INSTANTIATE_TYPED_TEST_SUITE_P(FloatCertified, Soundness, Float_certified_kernels, Kernel_name);
}  // namespace relgeo::test
