// tools/relgeo/commands/boolean/oracle.cpp — CGAL's corefinement with Epeck
// on the same operands, and how far relgeo's result is from it: the volume of
// their symmetric difference (relgeo's exact Boolean of the two outputs) and
// their symmetric Hausdorff distance (CGAL PMP, sampled). The corefinement
// itself is compiled once for the tests, benchmarks and tool
// (relgeo_fixtures/peers/cgal_corefinement.h).
#include <cmath>

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include "commands/boolean/facade.h"
#include "relgeo/boolean.h"
#include "relgeo/mesh/cgal_conversion.h"
#include "relgeo_fixtures/peers/cgal_corefinement.h"

namespace relgeo::tool {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

template <class K>
CGAL::Surface_mesh<typename K::Point_3> surface(const Mesh_double& m) {
  return to_surface_mesh<typename K::Point_3>(m);
}

Mesh_double doubles(const CGAL::Surface_mesh<CGAL::Epeck::Point_3>& s) {
  Mesh_double m;
  std::vector<Index> id(s.number_of_vertices());
  for (auto v : s.vertices()) {
    id[v.idx()] = static_cast<Index>(m.vertices.size());
    const auto& p = s.point(v);
    m.vertices.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  for (auto f : s.faces()) {
    Triangle t;
    int k = 0;
    for (auto v : s.vertices_around_face(s.halfedge(f))) t[k++] = id[v.idx()];
    m.faces.push_back(t);
  }
  return m;
}

}  // namespace

Oracle_comparison compare_with_cgal(const Mesh_double& a, const Mesh_double& b, Boolean_operation op,
                                    const Mesh_double& result) {
  using Epeck = CGAL::Epeck;
  Oracle_comparison c;
  const auto corefine = [&](Boolean_operation o, CGAL::Surface_mesh<Epeck::Point_3>& out) {
    auto sa = surface<Epeck>(a), sb = surface<Epeck>(b);
    return peers::cgal_corefine_and_compute(sa, sb, o, out);
  };
  Mesh_double cgal;
  if (op == Boolean_operation::symmetric_difference) {  // CGAL has none: (A - B) and (B - A) side by side
    CGAL::Surface_mesh<Epeck::Point_3> ab, ba;
    auto sa = surface<Epeck>(a), sb = surface<Epeck>(b), sa2 = surface<Epeck>(a), sb2 = surface<Epeck>(b);
    c.cgal_ok = peers::cgal_corefine_and_compute(sa, sb, Boolean_operation::difference, ab) &&
                peers::cgal_corefine_and_compute(sb2, sa2, Boolean_operation::difference, ba);
    if (!c.cgal_ok) return c;
    c.cgal_volume = CGAL::to_double(PMP::volume(ab)) + CGAL::to_double(PMP::volume(ba));
    cgal = doubles(ab);
    const Mesh_double second = doubles(ba);
    const Index offset = static_cast<Index>(cgal.vertices.size());
    cgal.vertices.insert(cgal.vertices.end(), second.vertices.begin(), second.vertices.end());
    for (const auto& f : second.faces) cgal.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  } else {
    CGAL::Surface_mesh<Epeck::Point_3> out;
    c.cgal_ok = corefine(op, out);
    if (!c.cgal_ok) return c;
    c.cgal_volume = CGAL::to_double(PMP::volume(out));
    cgal = doubles(out);
  }
  c.cgal_faces = cgal.faces.size();
  if (result.faces.empty()) return c;  // the oracle's figures only
  if (!cgal.faces.empty()) try {
    const auto r = surface<CGAL::Epick>(result), o = surface<CGAL::Epick>(cgal);
    c.hausdorff = PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(
        r, o, CGAL::parameters::number_of_points_per_area_unit(4000), CGAL::parameters::number_of_points_per_area_unit(4000));
  } catch (const Invalid_mesh&) {
    c.hausdorff = std::nan("");  // a non-manifold mesh (two solids sharing an edge): Surface_mesh cannot hold it
  }
  // The volume of the difference between the two solids, by relgeo's exact
  // Boolean (operands not checked: a rounded output may touch itself). A
  // result that is not a manifold (a regularised result pinched at a vertex
  // or along an edge) is no operand: no volume then, as no distance above.
  if (op != Boolean_operation::symmetric_difference) try {
      const auto x = relgeo::boolean(result, cgal, Boolean_operation::symmetric_difference, Filtered_exact_kernel{},
                                     Boolean_options{.check_operands = false, .rounding = Output_rounding::nearest});
      if (x.ok()) {
        double v = 0;
        for (const auto& f : x.mesh.faces) {
          const auto &p = x.mesh.vertices[f[0]], &q = x.mesh.vertices[f[1]], &r = x.mesh.vertices[f[2]];
          v += p.x * (q.y * r.z - q.z * r.y) - p.y * (q.x * r.z - q.z * r.x) + p.z * (q.x * r.y - q.y * r.x);
        }
        c.symmetric_difference_volume = std::abs(v / 6);
      }
    } catch (const Invalid_mesh&) {
    }
  return c;
}

}  // namespace relgeo::tool
