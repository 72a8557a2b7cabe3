// relgeo/boolean/internal/control_mapping.h — the polyhedral result of a
// subdivision Boolean carried to the level-k control meshes (thesis Sec.
// 5.3, steps 1-3): each vertex of the result lies on the limit mesh of an
// operand at a known vertex, edge or face; the same place on the control
// mesh (same connectivity) gives its control point. The faces the curves cut
// are split exactly as the Boolean split the limit faces, so cutting and
// merging are the Boolean's own exact retriangulation, and the curves and
// the operands' creases become the result's crease tags.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "relgeo/boolean/boolean_types.h"
#include "relgeo/kernel/vector_3.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

/// One operand at level k: its refined control mesh and its limit mesh
/// (the same faces; the limit mesh's vertices are the control vertices'
/// limit positions).
struct Operand_at_level {
  Triangle_mesh<Point_3<double>> control, limit;
};

inline Point_3<double> lerp(const Point_3<double>& a, const Point_3<double>& b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
}

/// Barycentric coordinates of p (a point of the plane of a, b, c, or near
/// it) in the triangle, clamped to the triangle.
inline std::array<double, 3> barycentric(const Point_3<double>& p, const Point_3<double>& a, const Point_3<double>& b,
                                         const Point_3<double>& c) {
  const Point_3<double> e1 = difference(b, a), e2 = difference(c, a), d = difference(p, a);
  const double a11 = dot(e1, e1), a12 = dot(e1, e2), a22 = dot(e2, e2), r1 = dot(d, e1), r2 = dot(d, e2);
  const double det = a11 * a22 - a12 * a12;
  if (!(det > 0)) return {1, 0, 0};
  double u = (r1 * a22 - r2 * a12) / det, v = (r2 * a11 - r1 * a12) / det;
  u = std::max(u, 0.0), v = std::max(v, 0.0);
  if (u + v > 1) {
    const double s = u + v;
    u /= s, v /= s;
  }
  return {1 - u - v, u, v};
}

/// The control point of point p located at `l` on the operand's limit mesh.
inline Point_3<double> map_to_control(const Operand_at_level& o, const Surface_location& l, const Point_3<double>& p) {
  using Kind = Surface_location::Kind;
  switch (l.kind) {
    case Kind::vertex: return o.control.vertices[l.vertices[0]];
    case Kind::edge: {
      const Point_3<double>& a = o.limit.vertices[l.vertices[0]];
      const Point_3<double>& b = o.limit.vertices[l.vertices[1]];
      const double e[3] = {b.x - a.x, b.y - a.y, b.z - a.z};
      const double ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
      const double t = ee > 0 ? std::clamp(((p.x - a.x) * e[0] + (p.y - a.y) * e[1] + (p.z - a.z) * e[2]) / ee, 0.0, 1.0) : 0.0;
      return lerp(o.control.vertices[l.vertices[0]], o.control.vertices[l.vertices[1]], t);
    }
    case Kind::face: {
      const Triangle& t = o.limit.faces[l.face];
      const auto w = barycentric(p, o.limit.vertices[t[0]], o.limit.vertices[t[1]], o.limit.vertices[t[2]]);
      const Point_3<double>&a = o.control.vertices[t[0]], &b = o.control.vertices[t[1]], &c = o.control.vertices[t[2]];
      return {w[0] * a.x + w[1] * b.x + w[2] * c.x, w[0] * a.y + w[1] * b.y + w[2] * c.y, w[0] * a.z + w[1] * b.z + w[2] * c.z};
    }
    case Kind::none: break;
  }
  return p;
}

/// The operand edge (ends in the operand's numbering) that contains both
/// located points, or nothing: two vertices of a face, a vertex and a point
/// of an edge at it, or two points of one edge.
inline std::optional<Edge> common_operand_edge(const Surface_location& a, const Surface_location& b) {
  using Kind = Surface_location::Kind;
  const auto edge_of = [](const Surface_location& l) { return Edge::of(l.vertices[0], l.vertices[1]); };
  if (a.kind == Kind::vertex && b.kind == Kind::vertex && a.vertices[0] != b.vertices[0])
    return Edge::of(a.vertices[0], b.vertices[0]);
  if (a.kind == Kind::vertex && b.kind == Kind::edge && (b.vertices[0] == a.vertices[0] || b.vertices[1] == a.vertices[0]))
    return edge_of(b);
  if (a.kind == Kind::edge && b.kind == Kind::vertex) return common_operand_edge(b, a);
  if (a.kind == Kind::edge && b.kind == Kind::edge && edge_of(a) == edge_of(b)) return edge_of(a);
  return std::nullopt;
}

/// The subdivision result's control mesh: the polyhedral result's faces, each
/// vertex at its control point (the mean of the two operands' points on the
/// curves: the merge), the curves and the operands' creases and corners
/// tagged. `curve` receives the vertices on the curves.
inline Triangle_mesh<Point_3<double>> merged_control_mesh(const Triangle_mesh<Point_3<double>>& polyhedral,
                                                          const std::vector<Face_origin>& provenance,
                                                          const std::vector<std::array<Surface_location, 2>>& where,
                                                          const std::array<const Operand_at_level*, 2>& operands,
                                                          std::vector<Index>& curve) {
  Triangle_mesh<Point_3<double>> out;
  out.faces = polyhedral.faces;
  out.vertices.resize(polyhedral.vertices.size());
  std::vector<Index> corners;
  for (Index v = 0; v < polyhedral.vertices.size(); ++v) {
    Point_3<double> sum{0, 0, 0};
    int n = 0;
    for (int m = 0; m < 2; ++m) {
      const Surface_location& l = where[v][m];
      if (l.kind == Surface_location::Kind::none) continue;
      const Point_3<double> c = map_to_control(*operands[m], l, polyhedral.vertices[v]);
      sum = {sum.x + c.x, sum.y + c.y, sum.z + c.z};
      ++n;
      if (l.kind == Surface_location::Kind::vertex && operands[m]->control.tags.is_corner(l.vertices[0])) corners.push_back(v);
    }
    out.vertices[v] = n == 0 ? polyhedral.vertices[v] : Point_3<double>{sum.x / n, sum.y / n, sum.z / n};
  }
  std::vector<Edge> creases(polyhedral.tags.creases().begin(), polyhedral.tags.creases().end());
  for (const Edge& e : creases) curve.push_back(e.a), curve.push_back(e.b);
  std::sort(curve.begin(), curve.end());
  curve.erase(std::unique(curve.begin(), curve.end()), curve.end());
  for (std::size_t f = 0; f < out.faces.size(); ++f) {
    const int m = provenance[f].operand;
    const Feature_tags& tags = operands[m]->control.tags;
    if (tags.creases().empty()) continue;
    for (int k = 0; k < 3; ++k) {
      const Index u = out.faces[f][k], w = out.faces[f][(k + 1) % 3];
      const auto e = common_operand_edge(where[u][m], where[w][m]);
      if (e && tags.is_crease(e->a, e->b)) creases.push_back(Edge::of(u, w));
    }
  }
  out.tags.set_creases(std::move(creases));
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  out.tags.set_corners(std::move(corners));
  return out;
}

/// Level-k control faces of operand m that the curves cross badly (thesis
/// Sec. 5.3: through the boundary more than twice, twice through one edge,
/// or never while passing inside).
inline std::size_t count_bad_faces(const Operand_at_level& o, int m, const std::vector<Index>& curve,
                                   const std::vector<std::array<Surface_location, 2>>& where) {
  using Kind = Surface_location::Kind;
  const Mesh_topology t = Mesh_topology::build(o.control);
  struct Crossings {
    std::array<int, 3> per_side{};
    int inside = 0;
  };
  std::vector<Crossings> faces(o.control.faces.size());
  for (Index v : curve) {
    const Surface_location& l = where[v][m];
    if (l.kind == Kind::face) ++faces[l.face].inside;
    if (l.kind != Kind::edge) continue;
    const Index h = t.find_halfedge(l.vertices[0], l.vertices[1]);
    const Index g = t.find_halfedge(l.vertices[1], l.vertices[0]);
    for (Index x : {h, g})
      if (x != invalid_index) ++faces[Mesh_topology::face(x)].per_side[x % 3];
  }
  std::size_t bad = 0;
  for (const Crossings& c : faces) {
    const int total = c.per_side[0] + c.per_side[1] + c.per_side[2];
    const bool twice_one_side = total == 2 && std::max({c.per_side[0], c.per_side[1], c.per_side[2]}) == 2;
    if (total > 2 || twice_one_side || (total == 0 && c.inside > 0)) ++bad;
  }
  return bad;
}

}  // namespace relgeo::internal
