// test/boolean/cgal_data_solids.h — the closed solids of CGAL's data set for
// the Boolean tests that run over real meshes: every .off file of
// RELGEO_CGAL_MESH_DIR (a compile definition of those tests) that reads, is
// a valid closed mesh and bounds a positive volume, in file-name order.
// Unreadable, open, non-manifold and inverted files are skipped: they are
// the subject of the reliability tests, not of these.
#pragma once

#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "boolean_inputs.h"
#include "relgeo/core/errors.h"
#include "relgeo/mesh/mesh_io.h"
#include "relgeo/mesh/validity.h"

namespace relgeo::test {

struct Data_solid {
  std::string name;  ///< file name
  Mesh mesh;
  double size = 0;  ///< largest extent of the bounding box
};

/// Whether the data set is there (the setup script fetches it).
inline bool cgal_data_available() {
  return std::filesystem::exists(std::filesystem::path(RELGEO_CGAL_MESH_DIR) / "elephant.off");
}

/// The solids whose name and face count `wanted` accepts.
inline std::vector<Data_solid> cgal_data_solids(
    const std::function<bool(const std::string& name, std::size_t faces)>& wanted) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(RELGEO_CGAL_MESH_DIR))
    if (e.path().extension() == ".off") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<Data_solid> out;
  for (const auto& file : files) {
    Data_solid s{file.filename().string(), {}, 0};
    try {
      s.mesh = read_mesh(file.string());
    } catch (const Error&) {
      continue;
    }
    if (s.mesh.faces.empty() || !wanted(s.name, s.mesh.faces.size())) continue;
    if (!check_mesh(s.mesh).is_valid() || volume(s.mesh) <= 0) continue;
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (const auto& p : s.mesh.vertices) {
      const double c[3] = {p.x, p.y, p.z};
      for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], c[i]), hi[i] = std::max(hi[i], c[i]);
    }
    s.size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace relgeo::test
