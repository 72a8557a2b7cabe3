// OpenMesh's Subdivider::Uniform::LoopT on a TriMesh with double points.
#include "loop_benchmark.h"

#ifdef RELGEO_HAS_OPENMESH
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <memory>

namespace relgeo_bench {

namespace {
struct Traits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using Om = OpenMesh::TriMesh_ArrayKernelT<Traits>;
}  // namespace

bool have_openmesh() { return true; }

void register_openmesh(const std::vector<Bench_mesh>& meshes) {
  const auto build = [](const Mesh_d& m) {
    Om om;
    for (const auto& p : m.vertices) om.add_vertex(Om::Point(p.x, p.y, p.z));
    for (const auto& f : m.faces) om.add_face(om.vertex_handle(f[0]), om.vertex_handle(f[1]), om.vertex_handle(f[2]));
    return om;
  };
  register_peer(meshes, "OpenMesh", build, [](Om& om, int level) {
    OpenMesh::Subdivider::Uniform::LoopT<Om, double> loop;  // its weight table: microseconds
    loop.attach(om);
    loop(static_cast<std::size_t>(level));
    loop.detach();
    return std::size_t(om.n_faces());
  });
}

}  // namespace relgeo_bench
#else
namespace relgeo_bench {
bool have_openmesh() { return false; }
void register_openmesh(const std::vector<Bench_mesh>&) {}
}  // namespace relgeo_bench
#endif
