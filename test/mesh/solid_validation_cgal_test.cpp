// validate_solid and find_self_intersections against CGAL over Epeck on the
// meshes of CGAL's data set (data/meshes: OFF, PLY, STL; polygons split into
// fans, the same mesh for both) of up to 20000 faces times
// RELGEO_TEST_SCALE: closedness (CGAL::is_closed), self-intersection
// (PMP::does_self_intersect and the pairs of PMP::self_intersections),
// outward orientation of closed meshes without self-intersection
// (PMP::is_outward_oriented, volume_connected_components) and the exact
// volume (PMP::volume); a mesh relgeo calls a valid solid must be one for
// CGAL. Under Filtered_exact_kernel (the default), Exact_kernel on the
// small meshes (equal answers) and Failsafe_kernel (a subset of the
// answers, never a wrong one). CGAL's side is cgal_epeck_oracle.cpp, so
// this TU compiles no Epeck.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/cgal_epeck_oracle.h"
#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/failsafe_kernel.h"
#include "relgeo/mesh/mesh_io.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/solid_validation.h"
#include "support/soundness_data.h"

namespace {

using namespace relgeo;
using relgeo_test::Cgal_solid_verdict;
using relgeo_test::cgal_epeck_verdict;
using Mesh = Triangle_mesh<Point_3<double>>;

struct Data_mesh {
  std::string name;
  Mesh mesh;
};

// Every mesh file of the data set that reads as a triangle mesh.
const std::vector<Data_mesh>& data_meshes() {
  static const std::vector<Data_mesh> meshes = [] {
    std::vector<Data_mesh> out;
    const std::filesystem::path dir(RELGEO_CGAL_ALL_MESHES_DIR);
    if (!std::filesystem::is_directory(dir)) return out;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& p : files) {
      const std::string ext = p.extension().string();
      if (ext != ".off" && ext != ".ply" && ext != ".stl") continue;
      try {
        out.push_back({p.filename().string(), read_mesh(p.string(), {.triangulate_polygons = true})});
      } catch (const Error&) {  // unreadable, non-finite: not a mesh of this test
      }
    }
    return out;
  }();
  return meshes;
}

std::size_t max_faces() { return static_cast<std::size_t>(20000 * relgeo::test::test_scale()); }

bool contains(const std::vector<Face_pair>& v, const Face_pair& p) { return std::binary_search(v.begin(), v.end(), p); }

// The fail-safe kernel: a subset of the exact answers, never a wrong one.
void expect_failsafe_never_wrong(const Mesh& m, const std::vector<Face_pair>& expected, const Solid_report& exact,
                                 std::size_t& undecided_meshes) {
  const Self_intersections fs = find_self_intersections<Failsafe_kernel<double>>(m);
  for (const Face_pair& p : fs.pairs) EXPECT_TRUE(contains(expected, p)) << p.first << " " << p.second;
  for (const Face_pair& p : expected) {
    const bool undecided_face = std::binary_search(fs.undecided_faces.begin(), fs.undecided_faces.end(), p.first) ||
                                std::binary_search(fs.undecided_faces.begin(), fs.undecided_faces.end(), p.second);
    EXPECT_TRUE(contains(fs.pairs, p) || contains(fs.undecided, p) || undecided_face) << p.first << " " << p.second;
  }
  const Solid_report rf = validate_solid<Failsafe_kernel<double>>(m);
  rf.for_each_check([&](std::string_view name, const Solid_check& c) {
    if (c.status == Check_status::pass || c.status == Check_status::fail) {
      const Solid_check* e = nullptr;
      exact.for_each_check([&](std::string_view n, const Solid_check& x) {
        if (n == name) e = &x;
      });
      EXPECT_EQ(c.status, e->status) << name;
    }
  });
  undecided_meshes += !fs.undecided.empty();
}

TEST(SolidValidationCgal, DataSetMeshesAgreeWithCgalEpeck) {
  const auto& meshes = data_meshes();
  if (meshes.empty()) GTEST_SKIP() << "CGAL's data set not found (" << RELGEO_CGAL_ALL_MESHES_DIR << ")";
  const std::size_t limit = max_faces();
  std::size_t tested = 0, too_large = 0, not_representable = 0, open = 0, closed = 0, self_intersecting = 0;
  std::size_t oriented_checked = 0, valid = 0, exact_checked = 0, failsafe_undecided = 0;
  std::string self_intersecting_names;
  for (const Data_mesh& d : meshes) {
    if (d.mesh.faces.size() > limit) {
      ++too_large;
      continue;
    }
    SCOPED_TRACE(d.name);
    ++tested;
    const Solid_report r = validate_solid(d.mesh);
    const Cgal_solid_verdict cgal = cgal_epeck_verdict(d.mesh);
    // Never a valid solid that CGAL finds invalid.
    if (r.is_valid_solid()) {
      EXPECT_TRUE(cgal.valid_solid()) << r.summary();
      ++valid;
    }
    if (!cgal.representable) {  // Surface_mesh refuses it: non-manifold or misoriented
      ++not_representable;
      EXPECT_FALSE(r.edge_manifold.passed() && r.vertex_manifold.passed() && r.consistently_oriented.passed() &&
                   r.valid_indices.passed() && r.non_degenerate_faces.count == 0)
          << r.summary();
      continue;
    }
    if (d.mesh.faces.empty()) {  // a point set (b9.ply): no solid
      EXPECT_FALSE(r.is_valid_solid());
      continue;
    }
    // The Euler counts (read off the topology on an edge-manifold mesh)
    // equal those of the distinct vertex pairs.
    {
      const internal::Face_components comps = internal::face_components(d.mesh.faces, d.mesh.vertices.size());
      std::size_t edges = 0;
      long long characteristic = 0;
      for (const internal::Euler_counts& c : internal::euler_counts(d.mesh.faces, d.mesh.vertices.size(), comps))
        edges += c.edges, characteristic += c.characteristic();
      EXPECT_EQ(r.edges, edges);
      EXPECT_EQ(r.euler_characteristic, characteristic);
    }
    // Closedness.
    EXPECT_EQ(r.closed.passed(), cgal.closed) << r.summary();
    (cgal.closed ? closed : open) += 1;
    // Self-intersection: the same pairs, the same verdict (CGAL counts a
    // degenerate face as a self-intersection; relgeo reports it as such).
    const Self_intersections mine = find_self_intersections(d.mesh);
    EXPECT_EQ(mine.pairs, cgal.pairs);
    EXPECT_TRUE(mine.undecided.empty() && mine.undecided_faces.empty());
    // check_solid decides the pairs around vertices with an embedded star
    // without predicates (internal/embedded_stars.h): the same pairs.
    const Mesh_report solid = check_solid(d.mesh, {.require_closed = false});
    if (solid.self_intersections_checked) {
      std::vector<Face_pair> pairs;
      for (const Mesh_issue& i : solid.issues)
        if (i.defect == Mesh_defect::self_intersection) pairs.push_back({i.elements[0], i.elements[1]});
      std::sort(pairs.begin(), pairs.end());
      EXPECT_EQ(pairs, cgal.pairs);
    }
    EXPECT_EQ(r.self_intersection_free.count, cgal.pairs.size());
    EXPECT_EQ(r.self_intersection_free.passed() && r.non_degenerate_faces.passed(), !cgal.self_intersects)
        << r.summary();
    if (cgal.self_intersects) {
      ++self_intersecting;
      self_intersecting_names += " " + d.name;
    }
    if (cgal.closed) {
      ASSERT_TRUE(r.volume.exact);
      EXPECT_EQ(mpq_class(r.volume.exact_value), mpq_class(cgal.volume));
    }
    // Outward orientation of closed meshes without self-intersection (CGAL's
    // tests assume a manifold without isolated vertices, as relgeo's does).
    if (cgal.outward_oriented && r.edge_manifold.passed() && r.vertex_manifold.passed() &&
        r.consistently_oriented.passed() && r.no_isolated_vertices.passed()) {
      ++oriented_checked;
      EXPECT_NE(r.outward_oriented.status, Check_status::undecided);
      EXPECT_EQ(r.outward_oriented.passed(), *cgal.bounds_outward_volume) << r.summary();
      if (r.components == 1) {
        EXPECT_EQ(r.outward_oriented.passed(), *cgal.outward_oriented) << r.summary();
      }
      // Both ways: CGAL's valid solid is relgeo's.
      EXPECT_EQ(r.is_valid_solid(), cgal.valid_solid()) << r.summary();
    }
    expect_failsafe_never_wrong(d.mesh, cgal.pairs, r, failsafe_undecided);
    if (d.mesh.faces.size() <= 3000) {  // Exact_kernel: the same answers
      ++exact_checked;
      EXPECT_EQ(find_self_intersections<Exact_kernel>(d.mesh).pairs, cgal.pairs);
      const Solid_report re = validate_solid<Exact_kernel>(d.mesh);
      r.for_each_check([&](std::string_view name, const Solid_check& c) {
        re.for_each_check([&](std::string_view n, const Solid_check& x) {
          if (n == name) {
            EXPECT_EQ(x.status, c.status) << name;
          }
        });
      });
      EXPECT_EQ(re.volume.exact_value, r.volume.exact_value);
    }
  }
  std::printf("[ data set ] %zu meshes read, %zu tested (<= %zu faces; %zu larger skipped): %zu not representable "
              "in Surface_mesh, %zu open, %zu closed, %zu self-intersecting:%s; orientation compared on %zu; %zu "
              "valid solids; Exact_kernel on %zu; fail-safe left pairs undecided on %zu\n",
              meshes.size(), tested, limit, too_large, not_representable, open, closed, self_intersecting,
              self_intersecting_names.c_str(), oriented_checked, valid, exact_checked, failsafe_undecided);
  if (relgeo::test::test_scale() >= 1) {  // the data set exercises every verdict
    EXPECT_GE(closed, 30u);
    EXPECT_GE(open, 10u);
    EXPECT_GE(self_intersecting, 1u);
    EXPECT_GE(oriented_checked, 20u);
    EXPECT_GE(valid, 20u);
    EXPECT_LT(valid, oriented_checked + 1);
  }
}

// Rigid motions of closed meshes against themselves: the union of a mesh and
// a moved copy self-intersects exactly where CGAL says.
TEST(SolidValidationCgal, MeshesAgainstMovedCopiesOfThemselves) {
  const auto& meshes = data_meshes();
  if (meshes.empty()) GTEST_SKIP() << "CGAL's data set not found";
  std::size_t tested = 0;
  for (const char* name : {"elephant.off", "eight.off", "sphere.off", "knot1.off", "fandisk.off", "cow.off"}) {
    const auto it = std::find_if(meshes.begin(), meshes.end(), [&](const Data_mesh& d) { return d.name == name; });
    if (it == meshes.end() || 2 * it->mesh.faces.size() > max_faces()) continue;
    SCOPED_TRACE(name);
    Mesh both = it->mesh;
    const Index off = static_cast<Index>(both.vertices.size());
    const double c = std::cos(0.3), s = std::sin(0.3);
    for (const auto& p : it->mesh.vertices) both.vertices.push_back({c * p.x - s * p.y + 0.01, s * p.x + c * p.y, p.z});
    for (const Triangle& t : it->mesh.faces) both.faces.push_back({t[0] + off, t[1] + off, t[2] + off});
    const Cgal_solid_verdict cgal = cgal_epeck_verdict(both, /*pairs_only=*/true);
    ASSERT_TRUE(cgal.representable);
    EXPECT_EQ(find_self_intersections(both, {.threads = 2}).pairs, cgal.pairs);
    EXPECT_FALSE(cgal.pairs.empty());
    EXPECT_FALSE(validate_solid(both).is_valid_solid());
    ++tested;
  }
  if (relgeo::test::test_scale() >= 1) {
    EXPECT_GE(tested, 3u);
  }
}

}  // namespace
