// CGAL's Epeck through relgeo's adapter in every floating-point environment.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "fp_environment_soundness.h"
#include "relgeo/kernel/cgal_kernel.h"

namespace relgeo::test {
namespace {

TEST(FpEnvironmentSoundness, CgalEpeck) { expect_sound_in_every_environment<Cgal_kernel<CGAL::Epeck>>(); }

}  // namespace
}  // namespace relgeo::test
