// test/support/fp_environments.h — the non-default floating-point environments
// the tests run relgeo under: flush-to-zero, denormals-are-zero, both, and the
// three directed rounding modes (alone and with FTZ/DAZ), as a client built
// with -ffast-math or calling fesetround would leave them.
#pragma once

#include <string>
#include <vector>

namespace relgeo::test {

struct Fp_environment_setting {
  std::string name;
  bool flush_to_zero = false;
  bool denormals_are_zero = false;
  int rounding = 0;  ///< FE_TONEAREST, FE_UPWARD, FE_DOWNWARD or FE_TOWARDZERO
  /// x86's x87 precision control: 64 (the default), 53 or 24 significand
  /// bits for long double arithmetic (set by some runtimes and graphics
  /// libraries; it changes nothing in float or double, which run on SSE).
  int x87_precision = 64;
};

/// Every setting the platform supports (FTZ/DAZ only on x86).
std::vector<Fp_environment_setting> non_default_fp_environments();

/// The x87 precision control at 53 and 24 bits, alone and with directed
/// rounding (x86 only; empty elsewhere): the environments of long double.
std::vector<Fp_environment_setting> reduced_x87_precision_environments();

/// Sets `s` for its lifetime (out of line, so no computation of the caller is
/// moved across the switch) and restores the default environment after.
class Scoped_fp_environment {
 public:
  explicit Scoped_fp_environment(const Fp_environment_setting& s);
  ~Scoped_fp_environment();
  Scoped_fp_environment(const Scoped_fp_environment&) = delete;
  Scoped_fp_environment& operator=(const Scoped_fp_environment&) = delete;
};

}  // namespace relgeo::test
