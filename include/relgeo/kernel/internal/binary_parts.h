// relgeo/kernel/internal/binary_parts.h — a finite double as the integer
// mantissa and power of two it is made of, read from its bits.
//
// Reading the bits, not computing with the value (frexp, ldexp, a GMP or
// MPFR conversion, a comparison), gives the same answer in every
// floating-point environment: under denormals-are-zero every arithmetic
// instruction, conversions and comparisons included, reads a subnormal as 0.
#pragma once

#include <gmp.h>
#include <gmpxx.h>

#include <bit>
#include <cstdint>
#include <cstdlib>

namespace relgeo::internal {

/// v = mantissa * 2^exponent exactly, |mantissa| < 2^53.
struct Binary_parts {
  std::int64_t mantissa;
  int exponent;
};

/// The parts of a finite double (0 for +-0). \pre v is finite.
inline Binary_parts binary_parts(double v) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
  const int biased = static_cast<int>((bits >> 52) & 0x7FF);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  // Subnormals have no hidden bit and the exponent of the smallest normals.
  const std::uint64_t magnitude = biased == 0 ? fraction : fraction | (std::uint64_t{1} << 52);
  const int exponent = (biased == 0 ? 1 : biased) - 1075;
  const auto m = static_cast<std::int64_t>(magnitude);
  return {(bits >> 63) ? -m : m, exponent};
}

/// z = m, for any width of long (mpz_set_si takes a long).
inline void set_mpz(mpz_ptr z, std::int64_t m) {
  const std::uint64_t magnitude = m < 0 ? 0 - static_cast<std::uint64_t>(m) : static_cast<std::uint64_t>(m);
  mpz_import(z, 1, 1, sizeof magnitude, 0, 0, &magnitude);
  if (m < 0) mpz_neg(z, z);
}

/// The exact rational value of a finite double.
inline mpq_class exact_rational(double v) {
  Binary_parts p = binary_parts(v);
  mpq_class q;  // 0/1
  if (p.mantissa == 0) return q;
  // An odd numerator over a power of two is already in lowest terms.
  const int zeros = std::countr_zero(static_cast<std::uint64_t>(std::abs(p.mantissa)));
  p.mantissa /= std::int64_t{1} << zeros;
  p.exponent += zeros;
  set_mpz(q.get_num_mpz_t(), p.mantissa);
  if (p.exponent >= 0) mpz_mul_2exp(q.get_num_mpz_t(), q.get_num_mpz_t(), static_cast<mp_bitcnt_t>(p.exponent));
  else mpz_mul_2exp(q.get_den_mpz_t(), q.get_den_mpz_t(), static_cast<mp_bitcnt_t>(-p.exponent));
  return q;
}

}  // namespace relgeo::internal
