// Eigen V/F matrices in and out.
#include <gtest/gtest.h>

#include "mesh/mesh_fixtures.h"
#include "relgeo/mesh.h"
#include "relgeo/mesh/eigen_io.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;

TEST(EigenIo, RoundTrip) {
  const Mesh_d m = jitter(icosphere(1), 0.01);
  const auto [V, F] = to_eigen(m);
  EXPECT_EQ(V.rows(), Eigen::Index(m.vertices.size()));
  EXPECT_EQ(F.rows(), Eigen::Index(m.faces.size()));
  const Mesh_d back = from_eigen(V, F);
  EXPECT_EQ(back.vertices, m.vertices);
  EXPECT_EQ(back.faces, m.faces);
  EXPECT_TRUE(check_mesh(back).is_valid());
  // exact coordinates leave as doubles
  const auto [Ve, Fe] = to_eigen(convert<mpq_class>(m));
  EXPECT_EQ(Ve, V);
}

TEST(EigenIo, BadShapesAndIndicesAreTypedErrors) {
  Eigen::MatrixXd V(3, 2);
  V.setZero();
  Eigen::MatrixXi F(1, 3);
  F << 0, 1, 2;
  EXPECT_THROW((void)from_eigen(V, F), Invalid_input);
  Eigen::MatrixXd V3 = Eigen::MatrixXd::Zero(3, 3);
  F << 0, 1, 5;
  EXPECT_THROW((void)from_eigen(V3, F), Invalid_mesh);
  F << 0, -1, 2;
  EXPECT_THROW((void)from_eigen(V3, F), Invalid_mesh);
}

}  // namespace
