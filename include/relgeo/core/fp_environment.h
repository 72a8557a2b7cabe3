// relgeo/core/fp_environment.h — the floating-point environment relgeo's
// certified computations assume, detected and established around them.
//
// Error-free transformations (TwoSum, TwoProduct), outward-rounded intervals
// and exact decoding of doubles assume the default IEEE environment: round to
// nearest, subnormals neither flushed to zero (FTZ) on output nor read as zero
// (DAZ) on input, and x87 arithmetic at its full 64-bit precision. A client
// can change that process-wide (fesetround, or any object built with
// -ffast-math, which sets FTZ/DAZ at start-up), so relgeo never relies on the
// caller having left it alone:
//  * the semi-static filters (kernel/internal/semi_static_filter.h) are
//    derived for every rounding mode and for FTZ/DAZ, so their fast path needs
//    no check;
//  * everything else that computes certified answers in hardware floating
//    point (the later stages of Filtered_exact_kernel, Interval_kernel, the
//    algorithms' entry points) holds a Default_fp_environment for its
//    duration: one read of the control registers, and only when they are not
//    the default, a switch to the default environment and back.
#pragma once

#include <cfenv>
#include <cstdint>

#include "relgeo/core/errors.h"

namespace relgeo {

/// Whether the calling thread's floating-point environment is the default
/// one: round to nearest, no flush-to-zero, no denormals-are-zero (and, on
/// x86, the x87 unit at 64-bit precision, rounding to nearest).
inline bool is_default_fp_environment() noexcept {
#if defined(__x86_64__) || defined(__i386__)
  // MXCSR: DAZ (bit 6), rounding control (13-14), FTZ (15). x87 control
  // word: precision control (8-9, 0b11 = 64 bits), rounding control (10-11).
  const unsigned mxcsr = __builtin_ia32_stmxcsr();
  std::uint16_t x87 = 0;
  __asm__ volatile("fnstcw %0" : "=m"(x87));
  return (mxcsr & 0xE040u) == 0 && (x87 & 0x0F00u) == 0x0300u;
#elif defined(__aarch64__)
  // FPCR: FZ16 (bit 19), RMode (22-23), FZ (24).
  const unsigned fpcr = __builtin_aarch64_get_fpcr();
  return (fpcr & 0x01C80000u) == 0;
#else
  // Portable fallback: the rounding mode from <cfenv>, flush-to-zero probed
  // on a subnormal result (volatile: computed at run time, in this mode).
  static volatile double smallest_normal = 0x1p-1022;
  const double half_of_it = smallest_normal * 0.5;
  return std::fegetround() == FE_TONEAREST && half_of_it != 0;
#endif
}

/// Whether long double arithmetic rounds to its own precision: on x86 the
/// x87 unit's precision control (bits 8-9 of its control word) can be set to
/// 24 or 53 bits (some runtimes and graphics libraries do), and then every
/// long double operation rounds to that many bits, which error bounds
/// derived for 64 cannot cover. One read of the control word; true
/// elsewhere.
inline bool long_double_at_full_precision() noexcept {
#if defined(__x86_64__) || defined(__i386__)
  std::uint16_t x87 = 0;
  __asm__ volatile("fnstcw %0" : "=m"(x87));
  return (x87 & 0x0300u) == 0x0300u;
#else
  return true;
#endif
}

/// The environment cannot be made the default (fesetenv failed).
class Fp_environment_error : public Error {
 public:
  explicit Fp_environment_error(const std::string& what) : Error(Error_code::computation_failure, what) {}
};

/// \brief Scope guard: the default floating-point environment for its
/// lifetime.
///
/// When the environment already is the default (the usual case) it costs one
/// read of the control registers and does nothing else. Otherwise it saves the
/// caller's environment, installs FE_DFL_ENV (round to nearest, no FTZ/DAZ)
/// and restores the caller's on destruction, also when an exception leaves
/// the scope. Computations that depend on the environment must run after it
/// is constructed: in its scope, through calls (not hoisted across them).
class Default_fp_environment {
 public:
  Default_fp_environment() {
    if (is_default_fp_environment()) [[likely]]
      return;
    std::fegetenv(&saved_);
    if (std::fesetenv(FE_DFL_ENV) != 0 || !is_default_fp_environment()) {
      std::fesetenv(&saved_);
      throw Fp_environment_error("relgeo: cannot establish the default floating-point environment");
    }
    changed_ = true;
    compiler_barrier();
  }
  ~Default_fp_environment() {
    if (!changed_) return;
    compiler_barrier();
    std::fesetenv(&saved_);
  }
  Default_fp_environment(const Default_fp_environment&) = delete;
  Default_fp_environment& operator=(const Default_fp_environment&) = delete;

  /// Whether the caller's environment was not the default (and was replaced).
  bool changed() const noexcept { return changed_; }

 private:
  // Values in memory are read again after the switch (not reused from before).
  static void compiler_barrier() noexcept { __asm__ volatile("" ::: "memory"); }

  std::fenv_t saved_{};
  bool changed_ = false;
};

/// What an algorithm holds for its duration: Default_fp_environment when it
/// computes certified answers (`Establish`, e.g. K::is_certified), nothing
/// otherwise: a naive kernel computes in the caller's environment, and what
/// that environment does to it is part of what it shows.
template <bool Establish>
class Default_fp_environment_if : public Default_fp_environment {};
template <>
class Default_fp_environment_if<false> {
 public:
  Default_fp_environment_if() noexcept {}  // user-provided: a scope object, not an unused variable
};

namespace internal {

/// Makes `value` complete in memory at this point. Compilers assume one fixed
/// floating-point environment and may move arithmetic across a switch of
/// it: clang 14 moved the conversion of call_in_default_fp_environment's
/// result after the destructor that restores the caller's environment, so
/// Failsafe_kernel<float>::from_double flushed a subnormal under FTZ after
/// all. A volatile asm that reads and writes the value stays in order with
/// the switches (also volatile asm and calls).
template <class T>
inline void complete_here(T& value) noexcept {
  __asm__ volatile("" : "+m"(value));
}

/// f() evaluated in a Default_fp_environment, out of line so that none of
/// its arithmetic is moved before the switch.
template <class F>
[[gnu::noinline]] auto call_in_default_fp_environment(const F& f) {
  const Default_fp_environment environment;
  auto result = f();
  complete_here(result);  // before the caller's environment is restored
  return result;
}

/// f() in the default floating-point environment: inline when the caller's
/// environment is the default (one read of the control registers), through
/// call_in_default_fp_environment otherwise.
template <class F>
inline auto in_default_fp_environment(const F& f) {
  if (is_default_fp_environment()) [[likely]]
    return f();
  return call_in_default_fp_environment(f);
}

}  // namespace internal
}  // namespace relgeo
