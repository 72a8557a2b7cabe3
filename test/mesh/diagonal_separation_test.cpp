// The diagonal extents of faces (mesh/internal/diagonal_separation.h): they
// enclose the exact extents in every floating-point environment, separate
// only disjoint faces, never separate faces that touch, and separate box
// pairs of long faces lying across the axes.
#include "relgeo/mesh/internal/diagonal_separation.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/internal/face_pair_predicates.h"
#include "support/fp_environments.h"

namespace {

using namespace relgeo;
using internal::Diagonal_extents;
using internal::diagonal_extents;
using internal::diagonally_separated;
using Corner = std::array<double, 3>;

// The exact value of corner c along diagonal k (0-2: x+y, y+z, z+x; 3-5:
// x-y, y-z, z-x).
mpq_class exact_along(const Corner& c, int k) {
  const int i = k % 3, j = (k + 1) % 3;
  return k < 3 ? mpq_class(mpq_class(c[i]) + mpq_class(c[j])) : mpq_class(mpq_class(c[i]) - mpq_class(c[j]));
}

// A double of random sign and exponent over the whole range, subnormals and
// values beyond float's range included.
double any_double(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-1074, 140);
  const double x = std::ldexp(mantissa(rng), exponent(rng));
  return rng() % 2 ? x : -x;
}

TEST(DiagonalSeparation, ExtentsEncloseTheExactOnesInEveryFloatingPointEnvironment) {
  std::vector<test::Fp_environment_setting> settings{{"default"}};
  for (const auto& s : test::non_default_fp_environments()) settings.push_back(s);
  std::mt19937_64 rng(20261203);
  std::size_t nearest_float_misses = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::array<Corner, 3> t;
    // Mostly coordinates of one scale (sums that round), some of any scale.
    const int scale = std::uniform_int_distribution<int>(-1060, 120)(rng);
    for (auto& c : t)
      for (double& x : c)
        x = trial % 4 == 0 ? any_double(rng)
                           : std::ldexp(std::uniform_real_distribution<double>(-1.0, 1.0)(rng), scale);
    for (const auto& s : settings) {
      Diagonal_extents e;
      {
        const test::Scoped_fp_environment environment(s);
        e = diagonal_extents(t[0], t[1], t[2]);
      }
      for (int k = 0; k < 6; ++k) {
        for (const Corner& c : t) {
          const mpq_class v = exact_along(c, k);
          if (std::isfinite(e.lo[k])) {
            EXPECT_LE(mpq_class(e.lo[k]), v) << s.name << " axis " << k;
          }
          if (std::isfinite(e.hi[k])) {
            EXPECT_GE(mpq_class(e.hi[k]), v) << s.name << " axis " << k;
          }
        }
        if (s.name != "default") continue;
        // The nearest float of each end, without moving it outward: it
        // leaves corners outside (what the margin is for).
        mpq_class lo = exact_along(t[0], k), hi = lo;
        for (const Corner& c : t) lo = std::min(lo, exact_along(c, k)), hi = std::max(hi, exact_along(c, k));
        const float nearest_lo = static_cast<float>(lo.get_d()), nearest_hi = static_cast<float>(hi.get_d());
        if (std::isfinite(nearest_lo) && std::isfinite(nearest_hi))
          nearest_float_misses += mpq_class(nearest_lo) > lo || mpq_class(nearest_hi) < hi;
      }
    }
  }
  EXPECT_GT(nearest_float_misses, 1000u);
}

TEST(DiagonalSeparation, FacesWithNanOrInfiniteCornersAreNeverSeparated) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const Diagonal_extents unit = diagonal_extents(Corner{0, 0, 0}, Corner{1, 0, 0}, Corner{0, 1, 0});
  for (const double bad : {nan, inf, -inf}) {
    const Diagonal_extents e = diagonal_extents(Corner{bad, 0, 0}, Corner{100, 100, 100}, Corner{101, 100, 100});
    for (int k = 0; k < 6; ++k) {
      EXPECT_EQ(e.lo[k], -std::numeric_limits<float>::infinity()) << bad << " axis " << k;
      EXPECT_EQ(e.hi[k], std::numeric_limits<float>::infinity()) << bad << " axis " << k;
    }
    EXPECT_FALSE(diagonally_separated(e, unit));
  }
  // Finite corners beyond float's range: infinite ends on the diagonals
  // that read that coordinate (x+y, z+x, x-y, z-x), finite on the others.
  const Diagonal_extents huge = diagonal_extents(Corner{0x1p127, 0, 0}, Corner{1, 0, 0}, Corner{0, 1, 0});
  for (int k : {0, 2, 3}) EXPECT_EQ(huge.hi[k], std::numeric_limits<float>::infinity()) << k;
  EXPECT_EQ(huge.lo[5], -std::numeric_limits<float>::infinity());
  EXPECT_TRUE(std::isfinite(huge.lo[1]) && std::isfinite(huge.hi[1]));
  // Faces far apart are separated.
  EXPECT_TRUE(diagonally_separated(
      unit, diagonal_extents(Corner{100, 100, 100}, Corner{101, 100, 100}, Corner{100, 101, 100})));
}

// Triangles that share a vertex, or one of whose vertices is the midpoint
// of the other's edge (exact), in every environment: they touch, so no
// diagonal may separate them, however the sums round.
TEST(DiagonalSeparation, TouchingFacesAreNeverSeparated) {
  std::vector<test::Fp_environment_setting> settings{{"default"}};
  for (const auto& s : test::non_default_fp_environments()) settings.push_back(s);
  std::mt19937_64 rng(7);
  const Filtered_exact_kernel k;
  for (int trial = 0; trial < 2000; ++trial) {
    const int scale = std::uniform_int_distribution<int>(-1000, 100)(rng);
    // Even integers below 2^52 times 2^scale: midpoints are doubles.
    const auto coordinate = [&] {
      return std::ldexp(2.0 * static_cast<double>(rng() % (std::uint64_t(1) << 51)), scale - 52);
    };
    const auto point = [&] { return Point_3<double>{coordinate(), coordinate(), coordinate()}; };
    const Point_3<double> q = point(), r = point(), s = point(), u = point(), w = point();
    const Point_3<double> mid{(q.x + r.x) / 2, (q.y + r.y) / 2, (q.z + r.z) / 2};  // exact
    const std::array<Point_3<double>, 3> a{q, r, s}, sharing{q, u, w}, on_edge{mid, u, w};
    for (const auto* b : {&sharing, &on_edge}) {
      const auto corners = [](const std::array<Point_3<double>, 3>& t) {
        return std::array<Corner, 3>{Corner{t[0].x, t[0].y, t[0].z}, Corner{t[1].x, t[1].y, t[1].z},
                                     Corner{t[2].x, t[2].y, t[2].z}};
      };
      const auto ca = corners(a), cb = corners(*b);
      for (const auto& setting : settings) {
        bool separated = false;
        {
          const test::Scoped_fp_environment environment(setting);
          separated =
              diagonally_separated(diagonal_extents(ca[0], ca[1], ca[2]), diagonal_extents(cb[0], cb[1], cb[2]));
        }
        EXPECT_FALSE(separated) << setting.name << " trial " << trial;
      }
      // The exact predicate agrees that they meet (when neither is degenerate).
      const internal::Maybe meet = internal::triangles_meet(k, {&a[0], &a[1], &a[2]}, {&(*b)[0], &(*b)[1], &(*b)[2]});
      if (meet) {
        EXPECT_TRUE(*meet);
      }
    }
  }
}

// Long thin faces in random directions (a gear's teeth, turned): many pairs
// have overlapping boxes, and the diagonals separate a good share of them,
// each one a pair the exact predicate finds disjoint.
TEST(DiagonalSeparation, SeparatesBoxPairsOfSliversAndOnlyDisjointOnes) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0), dir(-1.0, 1.0);
  std::vector<std::array<Point_3<double>, 3>> faces;
  std::vector<Box_3> boxes;
  for (int i = 0; i < 600; ++i) {
    const Point_3<double> p{unit(rng), unit(rng), unit(rng)};
    const double dx = dir(rng), dy = dir(rng), dz = dir(rng);
    const Point_3<double> q{p.x + 0.5 * dx, p.y + 0.5 * dy, p.z + 0.5 * dz};
    const Point_3<double> r{p.x + 0.01 * dir(rng), p.y + 0.01 * dir(rng), p.z + 0.01 * dir(rng)};
    faces.push_back({p, q, r});
    Box_3 b;
    for (const auto& c : faces.back()) b.extend(c.x, c.y, c.z);
    boxes.push_back(b);
  }
  const Filtered_exact_kernel k;
  std::size_t box_pairs = 0, separated = 0;
  Face_bvh(boxes).for_each_overlapping_pair([&](Index i, Index j) {
    ++box_pairs;
    const auto& a = faces[i];
    const auto& b = faces[j];
    const auto extents = [](const std::array<Point_3<double>, 3>& t) {
      return diagonal_extents(Corner{t[0].x, t[0].y, t[0].z}, Corner{t[1].x, t[1].y, t[1].z},
                              Corner{t[2].x, t[2].y, t[2].z});
    };
    if (!diagonally_separated(extents(a), extents(b))) return;
    ++separated;
    const internal::Maybe meet = internal::triangles_meet(k, {&a[0], &a[1], &a[2]}, {&b[0], &b[1], &b[2]});
    ASSERT_TRUE(meet.has_value());
    EXPECT_FALSE(*meet) << "faces " << i << " and " << j;
  });
  EXPECT_GT(box_pairs, 5000u);
  EXPECT_GT(4 * separated, box_pairs);  // more than a quarter of the box pairs
}

}  // namespace
