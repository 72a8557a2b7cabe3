// The orientation_2 expansion stage of Filtered_exact_kernel
// (internal/expansion_orientation.h) against the GMP stage
// (internal/exact_dyadic.h) on near-degenerate input over the whole guarded
// range, at its edges and outside it; the constant of its bound.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/core/dyadic.h"
#include "relgeo/kernel/internal/exact_dyadic.h"
#include "relgeo/kernel/internal/expansion_orientation.h"

namespace relgeo::internal {
namespace {

using analysis::moved_by_ulps;

struct Case {
  double px, py, qx, qy, rx, ry;
};

// r on segment pq (rounded), then every coordinate moved by a few ulps, all
// scaled by 2^scale (exact). Zero, positive and negative signs all occur.
Case near_collinear(std::mt19937_64& g, int scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  auto ulps = [&] { return static_cast<int>(g() % 5) - 2; };
  const double px = u(g), py = u(g), qx = u(g) * 8, qy = u(g) * 8, t = u(g);
  const double rx = px + t * (qx - px), ry = py + t * (qy - py);
  auto s = [&](double v) { return std::ldexp(moved_by_ulps(v, ulps()), scale); };
  return {s(px), s(py), s(qx), s(qy), s(rx), s(ry)};
}

bool in_range(const Case& c) {
  for (double v : {c.px, c.py, c.qx, c.qy, c.rx, c.ry})
    if (!in_expansion_range(v)) return false;
  return true;
}

// Agreement with GMP when decided; every case in range must be decided.
std::size_t by_step[2] = {0, 0};  // exact expansions, compensated
void expect_agreement(const Case& c, std::size_t& decided) {
  const auto s = expansion_orientation_2_with_step(c.px, c.py, c.qx, c.qy, c.rx, c.ry);
  if (s) ++by_step[s->second];
  const auto e = expansion_orientation_2(c.px, c.py, c.qx, c.qy, c.rx, c.ry);
  ASSERT_EQ(e.has_value(), in_range(c))
      << std::hexfloat << c.px << ' ' << c.py << ' ' << c.qx << ' ' << c.qy << ' ' << c.rx << ' ' << c.ry;
  if (!e) return;
  ++decided;
  ASSERT_EQ(*e, exact_orientation_2(c.px, c.py, c.qx, c.qy, c.rx, c.ry))
      << std::hexfloat << c.px << ' ' << c.py << ' ' << c.qx << ' ' << c.qy << ' ' << c.rx << ' ' << c.ry;
}

TEST(ExpansionOrientation, AgreesWithGmpOverTheGuardedRange) {
  std::mt19937_64 g(2026);
  std::size_t decided = 0, cases = 0, zeros = 0;
  for (int scale = -396; scale <= 496; scale += 4) {
    for (int i = 0; i < 400; ++i, ++cases) {
      Case c = near_collinear(g, scale);
      if (i % 4 == 0) {  // exactly collinear: integer steps along (dx, dy), scaled
        const double a = double(g() % 1000), b = double(g() % 1000), dx = double(g() % 97), dy = double(g() % 89);
        const double k = double(g() % 50);
        c = {std::ldexp(a, scale), std::ldexp(b, scale), std::ldexp(a + dx, scale), std::ldexp(b + dy, scale),
             std::ldexp(a + k * dx, scale), std::ldexp(b + k * dy, scale)};
      }
      zeros += exact_orientation_2(c.px, c.py, c.qx, c.qy, c.rx, c.ry) == Certified_sign::zero;
      expect_agreement(c, decided);
    }
  }
  // Nearly every case is in range (|v| in [2^-400, 2^500] or 0; a few
  // coordinates come out tinier) and every one of those settles (above).
  EXPECT_GT(decided, cases * 99 / 100);
  EXPECT_GT(zeros, 0u);
  // Both steps run: the compensated one on near-collinear cases, the exact
  // one on the exactly collinear quarter.
  std::printf("[ steps    ] cases=%zu compensated=%zu exact=%zu\n", cases, by_step[1], by_step[0]);
  EXPECT_GT(by_step[1], cases / 2);
  EXPECT_GT(by_step[0], cases / 5);
}

TEST(ExpansionOrientation, ConstantFollowsTheDerivation) {
  // The inequality of step 1 (expansion_orientation.h), exactly.
  using C = Expansion_orientation_2_constants;
  const mpq_class u = exact_rational(C::u);
  auto gamma = [&](int n) { return mpq_class(n * u / (1 - n * u)); };
  const mpq_class k = u * u + 2 * u * gamma(3) +
                      gamma(C::terms - 2) * gamma(C::terms - 1) * ((1 + u) * (1 + u) + 2 * u * (1 + gamma(3)));
  EXPECT_EQ(exact_rational(C::c), 32 * u * u);
  EXPECT_GE((1 - u) * (1 - u) * (1 - gamma(2)) * exact_rational(C::c), k);
  EXPECT_LE(k, 20 * u * u);  // "about 19 u^2"
  EXPECT_GE(C::c * 0x1p-904, 0x1p-1022);  // the bound is normal for products of multiples of 2^-452
}

TEST(ExpansionOrientation, MixedMagnitudesAndZeros) {
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> u(1, 2);
  std::size_t decided = 0;
  for (int i = 0; i < 20000; ++i) {
    auto v = [&] {
      const int kind = static_cast<int>(g() % 4);
      if (kind == 0) return 0.0;
      const int e = kind == 1 ? -400 : kind == 2 ? 499 : static_cast<int>(g() % 900) - 400;
      return (g() % 2 ? -1 : 1) * std::ldexp(u(g), e);
    };
    Case c{v(), v(), v(), v(), v(), v()};
    if (g() % 2) c.rx = c.px, c.ry = c.qy;  // exact zero parts
    ASSERT_TRUE(in_range(c));
    expect_agreement(c, decided);
  }
  EXPECT_EQ(decided, 20000u);  // every case is in range: every case is settled
}

TEST(ExpansionOrientation, RefusesOutsideItsRange) {
  EXPECT_FALSE(expansion_orientation_2(0x1p501, 0, 1, 1, 2, 2).has_value());
  EXPECT_FALSE(expansion_orientation_2(0x1p-401, 0, 1, 1, 2, 2).has_value());
  EXPECT_FALSE(expansion_orientation_2(NAN, 0, 1, 1, 2, 2).has_value());
  EXPECT_FALSE(expansion_orientation_2(0, INFINITY, 1, 1, 2, 2).has_value());
  EXPECT_EQ(expansion_orientation_2(0x1p500, 0, 0, 0x1p500, 0x1p-400, 0x1p-400), Certified_sign::positive);
}

}  // namespace
}  // namespace relgeo::internal
