// STEP and IGES input through OpenCASCADE. The files are made here, with
// OCC: a B-spline face, a trimmed cylinder, a face with a hole, two faces
// sewn along a shared edge; nothing is downloaded. Bad files give
// Unreadable_file.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <GC_MakeCircle.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <gp_Ax3.hxx>
#include <gp_Circ.hxx>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <unistd.h>

#include "joining/surface_fixtures.h"
#include "relgeo/kernel.h"
#include "relgeo/surfaces/occt_io.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("relgeo_occt_" + std::to_string(::getpid()) + "_" + name)).string();
}

// Writes `shape` in both formats, reads both back.
std::vector<Surface_model> through_files(const TopoDS_Shape& shape, const std::string& name) {
  std::vector<Surface_model> models;
  const std::string step = temp_path(name + ".step"), iges = temp_path(name + ".igs");
  write_step_shape(shape, step);
  write_iges_shape(shape, iges);
  models.push_back(read_cad_model(step));
  models.push_back(read_cad_model(iges));
  std::filesystem::remove(step), std::filesystem::remove(iges);
  return models;
}

// Largest distance between the surface and OCC's at the face's own (u,v)
// samples inside its domain.
TEST(OcctIo, BSplineFaceSurvivesStepAndIges) {
  std::mt19937_64 rng(21);
  const Nurbs_surface<double> s = random_surface(rng, 3, 3, 6, 5, true);
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(to_occt(s), 1e-7);
  for (const Surface_model& m : through_files(face, "bspline")) {
    ASSERT_EQ(m.faces.size(), 1u);
    const Trimmed_surface& f = m.faces[0];
    const auto [u0, u1] = f.surface().domain_u();
    const auto [v0, v1] = f.surface().domain_v();
    EXPECT_EQ(f.inner_loops().size(), 0u);
    EXPECT_EQ(f.outer_loop().curves.size(), 4u);
    for (int i = 0; i <= 8; ++i)
      for (int j = 0; j <= 8; ++j) {
        const double u = u0 + (u1 - u0) * i / 8, v = v0 + (v1 - v0) * j / 8;
        const auto a = f.surface().evaluate(u, v), b = s.evaluate(u, v);
        EXPECT_NEAR(a.x, b.x, 1e-9);
        EXPECT_NEAR(a.y, b.y, 1e-9);
        EXPECT_NEAR(a.z, b.z, 1e-9);
      }
    EXPECT_EQ(f.locate<Filtered_exact_kernel>({0.5 * (u0 + u1), 0.5 * (v0 + v1)}), Domain_location::inside);
    // Every edge of the face has its 3D curve, on the surface at its ends.
    for (const Model_edge& e : m.edges) EXPECT_TRUE(e.has_geometry());
  }
}

TEST(OcctIo, TrimmedCylinderIsARationalSurfaceOnTheCylinder) {
  Handle(Geom_CylindricalSurface) cyl = new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), 2.0);
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(cyl, 0.3, 2.0, -1.0, 1.5, 1e-7);
  for (const Surface_model& m : through_files(face, "cylinder")) {
    ASSERT_EQ(m.faces.size(), 1u);
    const Trimmed_surface& f = m.faces[0];
    EXPECT_TRUE(f.surface().is_rational());
    int inside = 0;
    const auto [u0, u1] = f.surface().domain_u();
    const auto [v0, v1] = f.surface().domain_v();
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        const double u = u0 + (u1 - u0) * i / 20, v = v0 + (v1 - v0) * j / 20;
        if (f.locate<Filtered_exact_kernel>({u, v}) != Domain_location::inside) continue;
        ++inside;
        const auto p = f.surface().evaluate(u, v);
        EXPECT_NEAR(std::hypot(p.x, p.y), 2.0, 1e-9);
        EXPECT_GE(std::atan2(p.y, p.x), 0.3 - 1e-7);
        EXPECT_LE(std::atan2(p.y, p.x), 2.0 + 1e-7);
        EXPECT_GE(p.z, -1.0 - 1e-7);
        EXPECT_LE(p.z, 1.5 + 1e-7);
      }
    EXPECT_GT(inside, 100);
  }
}

TEST(OcctIo, FaceWithAHole) {
  Handle(Geom_Plane) plane = new Geom_Plane(gp::XOY());
  BRepBuilderAPI_MakeWire outer;
  const gp_Pnt c[4] = {{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {0, 3, 0}};
  for (int i = 0; i < 4; ++i) outer.Add(BRepBuilderAPI_MakeEdge(c[i], c[(i + 1) % 4]));
  BRepBuilderAPI_MakeFace mf(plane, outer.Wire());
  TopoDS_Wire hole = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(2, 1.5, 0), gp::DZ()), 0.75)));
  hole.Reverse();
  mf.Add(hole);
  for (const Surface_model& m : through_files(mf.Face(), "hole")) {
    ASSERT_EQ(m.faces.size(), 1u);
    const Trimmed_surface& f = m.faces[0];
    ASSERT_EQ(f.inner_loops().size(), 1u);
    // The plane's parametrisation is (x, y) up to the NURBS conversion: find
    // the parameters of a few points through the surface itself.
    const auto param_of = [&](double x, double y) {
      // The converted plane is bilinear: invert on a fine grid (enough here).
      const auto [u0, u1] = f.surface().domain_u();
      const auto [v0, v1] = f.surface().domain_v();
      Point_2<double> best{u0, v0};
      double bd = 1e300;
      for (int i = 0; i <= 400; ++i)
        for (int j = 0; j <= 400; ++j) {
          const double u = u0 + (u1 - u0) * i / 400, v = v0 + (v1 - v0) * j / 400;
          const auto p = f.surface().evaluate(u, v);
          const double d = std::hypot(p.x - x, p.y - y);
          if (d < bd) bd = d, best = {u, v};
        }
      return best;
    };
    EXPECT_EQ(f.locate<Filtered_exact_kernel>(param_of(2, 1.5)), Domain_location::outside);  // the hole
    EXPECT_EQ(f.locate<Filtered_exact_kernel>(param_of(0.5, 0.5)), Domain_location::inside);
    EXPECT_EQ(f.locate<Filtered_exact_kernel>(param_of(3.5, 2.6)), Domain_location::inside);
  }
}

TEST(OcctIo, SewnFacesShareTheirEdge) {
  // Two B-spline patches meeting along x = 1, sewn into a shell.
  const auto patch = [](double x0) {
    std::vector<Point_3<double>> P;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) P.push_back({x0 + 0.5 * i, 0.5 * j, 0.1 * (x0 + 0.5 * i) * (0.5 * j)});
    return Nurbs_surface<double>(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, 3, 3, P);
  };
  BRepBuilderAPI_Sewing sewing(1e-6);
  sewing.Add(BRepBuilderAPI_MakeFace(to_occt(patch(0)), 1e-7));
  sewing.Add(BRepBuilderAPI_MakeFace(to_occt(patch(1)), 1e-7));
  sewing.Perform();
  for (const Surface_model& m : through_files(sewing.SewedShape(), "sewn")) {
    ASSERT_EQ(m.faces.size(), 2u);
    const auto uses = m.edge_uses();
    int shared = 0;
    for (std::size_t e = 0; e < uses.size(); ++e) {
      if (uses[e].size() != 2) continue;
      ++shared;
      ASSERT_TRUE(m.edges[e].curve.has_value());
      const auto& c = *m.edges[e].curve;
      for (int k = 0; k <= 4; ++k) {
        const auto [t0, t1] = c.domain();
        const auto p = c.evaluate(t0 + (t1 - t0) * k / 4);
        EXPECT_NEAR(p.x, 1.0, 1e-9);
      }
      EXPECT_NE(uses[e][0].face, uses[e][1].face);
    }
    EXPECT_EQ(shared, 1);
  }
}

TEST(OcctIoBadInput, UnreadableFilesAreTypedErrors) {
  EXPECT_THROW(read_cad_model("/nonexistent/relgeo/part.step"), Unreadable_file);
  EXPECT_THROW(read_cad_model("/nonexistent/relgeo/part.igs"), Unreadable_file);
  const std::string garbage = temp_path("garbage.step");
  std::ofstream(garbage) << "this is not a STEP file\n";
  EXPECT_THROW(read_cad_model(garbage), Unreadable_file);
  const std::string garbage_iges = temp_path("garbage.iges");
  std::ofstream(garbage_iges) << "neither is this an IGES file\n";
  EXPECT_THROW(read_cad_model(garbage_iges), Unreadable_file);
  const std::string other = temp_path("part.obj");
  std::ofstream(other) << "v 0 0 0\n";
  EXPECT_THROW(read_cad_model(other), Unreadable_file);
  // A STEP file holding only an edge: no face.
  const std::string edge_only = temp_path("edge.step");
  write_step_shape(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge(), edge_only);
  try {
    (void)read_cad_model(edge_only);
    ADD_FAILURE() << "accepted a file without faces";
  } catch (const Unreadable_file& e) {
    EXPECT_EQ(e.code(), Error_code::unreadable_file);
  }
  for (const auto& p : {garbage, garbage_iges, other, edge_only}) std::filesystem::remove(p);
}

}  // namespace
