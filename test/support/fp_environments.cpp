#include "fp_environments.h"

#include <cfenv>
#include <cstdint>
#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#endif

#include "relgeo/core/fp_environment.h"

namespace relgeo::test {

std::vector<Fp_environment_setting> non_default_fp_environments() {
  std::vector<Fp_environment_setting> out;
#if defined(__x86_64__) || defined(__i386__)
  out.push_back({"flush-to-zero", true, false, FE_TONEAREST});
  out.push_back({"denormals-are-zero", false, true, FE_TONEAREST});
  out.push_back({"ftz+daz", true, true, FE_TONEAREST});
#endif
  out.push_back({"upward", false, false, FE_UPWARD});
  out.push_back({"downward", false, false, FE_DOWNWARD});
  out.push_back({"toward-zero", false, false, FE_TOWARDZERO});
#if defined(__x86_64__) || defined(__i386__)
  out.push_back({"ftz+daz+upward", true, true, FE_UPWARD});
  out.push_back({"ftz+daz+downward", true, true, FE_DOWNWARD});
#endif
  return out;
}

std::vector<Fp_environment_setting> reduced_x87_precision_environments() {
  std::vector<Fp_environment_setting> out;
#if defined(__x86_64__) || defined(__i386__)
  out.push_back({"x87-53-bit", false, false, FE_TONEAREST, 53});
  out.push_back({"x87-24-bit", false, false, FE_TONEAREST, 24});
  out.push_back({"x87-53-bit+upward", false, false, FE_UPWARD, 53});
  out.push_back({"x87-53-bit+toward-zero", false, false, FE_TOWARDZERO, 53});
#endif
  return out;
}

[[gnu::noinline]] Scoped_fp_environment::Scoped_fp_environment(const Fp_environment_setting& s) {
  std::fesetround(s.rounding);
#if defined(__x86_64__) || defined(__i386__)
  unsigned csr = _mm_getcsr();
  if (s.flush_to_zero) csr |= 0x8000u;
  if (s.denormals_are_zero) csr |= 0x0040u;
  _mm_setcsr(csr);
  if (s.x87_precision != 64) {
    std::uint16_t cw = 0;
    __asm__ volatile("fnstcw %0" : "=m"(cw));
    cw = static_cast<std::uint16_t>((cw & ~0x0300u) | (s.x87_precision == 53 ? 0x0200u : 0x0000u));
    __asm__ volatile("fldcw %0" : : "m"(cw));
  }
#endif
  __asm__ volatile("" ::: "memory");
}

[[gnu::noinline]] Scoped_fp_environment::~Scoped_fp_environment() {
  __asm__ volatile("" ::: "memory");
  std::fesetenv(FE_DFL_ENV);
}

}  // namespace relgeo::test
