// Files (OFF by relgeo's reader and writer; OBJ, PLY, STL through CGAL's IO), tag side files, Surface_mesh
// conversion, CGAL's data meshes, and unreadable / bad files.
#include <gtest/gtest.h>

#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "mesh/mesh_fixtures.h"
#include "relgeo/mesh.h"
#include "relgeo/mesh/cgal_conversion.h"
#include "relgeo/mesh/mesh_io.h"

namespace {

using namespace relgeo;
using namespace relgeo_test;
namespace fs = std::filesystem;

const std::string data_dir = RELGEO_TEST_DATA_DIR;
const std::string cgal_dir = RELGEO_CGAL_MESH_DIR;

std::string temp_path(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "relgeo_mesh_io_test";
  fs::create_directories(dir);
  return (dir / name).string();
}

class RoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(RoundTrip, DoublesSurviveExactlyAndConnectivityIsKept) {
  const Mesh_d m = jitter(icosphere(1), 1e-3);
  const std::string path = temp_path("icosphere." + GetParam());
  write_mesh(path, m);
  const Mesh_d r = read_mesh(path);
  if (GetParam() == "stl") {
    // STL stores triangles, not shared vertices: CGAL merges equal points
    // again, possibly renumbering them; compare counts and the point set.
    EXPECT_EQ(r.faces.size(), m.faces.size());
    EXPECT_EQ(r.vertices.size(), m.vertices.size());
    EXPECT_TRUE(check_mesh(r).is_valid()) << check_mesh(r).summary();
  } else {
    EXPECT_EQ(r.faces, m.faces);
    EXPECT_EQ(r.vertices, m.vertices);  // 17 digits: exact
  }
}
INSTANTIATE_TEST_SUITE_P(Formats, RoundTrip, ::testing::Values("off", "obj", "ply", "stl"));

// relgeo's OFF writer (shortest round-trip decimals) over the whole range of
// doubles: random bit patterns (subnormals, the largest exponents, negative
// zero), every one read back to the same bits.
TEST(MeshIo, OffWritesEveryFiniteDoubleSoThatItReadsBackExactly) {
  std::mt19937_64 rng(20261129);
  Mesh_d m;
  while (m.vertices.size() < 30000) {
    double c[3];
    for (double& x : c) {
      const std::uint64_t bits = rng();
      std::memcpy(&x, &bits, sizeof x);
      if (!std::isfinite(x)) x = -0.0;
    }
    m.vertices.push_back({c[0], c[1], c[2]});
  }
  m.vertices.push_back({std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(),
                        -std::numeric_limits<double>::min()});
  for (Index v = 0; v + 2 < m.vertices.size(); v += 3) m.faces.push_back({v, v + 1, v + 2});
  const std::string path = temp_path("random_bits.off");
  write_mesh(path, m);
  const Mesh_d r = read_mesh(path);
  ASSERT_EQ(r.vertices.size(), m.vertices.size());
  EXPECT_EQ(r.faces, m.faces);
  std::size_t different = 0;
  for (std::size_t v = 0; v < m.vertices.size(); ++v)
    for (int i = 0; i < 3; ++i) {
      const double a = i == 0 ? m.vertices[v].x : i == 1 ? m.vertices[v].y : m.vertices[v].z;
      const double b = i == 0 ? r.vertices[v].x : i == 1 ? r.vertices[v].y : r.vertices[v].z;
      different += std::memcmp(&a, &b, sizeof a) != 0;
    }
  EXPECT_EQ(different, 0u);
}

// Write_options::precision below 17 rounds to that many significant digits.
TEST(MeshIo, OffPrecisionRoundsToItsDigits) {
  Mesh_d m = tetrahedron();
  m.vertices[0] = {1.0 / 3.0, -2.0 / 3.0, 12345.678901};
  const std::string path = temp_path("precision.off");
  write_mesh(path, m, {.precision = 6});
  const Mesh_d r = read_mesh(path);
  EXPECT_EQ(r.vertices[0].x, 0.333333);
  EXPECT_EQ(r.vertices[0].y, -0.666667);
  EXPECT_EQ(r.vertices[0].z, 12345.7);
  EXPECT_EQ(r.faces, m.faces);
}

TEST(MeshIo, BinaryPlyIsExact) {
  const Mesh_d m = jitter(torus(6, 5), 1e-2);
  const std::string path = temp_path("torus_bin.ply");
  write_mesh(path, m, {.binary = true});
  EXPECT_EQ(read_mesh(path).vertices, m.vertices);
}

TEST(MeshIo, CommittedFilesAndTheTagSideFile) {
  const Mesh_d box = read_mesh(data_dir + "/creased_box.off", {.tags_path = data_dir + "/creased_box.tags"});
  EXPECT_EQ(box, creased_box());  // geometry, faces and tags
  EXPECT_EQ(box.tags.creases().size(), 12u);
  EXPECT_EQ(box.tags.corners().size(), 8u);
  EXPECT_EQ(read_mesh(data_dir + "/bipyramid7.obj").faces.size(), 14u);
  EXPECT_EQ(read_mesh(data_dir + "/open_grid3.ply").faces.size(), 18u);
  // tags round trip
  const std::string tp = temp_path("box.tags");
  write_feature_tags(tp, box.tags);
  EXPECT_EQ(read_feature_tags(tp), box.tags);
}

TEST(MeshIo, BadFilesGiveTypedErrors) {
  EXPECT_THROW((void)read_mesh(data_dir + "/does_not_exist.off"), Unreadable_file);
  EXPECT_THROW((void)read_mesh(data_dir + "/garbage.off"), Unreadable_file);
  EXPECT_THROW((void)read_mesh(data_dir + "/README.md"), Unreadable_file);  // unknown format
  try {
    (void)read_mesh(data_dir + "/nan_vertex.off");
    FAIL() << "NaN accepted";
  } catch (const Non_finite_input& e) {
    EXPECT_EQ(e.code(), Error_code::non_finite_coordinate);
  } catch (const Unreadable_file&) {
    // CGAL's OFF reader may refuse "nan" itself: still a clear typed error
  }
  EXPECT_THROW((void)read_mesh(data_dir + "/quad_cube.off"), Invalid_input);
  const Mesh_d cube = read_mesh(data_dir + "/quad_cube.off", {.triangulate_polygons = true});
  EXPECT_EQ(cube.faces.size(), 12u);
  EXPECT_TRUE(check_mesh(cube).is_valid());
  const Mesh_d nm = read_mesh(data_dir + "/nonmanifold_edge.off");  // reading does not judge
  EXPECT_EQ(check_mesh(nm, {.require_closed = false}).count(Mesh_defect::non_manifold_edge), 1u);
  try {
    (void)read_feature_tags(data_dir + "/bad_tags.tags");
    FAIL();
  } catch (const Unreadable_file& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_mesh(temp_path("x.unknown_ext"), tetrahedron()), Unreadable_file);
}

TEST(CgalConversion, SurfaceMeshRoundTripKeepsIndicesAndTags) {
  using K = CGAL::Simple_cartesian<double>;
  const Mesh_d box = creased_box();
  const auto sm = to_surface_mesh<K::Point_3>(box);
  EXPECT_EQ(sm.number_of_vertices(), box.vertices.size());
  EXPECT_EQ(sm.number_of_faces(), box.faces.size());
  EXPECT_TRUE(CGAL::is_closed(sm));
  const Mesh_d back = from_surface_mesh<Point_3<double>>(sm);
  EXPECT_EQ(back.vertices, box.vertices);
  EXPECT_EQ(back.tags, box.tags);
  // faces: same triangles, possibly rotated
  ASSERT_EQ(back.faces.size(), box.faces.size());
  for (std::size_t f = 0; f < box.faces.size(); ++f) {
    const Triangle a = box.faces[f], b = back.faces[f];
    const bool same = (a == b) || (a == Triangle{b[1], b[2], b[0]}) || (a == Triangle{b[2], b[0], b[1]});
    EXPECT_TRUE(same) << f;
  }
  Mesh_d nm = tetrahedron();
  nm.faces.push_back({0, 1, 3});
  EXPECT_THROW((void)to_surface_mesh<K::Point_3>(nm), Invalid_mesh);
}

TEST(CgalData, RealMeshesAreValidClosedManifolds) {
  if (!fs::exists(cgal_dir + "/elephant.off")) GTEST_SKIP() << "CGAL data set not installed (libcgal-demo)";
  struct Expect {
    const char* name;
    std::size_t faces;
    long euler;
  };
  for (const Expect& e : {Expect{"elephant.off", 5558, -4}, Expect{"eight.off", 634, -2}, Expect{"sphere.off", 320, 2},
                          Expect{"knot1.off", 6400, 0}, Expect{"fandisk.off", 12946, 2}}) {
    const Mesh_d m = read_mesh(cgal_dir + "/" + e.name);
    EXPECT_EQ(m.faces.size(), e.faces) << e.name;
    const Mesh_report r = check_mesh(m);
    EXPECT_TRUE(r.is_valid()) << e.name << ": " << r.summary();
    const Mesh_topology t = Mesh_topology::build(m);
    EXPECT_EQ(long(t.number_of_vertices()) - long(t.number_of_edges()) + long(t.number_of_faces()), e.euler)
        << e.name;
  }
}

}  // namespace
