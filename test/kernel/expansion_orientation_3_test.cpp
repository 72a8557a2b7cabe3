// The orientation_3 expansion stage of Filtered_exact_kernel
// (internal/expansion_orientation_3.h) against the GMP stage
// (internal/exact_dyadic.h): over its whole range, at the range's edges and
// outside it; every case in range is decided, by each of its three steps.
#include "relgeo/kernel/internal/expansion_orientation_3.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <random>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/core/dyadic.h"
#include "relgeo/kernel/internal/exact_dyadic.h"

namespace relgeo::internal {
namespace {

using analysis::moved_by_ulps;
using Coplanar_case = std::array<double, 12>;
using Range = Expansion_orientation_3_range;

// Full 53-bit significands of magnitude in [2^-8, 1), either sign: their
// differences are mostly inexact.
double uniform(std::mt19937_64& g) {
  const double m = 1 + static_cast<double>(g() >> 12) * 0x1p-52;  // [1, 2)
  return (g() % 2 ? -1 : 1) * std::ldexp(m, -1 - static_cast<int>(g() % 8));
}

// s on the plane pqr (rounded), moved by up to `ulps` ulps per coordinate,
// everything scaled by 2^scale (exact in range).
Coplanar_case near_coplanar(std::mt19937_64& g, int scale, int ulps) {
  Coplanar_case c;
  for (int k = 0; k < 9; ++k) c[k] = uniform(g) * (k < 3 ? 1 : 8);
  const double a = uniform(g), b = uniform(g);
  for (int d = 0; d < 3; ++d) {
    const double v = c[d] + a * (c[3 + d] - c[d]) + b * (c[6 + d] - c[d]);
    c[9 + d] = moved_by_ulps(v, static_cast<int>(g() % static_cast<std::uint64_t>(2 * ulps + 1)) - ulps);
  }
  for (double& v : c) v = std::ldexp(v, scale);
  return c;
}

// Exactly coplanar (s = q) with mostly inexact differences.
Coplanar_case exactly_coplanar(std::mt19937_64& g, int scale) {
  Coplanar_case c;
  for (int k = 0; k < 9; ++k) c[k] = std::ldexp(uniform(g), scale);
  for (int d = 0; d < 3; ++d) c[9 + d] = c[3 + d];  // s = q: D = 0 exactly
  return c;
}

bool in_range(const Coplanar_case& c) {
  for (double v : c)
    if (!Range::contains(v)) return false;
  return true;
}

struct Steps {
  std::size_t decided = 0, by_step[3] = {0, 0, 0};
  std::size_t of(Expansion_step s) const { return by_step[static_cast<int>(s)]; }
};

void expect_agreement(const Coplanar_case& c, Steps& steps) {
  const auto e = expansion_orientation_3_with_step(c);
  ASSERT_EQ(e.has_value(), in_range(c)) << std::hexfloat << c[0] << ' ' << c[9];
  if (!e) return;
  ++steps.decided;
  ++steps.by_step[static_cast<int>(e->second)];
  ASSERT_EQ(e->first, exact_orientation_3(c)) << std::hexfloat << c[0] << ' ' << c[1] << ' ' << c[2] << ' '
                                              << c[3] << ' ' << c[4] << ' ' << c[5] << ' ' << c[6] << ' ' << c[7]
                                              << ' ' << c[8] << ' ' << c[9] << ' ' << c[10] << ' ' << c[11];
}

TEST(ExpansionOrientation3, ConstantsFollowTheDerivation) {
  // The inequality of step 1 (expansion_orientation_3.h), exactly.
  using C = Expansion_orientation_3_constants;
  const mpq_class u = exact_rational(C::u);
  auto gamma = [&](int n) { return mpq_class(n * u / (1 - n * u)); };
  const int n = C::terms;
  const mpq_class absolute_sum = (1 + 2 * u) * (1 + u) * (1 + u) + 3 * u * (1 + gamma(7));
  const mpq_class k = 3 * u * u + u * u * u + 3 * u * gamma(7) + u * u * (1 + u) +
                      gamma(n - 2) * gamma(n - 1) * absolute_sum;
  EXPECT_EQ(exact_rational(C::c), 512 * u * u);
  EXPECT_GE((1 - u) * (1 - u) * (1 - gamma(7)) * exact_rational(C::c), k);
  EXPECT_LE(k, 340 * u * u);  // the derivation's "about 331 u^2": c leaves a margin of 1.5
  // No underflow in the bound: c q^3 is normal for q = 2^-302, the lowest
  // bit of the smallest coordinate in range.
  EXPECT_EQ(Range::low, 0x1p-250);
  EXPECT_GE(C::c * 0x1p-906, 0x1p-1022);
  // No overflow: 192 terms of magnitude (2^301)^3 (1 + u)^3 stay below 2^912.
  EXPECT_LT(192 * std::pow(2 * Range::high, 3) * 1.01, 0x1p912);
}

TEST(ExpansionOrientation3, AgreesWithGmpOverTheRange) {
  std::mt19937_64 g(2027);
  Steps steps;
  std::size_t cases = 0;
  for (int scale = -246; scale <= 296; scale += 2) {
    for (int i = 0; i < 360; ++i, ++cases) {
      Coplanar_case c;
      switch (i % 6) {
        case 0: c = exactly_coplanar(g, scale); break;
        case 1: {  // integer points, coplanar or nearly: exact differences
          for (int k = 0; k < 9; ++k) c[k] = std::ldexp(static_cast<double>(static_cast<int>(g() % 2001) - 1000), scale);
          const double a = static_cast<double>(g() % 7), b = static_cast<double>(g() % 5);
          for (int d = 0; d < 3; ++d)
            c[9 + d] = c[d] + a * (c[3 + d] - c[d]) + b * (c[6 + d] - c[d]) + std::ldexp(static_cast<double>(g() % 3) - 1, scale);
          break;
        }
        case 2: c = near_coplanar(g, scale, 0); break;
        default: c = near_coplanar(g, scale, 4);
      }
      expect_agreement(c, steps);
    }
  }
  // A few near-coplanar coordinates come out just below 2^-250; all others
  // are in range, and every one of those is decided (above).
  EXPECT_GT(steps.decided, cases * 99 / 100);
  std::printf("[ steps    ] cases=%zu compensated=%zu exact(rounded differences)=%zu exact=%zu\n", cases,
              steps.of(Expansion_step::compensated), steps.of(Expansion_step::exact_rounded_differences),
              steps.of(Expansion_step::exact));
  EXPECT_GT(steps.of(Expansion_step::compensated), cases / 3);
  EXPECT_GT(steps.of(Expansion_step::exact_rounded_differences), cases / 500);  // 0.7%: integer, D = 0
  EXPECT_GT(steps.of(Expansion_step::exact), cases / 10);
}

TEST(ExpansionOrientation3, MixedMagnitudesZerosAndEdges) {
  std::mt19937_64 g(9);
  Steps steps;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    auto v = [&] {
      const int kind = static_cast<int>(g() % 5);
      if (kind == 0) return 0.0;
      const int e = kind == 1 ? -250 : kind == 2 ? 299 : static_cast<int>(g() % 548) - 250;
      const double m = 1 + static_cast<double>(g() >> 12) * 0x1p-52;  // [1, 2)
      return (g() % 2 ? -1 : 1) * std::ldexp(m, e);
    };
    Coplanar_case c;
    for (double& x : c) x = v();
    if (g() % 2) c[9] = c[0], c[4] = c[1];  // shared coordinates: exact zero parts
    if (g() % 4 == 0) c[11] = c[5];
    ASSERT_TRUE(in_range(c));
    expect_agreement(c, steps);
  }
  EXPECT_EQ(steps.decided, static_cast<std::size_t>(n));
}

// The determinant itself, in rationals.
mpq_class exact_determinant(const Coplanar_case& c) {
  std::array<std::array<mpq_class, 3>, 3> a;  // a[row][column] = (q, r, s)[column] - p, coordinate `row`
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) a[row][col] = mpq_class(c[3 * (col + 1) + row]) - mpq_class(c[row]);
  return a[0][0] * (a[1][1] * a[2][2] - a[2][1] * a[1][2]) - a[1][0] * (a[0][1] * a[2][2] - a[2][1] * a[0][2]) +
         a[2][0] * (a[0][1] * a[1][2] - a[1][1] * a[0][2]);
}

// orientation_3_enclosure holds D on every kind of case above, and is a few
// ulps of D wide where D is not small against its terms (uniform points).
TEST(ExpansionOrientation3, TheEnclosureHoldsTheDeterminantAndIsNarrowWhereWellConditioned) {
  std::mt19937_64 g(31);
  std::size_t wide = 0, uniform_cases = 0;
  for (int scale = -240; scale <= 290; scale += 10) {
    for (int i = 0; i < 200; ++i) {
      Coplanar_case c;
      const bool well_conditioned = i % 4 == 0;
      if (well_conditioned)
        for (double& v : c) v = std::ldexp(uniform(g), scale);
      else
        c = i % 4 == 1 ? exactly_coplanar(g, scale) : near_coplanar(g, scale, 4 * (i % 4));
      if (!in_range(c)) continue;
      const std::optional<Interval> e = orientation_3_enclosure(c);
      ASSERT_TRUE(e.has_value());
      const mpq_class d = exact_determinant(c);
      ASSERT_TRUE(mpq_class(e->inf()) <= d && d <= mpq_class(e->sup()))
          << std::hexfloat << c[0] << ' ' << c[1] << ' ' << c[2] << ' ' << c[9] << ' ' << c[10] << ' ' << c[11];
      if (well_conditioned) {
        ++uniform_cases;
        wide += e->sup() - e->inf() > 0x1p-50 * std::abs(d.get_d());
      }
    }
  }
  EXPECT_GT(uniform_cases, 2000u);
  EXPECT_LT(wide * 100, uniform_cases);  // at most 1% wider than 8 ulps of D
  Coplanar_case outside{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0x1p301};
  EXPECT_FALSE(orientation_3_enclosure(outside).has_value());
}

TEST(ExpansionOrientation3, RefusesOutsideItsRange) {
  Coplanar_case c{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  EXPECT_EQ(expansion_orientation_3(c), Certified_sign::positive);
  c[11] = -0x1p300;
  EXPECT_EQ(expansion_orientation_3(c), Certified_sign::negative);
  c[4] = 0x1p-250;
  EXPECT_EQ(expansion_orientation_3(c), Certified_sign::negative);
  for (double bad : {0x1p301, 0x1.0000000000001p300, 0x1.fffffffffffffp-251, std::nan(""), double(INFINITY)}) {
    Coplanar_case d = c;
    d[7] = bad;
    EXPECT_FALSE(expansion_orientation_3(d).has_value()) << bad;
  }
}

}  // namespace
}  // namespace relgeo::internal
