// The mesh-reader contract (doc/reliability.md, harnesses mesh_*):
//  * read_mesh returns a mesh whose face indices are all in range and whose
//    coordinates are all finite, or throws a relgeo::Error;
//  * the same holds with triangulate_polygons, which can only add faces;
//  * check_mesh never throws on what read_mesh returned;
//  * writing the mesh back in the same format (ASCII) and reading it again
//    gives the same vertices and faces (OFF, OBJ, PLY; STL re-reads);
//  * a mesh check_mesh finds free of topological defects is refined by Loop
//    subdivision into a mesh that is again free of them, with finite
//    coordinates — or refused with a typed error (two faces sharing two
//    edges, or coordinates whose refinement overflows).
#include "mesh_file_harness.h"

#include <cmath>
#include <string>

#include "fuzz_support.h"
#include "loop_input.h"
#include "relgeo/kernel/naive_kernel.h"
#include "relgeo/mesh/mesh_io.h"
#include "relgeo/mesh/validity.h"
#include "relgeo/subdivision/loop_subdivision.h"

namespace relgeo::fuzz {
namespace {

using Mesh = Triangle_mesh<Point_3<double>>;

// Bigger meshes are read and checked but not refined (time per input).
constexpr std::size_t max_refined_faces = 2000;

void require_well_formed(const Mesh& m, const char* who) {
  for (const Triangle& f : m.faces)
    for (Index v : f) require(v < m.vertices.size(), std::string(who) + ": face index in range");
  for (const auto& p : m.vertices)
    require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), std::string(who) + ": finite coordinates");
}

void check_refinement(const Mesh& m) {
  if (m.faces.size() > max_refined_faces) return;
  Mesh_report report;
  typed_errors_only([&] { report = loop_topology_report(m); }, "check_mesh");
  if (!report.is_valid()) return;
  Mesh refined;
  Loop_subdivider<Naive_kernel<double>> loop;
  const bool ok = typed_errors_only([&] { refined = loop.refine(m, 1); }, "Loop refinement");
  if (!ok) return;
  require(refined.faces.size() == 4 * m.faces.size(), "Loop refinement: four faces per face");
  require_well_formed(refined, "Loop refinement");
  require(loop_topology_report(refined).is_valid(), "Loop refinement keeps a valid mesh valid");
}

std::string sibling_path(const std::string& path, std::string_view extension) {
  return path + ".again" + std::string(extension);
}

}  // namespace

void check_mesh_file(const std::uint8_t* data, std::size_t size, std::string_view extension) {
  const Temporary_file file(data, size, extension);
  Mesh m;
  if (!typed_errors_only([&] { m = read_mesh(file.path()); }, "read_mesh")) {
    // Polygons with more than three corners are an error only without
    // triangulation; either way the result is well formed or typed.
    Mesh t;
    if (typed_errors_only([&] { t = read_mesh(file.path(), {.triangulate_polygons = true}); }, "read_mesh"))
      require_well_formed(t, "read_mesh (triangulated)");
    return;
  }
  require_well_formed(m, "read_mesh");
  require(m.tags.empty(), "read_mesh: no tags without a tag file");
  Mesh t;
  const bool triangulated =
      typed_errors_only([&] { t = read_mesh(file.path(), {.triangulate_polygons = true}); }, "read_mesh");
  require(triangulated && t == m, "read_mesh: triangulation changes nothing on triangles");

  typed_errors_only([&] { (void)check_mesh(m); }, "check_mesh");
  require(!check_mesh(m).has(Mesh_defect::index_out_of_range), "check_mesh: read_mesh's indices are in range");

  // Round trip through the writer in the same format.
  const std::string again = sibling_path(file.path(), extension);
  const bool written = typed_errors_only([&] { write_mesh(again, m); }, "write_mesh");
  if (written) {
    Mesh back;
    const bool read = typed_errors_only([&] { back = read_mesh(again); }, "read_mesh (round trip)");
    std::remove(again.c_str());
    if (extension != ".stl") {
      // STL has no shared vertices: its reader merges equal points, so only
      // the formats with an index list must give back the same mesh.
      require(read, "read_mesh reads what write_mesh wrote");
      require(back.faces == m.faces, "round trip keeps the faces");
      require(back.vertices.size() == m.vertices.size(), "round trip keeps the vertex count");
      for (std::size_t i = 0; i < m.vertices.size(); ++i)
        require(back.vertices[i].x == m.vertices[i].x && back.vertices[i].y == m.vertices[i].y &&
                    back.vertices[i].z == m.vertices[i].z,
                "round trip keeps the coordinates (17 digits)");
    }
  } else {
    std::remove(again.c_str());
  }
  check_refinement(m);
}

void check_tag_file(const std::uint8_t* data, std::size_t size) {
  const Temporary_file file(data, size, ".tags");
  Feature_tags tags;
  if (!typed_errors_only([&] { tags = read_feature_tags(file.path()); }, "read_feature_tags")) return;
  // Round trip.
  const std::string again = sibling_path(file.path(), ".tags");
  typed_errors_only([&] { write_feature_tags(again, tags); }, "write_feature_tags");
  Feature_tags back;
  const bool read = typed_errors_only([&] { back = read_feature_tags(again); }, "read_feature_tags (round trip)");
  std::remove(again.c_str());
  require(read && back == tags, "tags round trip");

  // The tags on an octahedron (vertices 0..5, 12 edges): check_mesh flags
  // every tag that is not an edge or a vertex; the others refine.
  Mesh m;
  m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  m.tags = tags;
  Mesh_report report;
  require(typed_errors_only([&] { report = check_mesh(m); }, "check_mesh"), "check_mesh never throws");
  std::size_t bad = 0;
  for (const Edge& e : tags.creases()) {
    const bool is_edge = e.b < 6 && e.a / 2 != e.b / 2;  // a < b; 2k and 2k+1 are opposite
    bad += !is_edge;
  }
  for (Index v : tags.corners()) bad += v >= 6;
  require(report.count(Mesh_defect::invalid_tag) == bad, "check_mesh flags exactly the tags that are not elements");
  Mesh refined;
  Loop_subdivider<Naive_kernel<double>> loop;
  const bool ok = typed_errors_only([&] { refined = loop.refine(m, 2); }, "Loop refinement with tags");
  require(ok == (bad == 0), "Loop refinement accepts exactly the valid tags");
  if (ok) {
    require(refined.tags.creases().size() == 4 * tags.creases().size(), "each crease becomes two, twice");
    require(!check_mesh(refined).has(Mesh_defect::invalid_tag), "refined tags are valid");
  }
}

}  // namespace relgeo::fuzz
