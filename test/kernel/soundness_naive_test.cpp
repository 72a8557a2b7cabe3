// Soundness suite: the naive kernels (wrong answers counted, never uncertain).
#include "relgeo/kernel/naive_kernel.h"
#include "soundness_suite.h"

namespace relgeo::test {
using Naive_kernels = ::testing::Types<Naive_kernel<float>, Naive_kernel<double>, Naive_kernel<long double>>;
INSTANTIATE_TYPED_TEST_SUITE_P(Naive, Soundness, Naive_kernels, Kernel_name);
}  // namespace relgeo::test
