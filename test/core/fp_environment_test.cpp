// Default_fp_environment: detects every non-default environment, establishes
// the default one for its scope and gives the caller's back, also when an
// exception leaves the scope.
#include <gtest/gtest.h>

#include <cfenv>
#include <stdexcept>

#include "relgeo/core/fp_environment.h"
#include "support/fp_environments.h"

namespace relgeo {
namespace {

// Half the smallest normal double, computed at run time in the current environment.
[[gnu::noinline]] double half_of_smallest_normal() {
  volatile double smallest = 0x1p-1022;
  return smallest * 0.5;
}

TEST(FpEnvironment, TheTestProcessStartsInTheDefaultEnvironment) {
  EXPECT_TRUE(is_default_fp_environment());
  EXPECT_NE(half_of_smallest_normal(), 0.0);
}

TEST(FpEnvironment, EverySettingIsDetectedAndReplacedInScope) {
  for (const auto& s : test::non_default_fp_environments()) {
    const test::Scoped_fp_environment caller(s);
    EXPECT_FALSE(is_default_fp_environment()) << s.name;
    const int rounding = std::fegetround();
    {
      const Default_fp_environment scope;
      EXPECT_TRUE(scope.changed()) << s.name;
      EXPECT_TRUE(is_default_fp_environment()) << s.name;
      EXPECT_EQ(std::fegetround(), FE_TONEAREST) << s.name;
      EXPECT_NE(half_of_smallest_normal(), 0.0) << s.name << ": subnormal results flushed inside the scope";
    }
    EXPECT_FALSE(is_default_fp_environment()) << s.name << ": the caller's environment was not restored";
    EXPECT_EQ(std::fegetround(), rounding) << s.name;
    if (s.flush_to_zero) {
      EXPECT_EQ(half_of_smallest_normal(), 0.0) << s.name;
    }
  }
}

TEST(FpEnvironment, AReducedX87PrecisionIsDetectedAndReplacedInScope) {
  for (const auto& s : test::reduced_x87_precision_environments()) {
    const test::Scoped_fp_environment caller(s);
    EXPECT_FALSE(is_default_fp_environment()) << s.name;
    EXPECT_FALSE(long_double_at_full_precision()) << s.name;
    {
      const Default_fp_environment scope;
      EXPECT_TRUE(scope.changed()) << s.name;
      EXPECT_TRUE(long_double_at_full_precision()) << s.name;
    }
    EXPECT_FALSE(long_double_at_full_precision()) << s.name << ": the caller's control word was not restored";
  }
  EXPECT_TRUE(long_double_at_full_precision());
}

TEST(FpEnvironment, TheDefaultEnvironmentIsLeftAlone) {
  const Default_fp_environment scope;
  EXPECT_FALSE(scope.changed());
  EXPECT_TRUE(is_default_fp_environment());
}

TEST(FpEnvironment, AnExceptionLeavingTheScopeRestoresTheCallersEnvironment) {
  const test::Scoped_fp_environment caller({"upward", false, false, FE_UPWARD});
  try {
    const Default_fp_environment scope;
    ASSERT_EQ(std::fegetround(), FE_TONEAREST);
    throw std::runtime_error("leaving");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(std::fegetround(), FE_UPWARD);
}

TEST(FpEnvironment, ConditionalScopeForNaiveComputations) {
  const test::Scoped_fp_environment caller({"downward", false, false, FE_DOWNWARD});
  {
    const Default_fp_environment_if<false> naive;  // computes in the caller's environment
    EXPECT_EQ(std::fegetround(), FE_DOWNWARD);
  }
  {
    const Default_fp_environment_if<true> certified;
    EXPECT_EQ(std::fegetround(), FE_TONEAREST);
  }
}

}  // namespace
}  // namespace relgeo
