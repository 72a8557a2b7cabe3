// Projection onto NURBS surfaces (thesis Sec. 4.2, 4.3.2): points F(u,v) +
// eta n recovered with their parameters and heights; ambiguous, focal and
// out-of-domain points refused with typed errors; meshes projected with
// neighbour hints.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "joining/surface_fixtures.h"
#include "relgeo/joining/projection.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

// A gently curved bicubic patch over [0,1]^2 (no folds: projections unique).
Nurbs_surface<double> wavy_patch() {
  std::vector<Point_3<double>> P;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) P.push_back({i / 3.0, j / 3.0, 0.15 * std::sin(1.0 + i) * std::cos(0.5 * j)});
  return Nurbs_surface<double>(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4, P);
}

TEST(Projection, RecoversParametersAndHeights) {
  std::mt19937_64 rng(41);
  for (const Nurbs_surface<double>& s : {wavy_patch(), quarter_cylinder(), random_surface(rng, 3, 2, 6, 5, true)}) {
    const Surface_projector proj(s);
    const auto [u0, u1] = s.domain_u();
    const auto [v0, v1] = s.domain_v();
    std::uniform_real_distribution<double> ru(u0 + 0.05 * (u1 - u0), u1 - 0.05 * (u1 - u0)),
        rv(v0 + 0.05 * (v1 - v0), v1 - 0.05 * (v1 - v0)), rh(-1, 1);
    int tested = 0;
    for (int k = 0; k < 300; ++k) {
      const Point_2<double> uv{ru(rng), rv(rng)};
      const double h = 1e-3 * proj.scale() * rh(rng);
      const Point_3<double> x = proj.lift(uv, h);
      Surface_projection r;
      try {
        r = proj.project(x);
      } catch (const Projection_error&) {
        continue;  // a random surface may fold back on itself near x
      }
      ++tested;
      EXPECT_NEAR(r.height, h, 1e-12 * proj.scale());
      EXPECT_NEAR(r.uv.x, uv.x, 1e-9 * (u1 - u0));
      EXPECT_NEAR(r.uv.y, uv.y, 1e-9 * (v1 - v0));
      // With a hint from nearby: the same answer.
      const auto r2 = proj.project(x, Point_2<double>{uv.x + 0.01 * (u1 - u0), uv.y});
      EXPECT_NEAR(r2.uv.x, r.uv.x, 1e-11 * (u1 - u0));
    }
    EXPECT_GT(tested, 250);
  }
}

TEST(Projection, PointsOnTheSurfaceAndSlightlyBeyondItsEdge) {
  const Surface_projector proj(wavy_patch());
  const auto r = proj.project(wavy_patch().evaluate(0.25, 0.5));
  EXPECT_NEAR(r.height, 0, 1e-14);
  EXPECT_NEAR(r.uv.x, 0.25, 1e-12);
  // Just beyond u = 1 (within the 5% extrapolation): accepted, parameters > 1.
  const Point_3<double> beyond = proj.lift({1.02, 0.5}, 1e-4);
  const auto b = proj.project(beyond);
  EXPECT_NEAR(b.uv.x, 1.02, 1e-9);
  // Far beyond: the closest point is on the domain's border, not a normal
  // projection.
  const Point_3<double> far{1.5, 0.5, 0.0};
  try {
    (void)proj.project(far, std::nullopt, 7);
    ADD_FAILURE() << "accepted a point beyond the domain";
  } catch (const Projection_error& e) {
    EXPECT_EQ(e.failure(), Projection_failure::outside_domain);
    EXPECT_EQ(e.index(), 7u);
    EXPECT_EQ(e.code(), Error_code::invalid_input);
  }
}

TEST(Projection, AmbiguousAndFocalPointsAreRefused) {
  // A half cylinder (two rational quarters): its axis is equally far from
  // every point.
  const Nurbs_surface<double> half(2, 1, {0, 0, 0, 1, 1, 2, 2, 2}, {0, 0, 1, 1}, 5, 2,
                                   {{1, 0, 0}, {1, 0, 2}, {1, 1, 0}, {1, 1, 2}, {0, 1, 0}, {0, 1, 2},
                                    {-1, 1, 0}, {-1, 1, 2}, {-1, 0, 0}, {-1, 0, 2}},
                                   {1, 1, 1, 1, 2, 2, 1, 1, 1, 1});
  const Surface_projector proj(half);
  try {
    (void)proj.project({0, 0, 1});
    ADD_FAILURE() << "a point on the axis was projected";
  } catch (const Projection_error& e) {
    EXPECT_EQ(e.failure(), Projection_failure::not_unique);
  }
  // Beyond half the radius towards the axis: ill-conditioned (focal_ratio 0.5).
  EXPECT_THROW((void)proj.project({0.3, 0.3, 1}), Projection_error);
  EXPECT_NO_THROW((void)proj.project({0.5, 0.5, 1}));  // |eta| kappa = 0.29
  // Outside the cylinder, any distance: unique.
  const auto r = proj.project({3, 4, 1});
  EXPECT_NEAR(r.height, 4.0, 1e-12);  // normal points outward (Su x Sv)
}

TEST(Projection, MeshesWithNeighbourHints) {
  // A grid mesh lifted from the wavy patch with heights.
  const Nurbs_surface<double> s = wavy_patch();
  const Surface_projector proj(s);
  Triangle_mesh<Point_3<double>> m;
  const int n = 30;
  std::vector<double> h;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double eta = 2e-3 * std::sin(7.0 * i + 3.0 * j);
      m.vertices.push_back(proj.lift({0.05 + 0.9 * i / n, 0.05 + 0.9 * j / n}, eta));
      h.push_back(eta);
    }
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j) {
      const Index a = i * (n + 1) + j;
      m.faces.push_back({a, a + n + 1, a + n + 2}), m.faces.push_back({a, a + n + 2, a + 1});
    }
  const auto r = proj.project_mesh(m);
  ASSERT_EQ(r.size(), m.vertices.size());
  for (std::size_t v = 0; v < r.size(); ++v) EXPECT_NEAR(r[v].height, h[v], 1e-12);
  m.vertices[5].z = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)proj.project_mesh(m), Non_finite_input);
}

}  // namespace
