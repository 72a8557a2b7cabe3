// CGAL's Epick through relgeo's adapter in every floating-point environment
// (CGAL's own filters assume round to nearest without FTZ/DAZ).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "fp_environment_soundness.h"
#include "relgeo/kernel/cgal_kernel.h"

namespace relgeo::test {
namespace {

TEST(FpEnvironmentSoundness, CgalEpick) { expect_sound_in_every_environment<Cgal_kernel<CGAL::Epick>>(); }

TEST(FpEnvironmentSoundness, CgalEpickAloneIsWrongUnderDenormalsAreZero) {
  // Why the adapter establishes the default environment: CGAL's functor
  // called directly under DAZ answers wrong on subnormal coordinates.
#if defined(__x86_64__) || defined(__i386__)
  const Environment_data& d = environment_data(Input_precision::binary64);
  std::size_t wrong = 0;
  const auto& o2 = d.orientation_2;
  {
    const Scoped_fp_environment daz({"denormals-are-zero", false, true, 0});
    const CGAL::Epick::Orientation_2 orientation;
    for (std::size_t i = 0; i < o2.cases.size(); ++i) {
      const auto& c = o2.cases[i];
      const int s = orientation(CGAL::Epick::Point_2(c.px, c.py), CGAL::Epick::Point_2(c.qx, c.qy),
                                CGAL::Epick::Point_2(c.rx, c.ry));
      wrong += s != to_int(o2.exact[i]);
    }
  }
  EXPECT_GT(wrong, 0u);
#else
  GTEST_SKIP() << "denormals-are-zero is set on x86 only";
#endif
}

}  // namespace
}  // namespace relgeo::test
