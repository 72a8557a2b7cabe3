// relgeo/kernel/internal/exact_dyadic.h — exact signs of the predicate
// determinants for double inputs, in GMP integers.
//
// Every finite double is m * 2^e with an integer m (|m| < 2^53). Scaling all
// coordinates of one predicate by 2^-emin (emin = the smallest such e) makes
// them integers without changing the determinant's sign, so the determinant is
// evaluated exactly with mpz_t: no gcd (as an mpq_class evaluation would do),
// and the scratch integers are reused per thread, so after warm-up no memory is
// allocated. This is the last stage of Filtered_exact_kernel.
#pragma once

#include <gmp.h>

#include <algorithm>
#include <array>
#include <climits>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/dyadic.h"

namespace relgeo::internal {

/// Thread-local GMP scratch registers for exact evaluation.
template <std::size_t N>
class Mpz_scratch {
 public:
  Mpz_scratch() {
    for (auto& z : regs_) mpz_init2(z, 256);
  }
  ~Mpz_scratch() {
    for (auto& z : regs_) mpz_clear(z);
  }
  Mpz_scratch(const Mpz_scratch&) = delete;
  Mpz_scratch& operator=(const Mpz_scratch&) = delete;
  mpz_ptr operator[](std::size_t i) { return regs_[i]; }

 private:
  std::array<mpz_t, N> regs_;
};

/// Loads the finite doubles v[0..n) into z[0..n) as integers, all scaled by the
/// same power of two.
/// \pre every v[i] is finite.
template <std::size_t N, std::size_t M>
void load_scaled_integers(const std::array<double, N>& v, Mpz_scratch<M>& z) {
  static_assert(N <= M);
  std::array<Binary_parts, N> parts{};
  int emin = INT_MAX;
  for (std::size_t i = 0; i < N; ++i) {
    parts[i] = binary_parts(v[i]);
    if (parts[i].mantissa != 0) emin = std::min(emin, parts[i].exponent);
  }
  for (std::size_t i = 0; i < N; ++i) {
    set_mpz(z[i], parts[i].mantissa);
    if (parts[i].mantissa != 0) mpz_mul_2exp(z[i], z[i], static_cast<mp_bitcnt_t>(parts[i].exponent - emin));
  }
}

/// Exact sign of orientation_2 of double points. \pre all coordinates finite.
inline Certified_sign exact_orientation_2(double px, double py, double qx, double qy, double rx,
                                          double ry) {
  thread_local Mpz_scratch<10> z;
  load_scaled_integers(std::array<double, 6>{px, py, qx, qy, rx, ry}, z);
  // z0..z5 = px py qx qy rx ry
  mpz_sub(z[6], z[2], z[0]);   // a = qx - px
  mpz_sub(z[7], z[5], z[1]);   // b = ry - py
  mpz_sub(z[8], z[3], z[1]);   // c = qy - py
  mpz_sub(z[9], z[4], z[0]);   // d = rx - px
  mpz_mul(z[6], z[6], z[7]);   // ab
  mpz_mul(z[8], z[8], z[9]);   // cd
  const int s = mpz_cmp(z[6], z[8]);
  return s > 0 ? Certified_sign::positive : (s < 0 ? Certified_sign::negative : Certified_sign::zero);
}

/// Exact sign of orientation_3 of double points. \pre all coordinates finite.
inline Certified_sign exact_orientation_3(const std::array<double, 12>& c) {
  thread_local Mpz_scratch<24> z;
  load_scaled_integers(c, z);
  // c = px py pz qx qy qz rx ry rz sx sy sz  -> z[0..11]
  auto diff = [&](std::size_t out, std::size_t a, std::size_t b) { mpz_sub(z[out], z[a], z[b]); };
  diff(12, 3, 0);  diff(13, 6, 0);  diff(14, 9, 0);   // a00 a01 a02 (x)
  diff(15, 4, 1);  diff(16, 7, 1);  diff(17, 10, 1);  // a10 a11 a12 (y)
  diff(18, 5, 2);  diff(19, 8, 2);  diff(20, 11, 2);  // a20 a21 a22 (z)
  // m01 = a00*a11 - a10*a01 -> z21 ; m02 = a00*a21 - a20*a01 -> z22 ; m12 = a10*a21 - a20*a11 -> z23
  mpz_mul(z[21], z[12], z[16]);
  mpz_mul(z[0], z[15], z[13]);
  mpz_sub(z[21], z[21], z[0]);
  mpz_mul(z[22], z[12], z[19]);
  mpz_mul(z[0], z[18], z[13]);
  mpz_sub(z[22], z[22], z[0]);
  mpz_mul(z[23], z[15], z[19]);
  mpz_mul(z[0], z[18], z[16]);
  mpz_sub(z[23], z[23], z[0]);
  // det = m01*a22 - m02*a12 + m12*a02
  mpz_mul(z[1], z[21], z[20]);
  mpz_mul(z[2], z[22], z[17]);
  mpz_sub(z[1], z[1], z[2]);
  mpz_mul(z[2], z[23], z[14]);
  mpz_add(z[1], z[1], z[2]);
  const int s = mpz_sgn(z[1]);
  return s > 0 ? Certified_sign::positive : (s < 0 ? Certified_sign::negative : Certified_sign::zero);
}

}  // namespace relgeo::internal
