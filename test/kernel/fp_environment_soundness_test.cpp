// relgeo's own kernels in every floating-point environment (see
// fp_environment_soundness.h); CGAL's adapters are in their own TUs.
#include "fp_environment_soundness.h"

#include "relgeo/kernel.h"

namespace relgeo::test {
namespace {

TEST(FpEnvironmentSoundness, FailsafeDouble) { expect_sound_in_every_environment<Failsafe_kernel<double>>(); }
TEST(FpEnvironmentSoundness, FailsafeFloat) {
  expect_sound_in_every_environment<Failsafe_kernel<float>>(Input_precision::binary32);
}
TEST(FpEnvironmentSoundness, FailsafeLongDouble) { expect_sound_in_every_environment<Failsafe_kernel<long double>>(); }
TEST(FpEnvironmentSoundness, Interval) { expect_sound_in_every_environment<Interval_kernel>(); }
TEST(FpEnvironmentSoundness, FilteredExact) { expect_sound_in_every_environment<Filtered_exact_kernel>(); }
TEST(FpEnvironmentSoundness, Exact) { expect_sound_in_every_environment<Exact_kernel>(); }

TEST(FpEnvironmentSoundness, TheFamiliesAreHardForANaiveKernel) {
  // The environments do reach the arithmetic, and the families meet them: the
  // naive kernel, which computes in the caller's environment, is wrong there.
  const Environment_data& d = environment_data(Input_precision::binary64);
  std::size_t wrong_flushed = 0, wrong_directed = 0;
  for (const auto& s : non_default_fp_environments()) {
    const std::size_t w = wrong_answers_in<Naive_kernel<double>>(s, d);
    (s.flush_to_zero || s.denormals_are_zero ? wrong_flushed : wrong_directed) += w;
  }
#if defined(__x86_64__) || defined(__i386__)
  EXPECT_GT(wrong_flushed, 0u);
#endif
  EXPECT_GT(wrong_directed, 0u);
}

}  // namespace
}  // namespace relgeo::test
