// relgeo/mesh/internal/exact_volume.h — the signed volume of a triangle mesh
// (per connected component and in total), exactly for coordinates that are
// doubles or rationals, as a certified enclosure otherwise.
//
// The signed volume is (1/6) sum over faces (a, b, c) of det(a, b, c), the
// orientation determinant against the origin (a fixed point: for a closed
// mesh any point gives the same value). For double coordinates each
// determinant is the sum of six signed products of three coordinates; each
// coordinate is m 2^e with an integer m of at most 53 bits, so a product is
// an integer of at most 159 bits times 2^(e1 + e2 + e3), which integer
// multiplications give exactly and which is added into a fixed-point
// accumulator (Exact_sum) whose 32-bit limbs span every double's exponent:
// no rounding anywhere, about 75 ns per face on a 2-core x86-64 machine
// (relgeo_mesh_benchmark's volume rows: splitting each product into four
// doubles by error-free products and adding those took 230). When
// every nonzero coordinate lies in [2^-200, 2^200] every product lands in
// the accumulator's range; faces with a coordinate outside take GMP
// rationals. Rational coordinates
// (and MPFR, long double: exact through Number_traits::to_rational) sum in
// GMP rationals; intervals and other types sum as intervals (an enclosure).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/dyadic.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/interval.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

/// An exact fixed-point sum: 68 signed 64-bit limbs, limb k holding a
/// multiple of 2^(32 k - 1074), so every finite double and every product of
/// three coordinates in the fast range fits (add_determinant). A term lands on
/// consecutive limbs as pieces below 2^32. Carries are propagated every 2^30
/// additions, before any limb can overflow.
class Exact_sum {
 public:
  /// Adds (-1)^negative (p2 2^128 + p1 2^64 + p0) 2^exponent. \pre p2 < 2^32,
  /// 0 <= exponent + 1074 and exponent + 1074 + 192 < 32 (size - 1) (the
  /// top limb stays headroom).
  void add(std::uint64_t p0, std::uint64_t p1, std::uint64_t p2, int exponent, bool negative) {
    const int position = exponent + 1074;
    const int shift = position & 31;
    // The 192-bit value shifted left by `shift` (< 32): p2 << shift still fits.
    const std::uint64_t q0 = p0 << shift;
    const std::uint64_t q1 = shift == 0 ? p1 : (p1 << shift) | (p0 >> (64 - shift));
    const std::uint64_t q2 = shift == 0 ? p2 : (p2 << shift) | (p1 >> (64 - shift));
    const std::array<std::int64_t, 6> piece{
        static_cast<std::int64_t>(q0 & 0xFFFFFFFFu), static_cast<std::int64_t>(q0 >> 32),
        static_cast<std::int64_t>(q1 & 0xFFFFFFFFu), static_cast<std::int64_t>(q1 >> 32),
        static_cast<std::int64_t>(q2 & 0xFFFFFFFFu), static_cast<std::int64_t>(q2 >> 32)};
    const std::size_t k = static_cast<std::size_t>(position >> 5);
    if (negative)
      for (std::size_t j = 0; j < 6; ++j) limb_[k + j] -= piece[j];
    else
      for (std::size_t j = 0; j < 6; ++j) limb_[k + j] += piece[j];
    if (++pending_ == (1u << 30)) normalise();
  }
  void add(Exact_sum other) {
    other.normalise();
    normalise();
    for (std::size_t k = 0; k < size; ++k) limb_[k] += other.limb_[k];
    pending_ = 1;
  }
  Certified_sign sign() {
    normalise();
    if (limb_[size - 1] < 0) return Certified_sign::negative;  // only the top limb can be negative
    for (std::int64_t l : limb_)
      if (l != 0) return Certified_sign::positive;
    return Certified_sign::zero;
  }
  mpq_class value() {
    normalise();
    mpz_class z = static_cast<long>(limb_[size - 1]);
    for (std::size_t k = size - 1; k-- > 0;) {
      z <<= 32;
      z += static_cast<unsigned long>(limb_[k]);
    }
    return to_rational(z, -1074);
  }

 private:
  static constexpr std::size_t size = 68;  // 2046 bit positions + 3 limbs of headroom for carries
  // Limbs 0..size-2 into [0, 2^32), the carries moved up (floor division).
  void normalise() {
    for (std::size_t k = 0; k + 1 < size; ++k) {
      const std::int64_t carry = limb_[k] >> 32;  // arithmetic shift: floor
      limb_[k] -= carry * (std::int64_t{1} << 32);
      limb_[k + 1] += carry;
    }
    pending_ = 0;
  }
  std::array<std::int64_t, size> limb_{};
  std::uint32_t pending_ = 0;
};

/// a b as two 64-bit words.
struct Wide_product {
  std::uint64_t low, high;
};
/// From four 32 x 32-bit products: for compilers without a 128-bit integer
/// (tested against the one below).
inline Wide_product multiply_wide_portable(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t a0 = a & 0xFFFFFFFFu, a1 = a >> 32, b0 = b & 0xFFFFFFFFu, b1 = b >> 32;
  const std::uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  const std::uint64_t middle = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
  return {(middle << 32) | (p00 & 0xFFFFFFFFu), p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32)};
}
inline Wide_product multiply_wide(std::uint64_t a, std::uint64_t b) {
#if defined(__SIZEOF_INT128__)
  __extension__ using U128 = unsigned __int128;  // GCC and Clang: one instruction on x86-64
  const U128 p = static_cast<U128>(a) * b;
  return {static_cast<std::uint64_t>(p), static_cast<std::uint64_t>(p >> 64)};
#else
  return multiply_wide_portable(a, b);
#endif
}

/// Whether products of three such coordinates land in Exact_sum's range
/// (file comment).
inline bool splits_exactly(double v) {
  const double a = std::abs(v);
  return a == 0 || (a >= 0x1p-200 && a <= 0x1p200);
}

/// det(a, b, c) = a . (b x c), exactly, into s: six products of three
/// coordinates as integers (binary_parts) times powers of two. \pre every
/// coordinate satisfies splits_exactly (so every product's exponent lies in
/// [-756, 444] and its bits below 2^606: inside the accumulator).
inline void add_determinant(Exact_sum& s, const std::array<Binary_parts, 3>& a, const std::array<Binary_parts, 3>& b,
                            const std::array<Binary_parts, 3>& c) {
  const auto product = [&s](const Binary_parts& x, const Binary_parts& y, const Binary_parts& z, bool negate) {
    if (x.mantissa == 0 || y.mantissa == 0 || z.mantissa == 0) return;
    const auto magnitude = [](std::int64_t m) { return static_cast<std::uint64_t>(m < 0 ? -m : m); };
    // |x y| < 2^106, then times |z| < 2^53: below 2^159, as three 64-bit words.
    const Wide_product xy = multiply_wide(magnitude(x.mantissa), magnitude(y.mantissa));
    const std::uint64_t mz = magnitude(z.mantissa);
    const Wide_product low = multiply_wide(xy.low, mz), high = multiply_wide(xy.high, mz);
    const std::uint64_t middle = low.high + high.low;
    const bool negative = ((x.mantissa < 0) != (y.mantissa < 0)) != ((z.mantissa < 0) != negate);
    s.add(low.low, middle, high.high + (middle < low.high), x.exponent + y.exponent + z.exponent, negative);
  };
  product(a[0], b[1], c[2], false);
  product(a[0], b[2], c[1], true);
  product(a[1], b[2], c[0], false);
  product(a[1], b[0], c[2], true);
  product(a[2], b[0], c[1], false);
  product(a[2], b[1], c[0], true);
}

template <class T>
mpq_class rational_determinant(const std::array<T, 3>& a, const std::array<T, 3>& b, const std::array<T, 3>& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/// Signed volumes of the components and of the whole mesh.
struct Signed_volumes {
  bool exact = false;                        ///< values exact (else enclosures)
  mpq_class total;                           ///< the exact volume (when exact)
  double total_lower = 0, total_upper = 0;   ///< bounds of the volume
  std::vector<Certified_sign> sign;          ///< per component
  std::vector<double> value;                 ///< the first `listed` components: nearest double (midpoint when not exact)
};

/// Number types whose values convert exactly to GMP rationals.
template <class T>
concept Has_exact_rational = requires(const T& x) {
  { Number_traits<T>::to_rational(x) } -> std::convertible_to<mpq_class>;
};

/// The signed volumes of the components (component[f] in [0, components)
/// for every face): the sign of each, the value of the first `listed`.
/// \pre indices in range, finite coordinates.
template <class P>
Signed_volumes signed_volumes(const Triangle_mesh<P>& m, const std::vector<Index>& component, std::size_t components,
                              std::size_t listed) {
  using A = Point_access<P>;
  using FT = typename A::FT;
  const Default_fp_environment environment;  // the enclosures (last branch) need round to nearest
  Signed_volumes r;
  r.sign.assign(components, Certified_sign::zero);
  r.value.assign(std::min(components, listed), 0.0);
  if constexpr (std::is_same_v<FT, double> || std::is_same_v<FT, float>) {
    r.exact = true;
    const auto coords = [&](Index v) {
      const P& p = m.vertices[v];
      return std::array<double, 3>{double(A::x(p)), double(A::y(p)), double(A::z(p))};
    };
    // Each coordinate decoded once (a vertex is in six faces on average).
    std::vector<char> safe(m.vertices.size());
    std::vector<std::array<Binary_parts, 3>> parts(m.vertices.size());
    for (Index v = 0; v < m.vertices.size(); ++v) {
      const auto c = coords(v);
      safe[v] = splits_exactly(c[0]) && splits_exactly(c[1]) && splits_exactly(c[2]);
      if (safe[v]) parts[v] = {binary_parts(c[0]), binary_parts(c[1]), binary_parts(c[2])};
    }
    // One component at a time (faces ordered by component, counting sort):
    // one accumulator in memory however many components there are.
    std::vector<Index> begin(components + 1, 0), order(m.faces.size());
    for (Index f = 0; f < m.faces.size(); ++f) ++begin[component[f] + 1];
    for (std::size_t c = 0; c < components; ++c) begin[c + 1] += begin[c];
    {
      std::vector<Index> fill(begin.begin(), begin.end() - 1);
      for (Index f = 0; f < m.faces.size(); ++f) order[fill[component[f]]++] = f;
    }
    Exact_sum total;
    for (std::size_t c = 0; c < components; ++c) {
      Exact_sum sum;
      mpq_class rest = 0;  // faces outside the splitting range (rare)
      bool has_rest = false;
      for (Index k = begin[c]; k < begin[c + 1]; ++k) {
        const Triangle& t = m.faces[order[k]];
        if (safe[t[0]] && safe[t[1]] && safe[t[2]]) {
          add_determinant(sum, parts[t[0]], parts[t[1]], parts[t[2]]);
          continue;
        }
        std::array<std::array<mpq_class, 3>, 3> q;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) q[i][j] = exact_rational(coords(t[i])[j]);
        rest += rational_determinant(q[0], q[1], q[2]);
        has_rest = true;
      }
      if (has_rest) {
        const mpq_class v = sum.value() + rest;
        r.sign[c] = sign_of(sgn(v));
        if (c < listed) r.value[c] = round_rational<double>(v / 6, Rounding::to_nearest);
        r.total += rest;
      } else {
        r.sign[c] = sum.sign();
        if (c < listed) r.value[c] = round_rational<double>(sum.value() / 6, Rounding::to_nearest);
      }
      total.add(sum);
    }
    r.total = (r.total + total.value()) / 6;
  } else if constexpr (Has_exact_rational<FT>) {
    r.exact = true;
    std::vector<mpq_class> sums(components);
    const auto coords = [&](Index v) {
      const P& p = m.vertices[v];
      return std::array<mpq_class, 3>{mpq_class(Number_traits<FT>::to_rational(A::x(p))),
                                      mpq_class(Number_traits<FT>::to_rational(A::y(p))),
                                      mpq_class(Number_traits<FT>::to_rational(A::z(p)))};
    };
    for (Index f = 0; f < m.faces.size(); ++f) {
      const Triangle& t = m.faces[f];
      sums[component[f]] += rational_determinant(coords(t[0]), coords(t[1]), coords(t[2]));
    }
    for (std::size_t c = 0; c < components; ++c) {
      r.sign[c] = sign_of(sgn(sums[c]));
      if (c < listed) r.value[c] = round_rational<double>(sums[c] / 6, Rounding::to_nearest);
      r.total += sums[c];
    }
    r.total /= 6;
  } else {
    // Enclosures: each coordinate as the interval of its double bounds.
    std::vector<Interval> sums(components, Interval(0.0));
    const auto coords = [&](Index v) {
      const P& p = m.vertices[v];
      return std::array<Interval, 3>{Interval(lower_double(A::x(p)), upper_double(A::x(p))),
                                     Interval(lower_double(A::y(p)), upper_double(A::y(p))),
                                     Interval(lower_double(A::z(p)), upper_double(A::z(p)))};
    };
    for (Index f = 0; f < m.faces.size(); ++f) {
      const Triangle& t = m.faces[f];
      const auto a = coords(t[0]), b = coords(t[1]), c = coords(t[2]);
      sums[component[f]] = sums[component[f]] + (a[0] * (b[1] * c[2] - b[2] * c[1]) +
                                                 a[1] * (b[2] * c[0] - b[0] * c[2]) +
                                                 a[2] * (b[0] * c[1] - b[1] * c[0]));
    }
    Interval total(0.0);
    for (std::size_t c = 0; c < components; ++c) {
      r.sign[c] = sums[c].sign();
      if (c < listed) r.value[c] = Number_traits<Interval>::to_double(sums[c] / Interval(6.0));
      total = total + sums[c];
    }
    const Interval v = total / Interval(6.0);
    r.total_lower = v.inf(), r.total_upper = v.sup();
    return r;
  }
  r.total_lower = round_rational<double>(r.total, Rounding::downward);
  r.total_upper = round_rational<double>(r.total, Rounding::upward);
  return r;
}

}  // namespace relgeo::internal
