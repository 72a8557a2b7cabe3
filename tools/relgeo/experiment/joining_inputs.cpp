// tools/relgeo/experiment/joining_inputs.cpp
#include "experiment/joining_inputs.h"

#include "relgeo/mesh/mesh_io.h"
#include "relgeo/surfaces/surface_json.h"
#include "relgeo_fixtures/joining/test_models.h"

namespace relgeo::tool {

std::vector<Joining_input> write_joining_inputs(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  struct Made {
    Joining_case c;
    std::string summary;
  };
  std::vector<Made> cases;
  cases.push_back({folding_case(),
                   "the folding configuration of thesis Figs. 4.2/4.7: two planes, a strip of thin triangles "
                   "along patch 0's edge, patch 1 overlapping by 0.02 (case 2)"});
  cases.back().c.name = "folding";
  cases.push_back({make_joining_case("two-faces-curve", two_face_model(true)),
                   "two bicubic faces within 2e-3 along a wavy edge with its 3D curve (case 1), noisy meshes"});
  cases.push_back({make_joining_case("three-faces-median", three_face_model(false)),
                   "three faces meeting at a point, no edge curves (case 2: median polylines), noisy meshes"});
  cases.push_back({make_joining_case("cylinder-plane", cylinder_and_plane_model(true)),
                   "a rational quarter cylinder and its tangent plane, exact edge curve (case 1), noisy meshes"});
  std::vector<Joining_input> out;
  for (const Made& m : cases) {
    Joining_input in{m.c.name, m.summary, (dir / (m.c.name + ".json")).string(), {}};
    write_surface_model_json(m.c.model, in.surface);
    for (std::size_t f = 0; f < m.c.meshes.size(); ++f) {
      in.meshes.push_back((dir / (m.c.name + "_" + std::to_string(f) + ".off")).string());
      write_mesh(in.meshes.back(), m.c.meshes[f]);
    }
    out.push_back(std::move(in));
  }
  return out;
}

}  // namespace relgeo::tool
