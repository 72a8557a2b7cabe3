// The exact rational coordinates of LPI and TPI points
// (internal/exact_implicit_coordinates.h) against the independent oracle of
// test/support (Gaussian elimination in GMP rationals), on every family of
// the implicit-point workloads (subnormal, huge and tiny magnitudes, points
// on the plane, axis-aligned lines); canonical (what every mpq operation
// assumes), the same on two threads at once, and a typed error where the
// point does not exist.
#include "relgeo/kernel/internal/exact_implicit_coordinates.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "relgeo/analysis/implicit_workloads.h"
#include "relgeo/core/errors.h"
#include "support/implicit_oracle.h"
#include "support/soundness_data.h"

namespace relgeo::internal {
namespace {

using Definition = analysis::Implicit_point_definition;

std::optional<std::array<mpq_class, 3>> converted(const Definition& d) {
  std::array<Point_3<double>, 9> v;
  for (int i = 0; i < 9; ++i) v[i] = {d.points[i][0], d.points[i][1], d.points[i][2]};
  try {
    if (d.kind == Implicit_point_kind::lpi)
      return Exact_implicit_coordinates::lpi(std::span<const Point_3<double>, 5>(v.data(), 5));
    return Exact_implicit_coordinates::tpi(v);
  } catch (const Precondition_violation&) {
    return std::nullopt;
  }
}

bool canonical(const mpq_class& q) {
  mpq_class c = q;
  c.canonicalize();
  return mpz_sgn(q.get_den_mpz_t()) > 0 && mpz_cmp(c.get_num_mpz_t(), q.get_num_mpz_t()) == 0 &&
         mpz_cmp(c.get_den_mpz_t(), q.get_den_mpz_t()) == 0;
}

// Cases per family (RELGEO_TEST_SCALE: the sanitizer build runs a twentieth).
std::size_t cases() { return static_cast<std::size_t>(4000 * test::test_scale()) + 100; }

std::vector<analysis::Implicit_workload> workloads() { return analysis::implicit_workloads(cases(), 20261203); }

TEST(ExactImplicitCoordinates, EqualTheOracleOnEveryFamilyAndAreCanonical) {
  std::size_t lpi = 0, tpi = 0, absent = 0;
  for (const auto& family : workloads()) {
    for (const Definition& d : family.points) {
      if (d.kind == Implicit_point_kind::explicit_point) continue;
      const std::optional<test::Exact_point> expected = test::oracle_point(d);
      const std::optional<std::array<mpq_class, 3>> got = converted(d);
      ASSERT_EQ(expected.has_value(), got.has_value()) << family.name;
      if (!expected) {
        ++absent;
        continue;
      }
      (d.kind == Implicit_point_kind::lpi ? lpi : tpi) += 1;
      for (int axis = 0; axis < 3; ++axis) {
        ASSERT_EQ((*got)[axis], expected->coordinate(axis)) << family.name << ", axis " << axis;
        ASSERT_TRUE(canonical((*got)[axis])) << family.name << ", axis " << axis;
      }
    }
  }
  // Both kinds met, in numbers (at scale 1: 7,331 and 2,397 of 4,100 cases a family).
  EXPECT_GT(lpi, cases() / 2);
  EXPECT_GT(tpi, cases() / 2);
  std::printf("%zu LPI and %zu TPI points equal the oracle's; %zu do not exist\n", lpi, tpi, absent);
}

// The LPI reduction's special cases: the line through a point of the plane
// (lambda = 0), a line parallel to a coordinate plane (a difference a_k = 0:
// that coordinate is an input's), inputs spread from subnormal to 2^1000.
TEST(ExactImplicitCoordinates, LpiSpecialCasesAreExact) {
  const auto lpi = [](std::array<Point_3<double>, 5> v) {
    return Exact_implicit_coordinates::lpi(std::span<const Point_3<double>, 5>(v));
  };
  // p on the plane z = 0: the point is p.
  const auto on_plane = lpi({{{0.1, -0.3, 0.0}, {0.7, 0.25, 1.5}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
  EXPECT_EQ(on_plane[0], mpq_class(0.1));
  EXPECT_EQ(on_plane[1], mpq_class(-0.3));
  EXPECT_EQ(on_plane[2], 0);
  // A vertical line through (0.1, 0.2) and a slanted plane x + y + z = 1:
  // x and y are the line's, z = 1 - x - y exactly.
  const auto vertical = lpi({{{0.1, 0.2, -5.0}, {0.1, 0.2, 3.0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
  EXPECT_EQ(vertical[0], mpq_class(0.1));
  EXPECT_EQ(vertical[1], mpq_class(0.2));
  EXPECT_EQ(vertical[2], 1 - mpq_class(0.1) - mpq_class(0.2));
  // Magnitudes from 2^-1074 to 2^1000 in one point: the line from the
  // subnormal point p = (2^-1074, 0, 0) through q = (1, 1, 1) meets the plane
  // x = 2^1000 at p + s (q - p), s = (2^1000 - 2^-1074) / (1 - 2^-1074).
  const double tiny = std::ldexp(1.0, -1074), huge = std::ldexp(1.0, 1000);
  const auto spread = lpi({{{tiny, 0, 0}, {1, 1, 1}, {huge, 0, 0}, {huge, 1, 0}, {huge, 0, 1}}});
  const mpq_class s = (mpq_class(huge) - mpq_class(tiny)) / (1 - mpq_class(tiny));
  EXPECT_EQ(spread[0], mpq_class(huge));
  EXPECT_EQ(spread[1], s);
  EXPECT_EQ(spread[2], s);
  for (const mpq_class& c : spread) EXPECT_TRUE(canonical(c));
}

TEST(ExactImplicitCoordinates, APointThatDoesNotExistIsATypedError) {
  // The line lies in a plane parallel to the given one.
  const std::array<Point_3<double>, 5> parallel{{{0, 0, 1}, {1, 2, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  EXPECT_THROW(Exact_implicit_coordinates::lpi(std::span<const Point_3<double>, 5>(parallel)), Precondition_violation);
  // Three planes through one line (the z axis).
  const std::array<Point_3<double>, 9> pencil{
      {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, {1, 1, 0}}};
  EXPECT_THROW(Exact_implicit_coordinates::tpi(pencil), Precondition_violation);
}

// Each thread has its own integers: two threads converting at once give
// what one gives.
TEST(ExactImplicitCoordinates, TwoThreadsAtOnceGiveTheSameCoordinates) {
  std::vector<Definition> points;
  for (const auto& family : workloads())
    for (const Definition& d : family.points)
      if (d.kind != Implicit_point_kind::explicit_point) points.push_back(d);
  std::vector<std::optional<std::array<mpq_class, 3>>> alone(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) alone[i] = converted(points[i]);
  std::array<std::vector<std::optional<std::array<mpq_class, 3>>>, 2> at_once;
  std::vector<std::thread> threads;
  for (auto& out : at_once)
    threads.emplace_back([&points, &out] {
      out.resize(points.size());
      for (std::size_t i = 0; i < points.size(); ++i) out[i] = converted(points[i]);
    });
  for (auto& t : threads) t.join();
  for (const auto& out : at_once) EXPECT_TRUE(out == alone);
}

}  // namespace
}  // namespace relgeo::internal
