// Bad input to the joiner: each a typed error naming the problem.
#include <gtest/gtest.h>

#include <limits>

#include "joining/join_fixtures.h"
#include "relgeo/joining/joiner.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

template <class E, class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
    return {};
  }
  ADD_FAILURE() << "no exception";
  return {};
}

TEST(JoinBadInput, TypedErrors) {
  const Joining_case good = make_joining_case("two faces", two_face_model(false));
  // NaN in a mesh.
  {
    Joining_case c = good;
    c.meshes[1].vertices[17].z = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(error_of<Non_finite_input>([&] { (void)join_meshes(c.model, c.meshes); }).find("face 1"), std::string::npos);
  }
  // An empty mesh; a missing mesh.
  {
    Joining_case c = good;
    c.meshes[0].faces.clear();
    EXPECT_NE(error_of<Joining_input_error>([&] { (void)join_meshes(c.model, c.meshes); }).find("no triangle"), std::string::npos);
    c.meshes.pop_back();
    EXPECT_NE(error_of<Joining_input_error>([&] { (void)join_meshes(c.model, c.meshes); }).find("meshes for"), std::string::npos);
    EXPECT_THROW((void)join_meshes(Surface_model{}, {}), Joining_input_error);
  }
  // A non-manifold mesh (an edge in three triangles).
  {
    Joining_case c = good;
    const Triangle t = c.meshes[0].faces[5];
    c.meshes[0].vertices.push_back({0.1, 0.1, 0.3});
    c.meshes[0].faces.push_back({t[0], t[1], static_cast<Index>(c.meshes[0].vertices.size() - 1)});
    EXPECT_THROW((void)join_meshes(c.model, c.meshes), Invalid_mesh);
  }
  // A mesh far from its surface: projections leave the domain.
  {
    Joining_case c = good;
    for (auto& p : c.meshes[0].vertices) p.x += 5;
    const std::string m = error_of<Projection_error>([&] { (void)join_meshes(c.model, c.meshes); });
    EXPECT_NE(m.find("domain"), std::string::npos) << m;
  }
  // A closed mesh has nothing to join.
  {
    Joining_case c = good;
    Triangle_mesh<Point_3<double>> tet;
    tet.vertices = {{0.1, 0.1, 0}, {0.3, 0.1, 0}, {0.1, 0.3, 0}, {0.15, 0.15, 0.01}};
    tet.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    c.meshes[0] = tet;
    EXPECT_THROW((void)join_meshes(c.model, c.meshes), Joining_input_error);
  }
  // A mesh whose boundary does not match its face's trim loops (a hole punched).
  {
    Joining_case c = good;
    auto& f = c.meshes[0].faces;
    const Mesh_topology t = Mesh_topology::build(c.meshes[0]);
    const auto interior = std::find_if(f.begin() + static_cast<std::ptrdiff_t>(f.size() / 2), f.end(), [&](const Triangle& x) {
      return !t.is_boundary_vertex(x[0]) && !t.is_boundary_vertex(x[1]) && !t.is_boundary_vertex(x[2]);
    });
    ASSERT_NE(interior, f.end());
    f.erase(interior);
    EXPECT_NE(error_of<Joining_input_error>([&] { (void)join_meshes(c.model, c.meshes); }).find("boundary cycles"),
              std::string::npos);
  }
  // An edge named by three trim curves.
  {
    Joining_case c = make_joining_case("three faces", three_face_model(false));
    Surface_model m = c.model;
    Trim_loop outer = m.faces[2].outer_loop();
    outer.curves[3].edge = 0;  // the top edge claims the shared edge 0 too
    m.faces[2] = Trimmed_surface(m.faces[2].surface(), outer);
    EXPECT_NE(error_of<Joining_input_error>([&] { (void)join_meshes(m, c.meshes); }).find("shared by 3"), std::string::npos);
  }
  // Degenerate surfaces. (a) (x, y) = (u + v, v^2): folded along v = 0,
  // where Su and Sv are parallel; a vertex below the fold projects onto it.
  {
    const Nurbs_surface<double> fold(1, 2, {0, 0, 1, 1}, {0, 0, 0, 1, 1, 1}, 2, 3,
                                     {{-1, 1, 0}, {0, -1, 0}, {1, 1, 0}, {0, 1, 0}, {1, -1, 0}, {2, 1, 0}});
    Surface_model m;
    m.faces.push_back(Trimmed_surface::untrimmed(fold));
    Triangle_mesh<Point_3<double>> mesh;
    mesh.vertices = {{0.5, -0.01, 0}, {0.6, 0.2, 0}, {0.4, 0.2, 0}};
    mesh.faces = {{0, 1, 2}};
    EXPECT_NE(error_of<Degenerate_surface>([&] { (void)join_meshes(m, {mesh}); }).find("Su x Sv"), std::string::npos);
  }
  // (b) A collapsed edge (a triangle as a bilinear patch): a vertex at the
  // apex has a whole edge of closest parameters.
  {
    const Nurbs_surface<double> apex(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    Surface_model m;
    m.faces.push_back(Trimmed_surface::untrimmed(apex));
    Triangle_mesh<Point_3<double>> mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 0}};
    mesh.faces = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    try {
      (void)join_meshes(m, {mesh});
      ADD_FAILURE() << "joined a mesh over a collapsed edge";
    } catch (const Projection_error& e) {
      EXPECT_EQ(e.failure(), Projection_failure::not_unique);
      EXPECT_EQ(e.index(), 0u);
    }
  }
}

}  // namespace
