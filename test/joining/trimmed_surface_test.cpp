// Trimmed patches: loops checked, oriented and flattened; the point-in-domain
// test certified under every certified kernel; open and non-finite trims
// refused with typed errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "joining/surface_fixtures.h"
#include "relgeo/kernel.h"
#include "relgeo/surfaces/trimmed_surface.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

// A full circle of radius r around c from four rational quarter arcs.
Trim_loop circle_loop(Point_2<double> c, double r, bool clockwise) {
  Trim_loop loop;
  const double rot[4][4] = {{1, 0, 0, 1}, {0, -1, 1, 0}, {-1, 0, 0, -1}, {0, 1, -1, 0}};
  const Nurbs_curve_2<double> arc = quarter_circle();
  for (int q = 0; q < 4; ++q) {
    std::vector<Point_2<double>> P;
    for (const auto& p : arc.control_points())
      P.push_back({c.x + r * (rot[q][0] * p.x + rot[q][1] * p.y), c.y + r * (rot[q][2] * p.x + rot[q][3] * p.y)});
    loop.curves.push_back({Nurbs_curve_2<double>(2, {0, 0, 0, 1, 1, 1}, P, {1, 1, 2}), false, -1});
  }
  if (clockwise) {
    std::reverse(loop.curves.begin(), loop.curves.end());
    for (auto& c : loop.curves) c.reversed = true;
  }
  return loop;
}

Trim_loop square_loop(double a, double b, bool clockwise) {
  Trim_loop loop;
  std::vector<Point_2<double>> P{{a, a}, {b, a}, {b, b}, {a, b}, {a, a}};
  if (clockwise) std::reverse(P.begin(), P.end());
  loop.curves.push_back({P, false, -1});
  return loop;
}

Nurbs_surface<double> unit_patch() {
  return Nurbs_surface<double>(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                               {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0.5}});
}

template <class K>
class TrimmedDomain : public ::testing::Test {};
using Certified_kernels = ::testing::Types<Failsafe_kernel<double>, Interval_kernel, Filtered_exact_kernel, Exact_kernel>;
TYPED_TEST_SUITE(TrimmedDomain, Certified_kernels);

TYPED_TEST(TrimmedDomain, SquareWithCircularHole) {
  using K = TypeParam;
  const Trimmed_surface f(unit_patch(), square_loop(0.1, 0.9, false), {circle_loop({0.5, 0.5}, 0.2, false)});
  EXPECT_EQ(f.locate<K>({0.2, 0.2}), Domain_location::inside);
  EXPECT_EQ(f.locate<K>({0.5, 0.5}), Domain_location::outside);   // in the hole
  EXPECT_EQ(f.locate<K>({0.05, 0.5}), Domain_location::outside);  // beyond the outer loop
  EXPECT_EQ(f.locate<K>({0.95, 0.95}), Domain_location::outside);
  EXPECT_EQ(f.locate<K>({0.1, 0.5}), Domain_location::on_boundary);
  EXPECT_EQ(f.locate<K>({0.9, 0.9}), Domain_location::on_boundary);  // a corner
  EXPECT_EQ(f.locate<K>({0.5 + 0.2, 0.5}), Domain_location::on_boundary);  // a vertex of the flattened circle
  EXPECT_EQ(f.locate<K>({0.5, 0.1}), Domain_location::on_boundary);
  // Just inside / outside the hole's flattened polygon, on a horizontal ray
  // through a vertex (the crossing rule's degenerate case).
  EXPECT_EQ(f.locate<K>({0.5 + 0.2 + 0x1p-40, 0.5}), Domain_location::inside);
  EXPECT_EQ(f.locate<K>({0.5 + 0.2 - 0x1p-40, 0.5}), Domain_location::outside);
  // A point one ulp off the edge x = 0.1: decided exactly by certified kernels
  // that are exact, `uncertain` allowed otherwise, never wrong.
  const Domain_location near = f.locate<K>({std::nextafter(0.1, 1.0), 0.5});
  if constexpr (K::has_exact_predicates) EXPECT_EQ(near, Domain_location::inside);
  else EXPECT_TRUE(near == Domain_location::inside || near == Domain_location::uncertain);
}

TEST(TrimmedSurface, LoopsAreOrientedAndFlattenedWithinTolerance) {
  // Outer given clockwise, hole counter-clockwise: both reoriented.
  const Trimmed_surface f(unit_patch(), square_loop(0.1, 0.9, true), {circle_loop({0.5, 0.5}, 0.2, false)});
  const auto& poly = f.domain_polygon();
  ASSERT_EQ(poly.size(), 2u);
  const auto area = [](const std::vector<Point_2<double>>& p) {
    double a = 0;
    for (std::size_t i = 0; i < p.size(); ++i) a += p[i].x * p[(i + 1) % p.size()].y - p[(i + 1) % p.size()].x * p[i].y;
    return a / 2;
  };
  EXPECT_NEAR(area(poly[0]), 0.64, 1e-15);
  EXPECT_LT(area(poly[1]), 0);
  EXPECT_NEAR(area(poly[1]), -M_PI * 0.04, 1e-4);
  EXPECT_TRUE(f.outer_loop().curves[0].reversed);
  for (const auto& c : f.inner_loops()[0].curves) EXPECT_TRUE(c.reversed);
  // Every flattened point of the circle lies on it; chords stay within the
  // tolerance (1e-4 of the parameter diagonal).
  const double tol = 1e-4 * std::sqrt(2.0);
  for (std::size_t i = 0; i < poly[1].size(); ++i) {
    const auto& p = poly[1][i];
    const auto& q = poly[1][(i + 1) % poly[1].size()];
    EXPECT_NEAR(std::hypot(p.x - 0.5, p.y - 0.5), 0.2, 1e-15);
    const double mid = std::hypot(0.5 * (p.x + q.x) - 0.5, 0.5 * (p.y + q.y) - 0.5);
    EXPECT_LE(0.2 - mid, tol);
  }
}

TEST(TrimmedSurface, UntrimmedPatchCoversItsParameterRectangle) {
  const Trimmed_surface f = Trimmed_surface::untrimmed(unit_patch());
  EXPECT_EQ(f.locate<Filtered_exact_kernel>({0.5, 0.5}), Domain_location::inside);
  EXPECT_EQ(f.locate<Filtered_exact_kernel>({1.0, 0.5}), Domain_location::on_boundary);
  EXPECT_EQ(f.locate<Filtered_exact_kernel>({1.5, 0.5}), Domain_location::outside);
}

TEST(TrimmedSurfaceBadInput, OpenLoopsAndNonFinitePointsAreRefused) {
  Trim_loop open = square_loop(0.1, 0.9, false);
  std::get<0>(open.curves[0].geometry).back() = {0.1, 0.11};  // ends 0.01 away from its start
  EXPECT_THROW(Trimmed_surface(unit_patch(), open), Open_trim_loop);
  Trim_loop gap = circle_loop({0.5, 0.5}, 0.2, false);
  gap.curves.erase(gap.curves.begin() + 1);  // three quarters: the chain does not close
  EXPECT_THROW(Trimmed_surface(unit_patch(), gap), Open_trim_loop);
  EXPECT_THROW(Trimmed_surface(unit_patch(), Trim_loop{}), Open_trim_loop);
  Trim_loop tiny;
  tiny.curves.push_back({std::vector<Point_2<double>>{{0.1, 0.1}, {0.2, 0.1}, {0.1, 0.1}}, false, -1});
  EXPECT_THROW(Trimmed_surface(unit_patch(), tiny), Open_trim_loop);  // fewer than 3 distinct points
  Trim_loop nan = square_loop(0.1, 0.9, false);
  std::get<0>(nan.curves[0].geometry)[2].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Trimmed_surface(unit_patch(), nan), Non_finite_input);
  try {
    Trimmed_surface(unit_patch(), open);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Error_code::invalid_input);
    EXPECT_NE(std::string(e.what()).find("outer trim loop"), std::string::npos) << e.what();
  }
}

}  // namespace
