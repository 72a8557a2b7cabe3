// Closed Bezier contours (closure checks, chains) and the rotation carrying
// the extrusion direction to the z axis, with its a-posteriori error bound.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <random>

#include "relgeo/curves/contour.h"
#include "relgeo_fixtures/curves/test_contours.h"

namespace relgeo::test {
namespace {

TEST(Contour, ChainsCloseByConstruction) {
  const Bezier_contour c = circle_contour(5, 2.0);
  ASSERT_EQ(c.size(), 5u);
  for (std::size_t m = 0; m < 5; ++m) {
    EXPECT_EQ(c[m].degree(), 3u);
    EXPECT_EQ(c[m][3], c[(m + 1) % 5][0]);
    for (std::size_t i = 0; i <= 3; ++i) EXPECT_GE(c.scale(m, i), std::hypot(c[m][i].x, c[m][i].y));
  }
  // end points on the circle, arc midpoints within the classical 2.7e-4 r of it (M = 4)
  const Bezier_contour q = circle_contour(4);
  for (std::size_t m = 0; m < 4; ++m) {
    const auto mid = q[m](0.5);
    EXPECT_NEAR(std::hypot(mid.x, mid.y), 1.0, 3e-4);
  }
}

TEST(Contour, NotClosedDegreeZeroNanAreRefused) {
  // curve 1 does not start where curve 0 ends
  std::vector<std::vector<Point_2<double>>> open = {
      {{0, 0}, {1, 0}}, {{1, 0.5}, {1, 1}}, {{1, 1}, {0, 0}}};
  try {
    (void)Bezier_contour::from_curves(open);
    FAIL() << "open contour accepted";
  } catch (const Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("not closed: curve 0 ends"), std::string::npos) << e.what();
  }
  // the last curve must return to the first point
  std::vector<std::vector<Point_2<double>>> last_open = {{{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{1, 1}, {0, 1e-300}}};
  EXPECT_THROW((void)Bezier_contour::from_curves(last_open), Invalid_input);
  // degree 0
  std::vector<std::vector<Point_2<double>>> deg0 = {{{0, 0}}, {{0, 0}, {1, 1}}};
  try {
    (void)Bezier_contour::from_curves(deg0);
    FAIL();
  } catch (const Invalid_input& e) {
    EXPECT_NE(std::string(e.what()).find("curve 0: Bezier curve: degree 0"), std::string::npos) << e.what();
  }
  const std::vector<Point_2<double>> chain = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_THROW((void)Bezier_contour::from_chain(chain, 0), Invalid_input);
  EXPECT_THROW((void)Bezier_contour::from_chain(chain, 3), Invalid_input);  // 4 points, not a multiple of 3
  EXPECT_THROW((void)Bezier_contour::from_curves({}), Invalid_input);
  std::vector<std::vector<Point_2<double>>> nan = {{{0, 0}, {std::nan(""), 0}, {1, 1}}, {{1, 1}, {0, 0}}};
  EXPECT_THROW((void)Bezier_contour::from_curves(nan), Non_finite_input);
  Bezier_contour c = Bezier_contour::from_chain(chain, 2);
  EXPECT_EQ(c.size(), 2u);
  EXPECT_THROW(c.set_scales({{1, 1, 1}}), Invalid_input);
  EXPECT_THROW(c.set_scales({{1, 1, 1}, {1, -1, 1}}), Invalid_input);
  c.set_scales({{1, 2, 3}, {3, 4, 1}});
  EXPECT_EQ(c.scale(1, 1), 4.0);
}

double det3(const Matrix_3& q) {
  return q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) - q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
         q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
}

TEST(Rotation, CarriesDToZ) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g;
  std::vector<Point_3<double>> dirs = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {1e-20, 0, -1}};
  for (int i = 0; i < 200; ++i) dirs.push_back({g(rng), g(rng), g(rng)});
  for (auto d : dirs) {
    const double n = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    d = {d.x / n, d.y / n, d.z / n};
    const Matrix_3 q = rotation_to_z(d);
    const double qd[3] = {q[0][0] * d.x + q[0][1] * d.y + q[0][2] * d.z, q[1][0] * d.x + q[1][1] * d.y + q[1][2] * d.z,
                          q[2][0] * d.x + q[2][1] * d.y + q[2][2] * d.z};
    EXPECT_NEAR(qd[0], 0, 1e-15);
    EXPECT_NEAR(qd[1], 0, 1e-15);
    EXPECT_NEAR(qd[2], 1, 1e-15);
    EXPECT_NEAR(det3(q), 1, 1e-15);  // a rotation, not a reflection
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) {
        const double dot = q[r][0] * q[s][0] + q[r][1] * q[s][1] + q[r][2] * q[s][2];
        EXPECT_NEAR(dot, r == s ? 1.0 : 0.0, 1e-15);
      }
  }
  // d = -z: the half turn about x
  const Matrix_3 q = rotation_to_z({0, 0, -1});
  EXPECT_EQ(q[0][0], 1.0);
  EXPECT_EQ(q[1][1], -1.0);
  EXPECT_EQ(q[2][2], -1.0);
}

TEST(Rotation, ProjectionErrorBoundHoldsAndIsTight) {
  // A contour in the plane d.x = 5 for d = (1, 2, 3)/|.|: its projection is a
  // rotated copy of the planar one (distances preserved).
  const Point_3<double> d{1, 2, 3};
  const double n = std::sqrt(14.0);
  const Point_3<double> du{1 / n, 2 / n, 3 / n};
  // an orthonormal basis of the plane
  const Point_3<double> e1{2 / std::sqrt(5.0), -1 / std::sqrt(5.0), 0};
  const Point_3<double> e2{du.y * e1.z - du.z * e1.y, du.z * e1.x - du.x * e1.z, du.x * e1.y - du.y * e1.x};
  std::vector<Point_3<double>> pts;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-100, 100);
  std::vector<Point_2<double>> planar;
  for (int i = 0; i < 300; ++i) {
    const double a = u(rng), b = u(rng);
    planar.push_back({a, b});
    pts.push_back({5 * du.x + a * e1.x + b * e2.x, 5 * du.y + a * e1.y + b * e2.y, 5 * du.z + a * e1.z + b * e2.z});
  }
  const Plane_projection p = project_along(pts, d);
  ASSERT_EQ(p.points.size(), pts.size());
  EXPECT_NEAR(p.height_min, 5, 1e-12);
  EXPECT_NEAR(p.height_max, 5, 1e-12);
  EXPECT_GT(p.rotation_error, 0);
  EXPECT_LT(p.rotation_error, 1e-12);  // a few ulps of |x| ~ 150
  // Independent check of the bound: recompute Q x in long double from the
  // same double matrix — the difference to the double result must be within
  // the bound (the bound also covers the matrix's own rounding).
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& q = p.rotation;
    const long double x = static_cast<long double>(q[0][0]) * pts[i].x + static_cast<long double>(q[0][1]) * pts[i].y +
                          static_cast<long double>(q[0][2]) * pts[i].z;
    EXPECT_LE(std::abs(static_cast<double>(x - p.points[i].x)), p.rotation_error);
    // pairwise distances preserved up to the bound
    if (i > 0) {
      const double dp = std::hypot(p.points[i].x - p.points[0].x, p.points[i].y - p.points[0].y);
      const double dq = std::hypot(planar[i].x - planar[0].x, planar[i].y - planar[0].y);
      EXPECT_NEAR(dp, dq, 1e-11);
    }
  }
  EXPECT_THROW((void)project_along(pts, {0, 0, 0}), Invalid_input);
  EXPECT_THROW((void)project_along(pts, {0, std::nan(""), 1}), Non_finite_input);
  pts[3].y = INFINITY;
  EXPECT_THROW((void)project_along(pts, d), Non_finite_input);
}

}  // namespace
}  // namespace relgeo::test
