// tools/relgeo/commands/boolean/checks.cpp — the checks `relgeo boolean`
// reports on its output (relgeo/mesh: check_mesh, topology, volume).
#include <algorithm>
#include <numeric>

#include "cli/text.h"
#include "commands/boolean/facade.h"
#include "relgeo/boolean.h"
#include "relgeo/mesh/validity.h"

namespace relgeo::tool {

Mesh_checks check_output(const Mesh_double& m, bool self_intersections) {
  Mesh_checks c;
  const Mesh_report report = check_mesh<Filtered_exact_kernel>(m, {.report_isolated_vertices = false});
  c.boundary_edges = report.count(Mesh_defect::boundary_edge);
  c.non_manifold_edges = report.count(Mesh_defect::non_manifold_edge);
  c.non_manifold_vertices = report.count(Mesh_defect::non_manifold_vertex);
  c.degenerate_faces = report.count(Mesh_defect::collinear_face) + report.count(Mesh_defect::repeated_vertex_in_face);
  c.closed = report.is_closed();
  c.manifold = report.is_manifold();
  c.oriented = report.is_consistently_oriented();
  c.no_degenerate_faces = c.degenerate_faces == 0;
  // Euler characteristic and components, from the faces (vertices in no face not counted).
  std::vector<std::pair<Index, Index>> edges;
  std::vector<Index> parent(m.vertices.size());
  std::iota(parent.begin(), parent.end(), Index{0});
  const auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<char> used(m.vertices.size(), 0);
  for (const Triangle& f : m.faces)
    for (int k = 0; k < 3; ++k) {
      edges.push_back(std::minmax(f[k], f[(k + 1) % 3]));
      used[f[k]] = 1;
      parent[find(f[k])] = find(f[(k + 1) % 3]);
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const long v = std::count(used.begin(), used.end(), 1);
  c.euler_characteristic = v - static_cast<long>(edges.size()) + static_cast<long>(m.faces.size());
  for (Index i = 0; i < m.vertices.size(); ++i) c.components += used[i] && find(i) == i;
  double vol = 0;
  for (const Triangle& f : m.faces) {
    const auto &p = m.vertices[f[0]], &q = m.vertices[f[1]], &r = m.vertices[f[2]];
    vol += p.x * (q.y * r.z - q.z * r.y) - p.y * (q.x * r.z - q.z * r.x) + p.z * (q.x * r.y - q.y * r.x);
  }
  c.volume = vol / 6;
  if (self_intersections && c.closed && c.manifold && c.oriented && c.no_degenerate_faces) {
    // relgeo::boolean's operand check, run on the output: Invalid_operand lists the pairs.
    try {
      (void)relgeo::boolean(m, Mesh_double{}, Boolean_operation::union_of);
      c.self_intersecting_pairs = 0;
    } catch (const Invalid_operand& e) {
      c.self_intersecting_pairs = static_cast<std::size_t>(std::count_if(
          e.issues().begin(), e.issues().end(), [](const Mesh_issue& i) { return i.defect == Mesh_defect::self_intersection; }));
    }
  }
  return c;
}

Boolean_operation parse_boolean_operation(const std::string& name) {
  for (Boolean_operation op : {Boolean_operation::union_of, Boolean_operation::intersection, Boolean_operation::difference,
                               Boolean_operation::symmetric_difference})
    if (name == to_string(op)) return op;
  throw Usage_error("--op must be union, intersection, difference or xor (got '" + name + "')");
}

}  // namespace relgeo::tool
