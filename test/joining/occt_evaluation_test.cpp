// OpenCASCADE as the oracle of evaluation: relgeo's NURBS curves and
// surfaces (double) against Geom_BSplineSurface / Geom_BSplineCurve /
// Geom2d_BSplineCurve on random data (degrees 1-5, interior knots of
// multiplicity up to 2, random weights), values and first and second
// derivatives; conversions both ways lose nothing.
#include <gtest/gtest.h>

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

#include <algorithm>
#include <cmath>
#include <random>

#include "joining/surface_fixtures.h"
#include "relgeo/surfaces/occt_conversion.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

double rel(const gp_XYZ& occ, const Vector_3<double>& ours) {
  const double d = (occ - gp_XYZ(ours[0], ours[1], ours[2])).Modulus();
  return d / (1 + occ.Modulus());
}

TEST(OcctEvaluation, RandomSurfacesAgreeWithGeomBSplineSurface) {
  std::mt19937_64 rng(11);
  double worst[3] = {0, 0, 0};
  int compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int p = 1 + trial % 5, q = 1 + (trial / 5) % 5;
    const std::size_t nu = static_cast<std::size_t>(p) + 1 + trial % 6, nv = static_cast<std::size_t>(q) + 1 + (trial / 3) % 6;
    const Nurbs_surface<double> s = random_surface(rng, p, q, nu, nv, trial % 2 == 1);
    const Handle(Geom_BSplineSurface) g = to_occt(s);
    const auto [u0, u1] = s.domain_u();
    const auto [v0, v1] = s.domain_v();
    std::uniform_real_distribution<double> ru(u0, u1), rv(v0, v1);
    for (int k = 0; k < 25; ++k) {
      const double u = ru(rng), v = rv(rng);
      gp_Pnt P;
      gp_Vec Du, Dv, Duu, Dvv, Duv;
      g->D2(u, v, P, Du, Dv, Duu, Dvv, Duv);
      const Surface_derivatives<double> d = s.derivatives(u, v, 2);
      worst[0] = std::max(worst[0], rel(P.XYZ(), internal::to_vector(d.point)));
      worst[1] = std::max({worst[1], rel(Du.XYZ(), d.du), rel(Dv.XYZ(), d.dv)});
      worst[2] = std::max({worst[2], rel(Duu.XYZ(), d.duu), rel(Duv.XYZ(), d.duv), rel(Dvv.XYZ(), d.dvv)});
      ++compared;
    }
  }
  EXPECT_EQ(compared, 5000);
  EXPECT_LT(worst[0], 1e-13) << "values";
  EXPECT_LT(worst[1], 1e-11) << "first derivatives";
  EXPECT_LT(worst[2], 1e-9) << "second derivatives";
}

TEST(OcctEvaluation, RandomCurvesAgreeWithGeomBSplineCurves) {
  std::mt19937_64 rng(12);
  double worst = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int p = 1 + trial % 5;
    const Nurbs_curve_3<double> c3 = random_curve<3>(rng, p, static_cast<std::size_t>(p) + 2 + trial % 7, trial % 2 == 0);
    const Nurbs_curve_2<double> c2 = random_curve<2>(rng, p, static_cast<std::size_t>(p) + 2 + trial % 5, trial % 3 == 0);
    const Handle(Geom_BSplineCurve) g3 = to_occt(c3);
    const Handle(Geom2d_BSplineCurve) g2 = to_occt(c2);
    std::uniform_real_distribution<double> rt(0, 3);
    for (int k = 0; k < 20; ++k) {
      const double t = rt(rng);
      gp_Pnt P;
      gp_Vec V1, V2;
      g3->D2(t, P, V1, V2);
      const auto d = c3.derivatives(t, 2);
      worst = std::max({worst, rel(P.XYZ(), d[0]), rel(V1.XYZ(), d[1]) * 1e-2, rel(V2.XYZ(), d[2]) * 1e-4});
      gp_Pnt2d P2;
      gp_Vec2d W1, W2;
      g2->D2(t, P2, W1, W2);
      const auto e = c2.derivatives(t, 2);
      worst = std::max({worst, rel(gp_XYZ(P2.X(), P2.Y(), 0), {e[0][0], e[0][1], 0}),
                        rel(gp_XYZ(W1.X(), W1.Y(), 0), {e[1][0], e[1][1], 0}) * 1e-2,
                        rel(gp_XYZ(W2.X(), W2.Y(), 0), {e[2][0], e[2][1], 0}) * 1e-4});
    }
  }
  EXPECT_LT(worst, 1e-13);
}

TEST(OcctEvaluation, ConversionsRoundTripExactly) {
  std::mt19937_64 rng(13);
  for (int trial = 0; trial < 20; ++trial) {
    const Nurbs_surface<double> s = random_surface(rng, 1 + trial % 4, 1 + trial % 3, 7, 6, trial % 2 == 0);
    const Nurbs_surface<double> back = nurbs_surface_from_occt(to_occt(s));
    EXPECT_EQ(back.knots_u(), s.knots_u());
    EXPECT_EQ(back.knots_v(), s.knots_v());
    EXPECT_EQ(back.control_points(), s.control_points());
    EXPECT_EQ(back.weights(), s.weights());
    const Nurbs_curve_3<double> c = random_curve<3>(rng, 1 + trial % 5, 8, trial % 2 == 1);
    const Nurbs_curve_3<double> cb = nurbs_curve_from_occt(to_occt(c));
    EXPECT_EQ(cb.knots(), c.knots());
    EXPECT_EQ(cb.control_points(), c.control_points());
    EXPECT_EQ(cb.weights(), c.weights());
  }
  // The rational quarter cylinder: OCC agrees that it is a cylinder.
  const Handle(Geom_BSplineSurface) g = to_occt(quarter_cylinder());
  for (double u : {0.1, 0.5, 0.93}) {
    const gp_Pnt p = g->Value(u, 0.3);
    EXPECT_NEAR(p.X() * p.X() + p.Y() * p.Y(), 1.0, 1e-15);
  }
}

}  // namespace
