// relgeo/joining/naive_sewing.h — the baseline of thesis Sec. 4.1: sewing two
// mesh patches by moving both boundary chains onto the midpoints of pairs of
// points obtained by linear interpolation along them (normalised arc
// length), inserting the other side's points into each chain. It conforms
// and closes the seam, but knows nothing of normals: a boundary vertex can be
// moved past its neighbours, and triangles flip ("folding", thesis Fig. 4.2,
// 4.8). The result is measured like the Whitney joiner's, with the same
// certified checks, so the two can be compared on the same inputs.
//
// No CGAL needed (Eigen for the projection: relgeo::eigen).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/joining/compiled_kernels.h"
#include "relgeo/joining/internal/join_steps.h"
#include "relgeo/joining/internal/sewn_measures.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/filtered_exact_kernel.h"

namespace relgeo {

namespace internal::join {

/// Normalised arc-length parameters of a 3D chain.
inline std::vector<double> arc_parameters(const std::vector<Point_3<double>>& p) {
  std::vector<double> s{0};
  for (std::size_t i = 1; i < p.size(); ++i) s.push_back(s.back() + internal::distance_3(p[i], p[i - 1]));
  const double total = s.back();
  if (!(total > 0)) throw Joining_input_error("naive sewing: a boundary chain of zero length");
  for (double& x : s) x /= total;
  s.back() = 1;
  return s;
}

inline Point_3<double> point_at(const std::vector<Point_3<double>>& p, const std::vector<double>& s, double t) {
  std::size_t i = static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), t) - s.begin());
  i = std::clamp<std::size_t>(i, 1, s.size() - 1);
  const double w = s[i] > s[i - 1] ? (t - s[i - 1]) / (s[i] - s[i - 1]) : 0.0;
  return lerp(p[i - 1], p[i], w);
}

/// One face's part of a sewing: its vertices' new positions (chain vertices
/// moved to midpoints, inserted points appended), the points inserted on its
/// boundary edges, and the seam key of every seam vertex ((joint, s); a
/// model vertex as (-1, vertex)).
struct Sewing_edit {
  std::vector<Point_3<double>> points;
  std::map<std::pair<Index, Index>, std::vector<std::pair<double, std::size_t>>> inserts;  // (a, b) -> (w, new vertex)
  std::map<Index, std::pair<int, double>> seam_key;
};

/// Moves both chains of every shared edge onto the midpoints of pairs of
/// points at equal normalised arc length, inserting the other side's points;
/// corners shared by several edges go to the mean of their midpoints.
inline std::vector<Sewing_edit> sew_shared_edges(const std::vector<Face_state>& faces, const std::vector<Joint>& joints,
                                                 const Surface_model& model, Join_report& report) {
  std::vector<Sewing_edit> edits(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) edits[f].points = faces[f].points;
  std::map<int, std::pair<Point_3<double>, int>> corner_sum;  // model vertex -> (sum, count)
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const Joint& J = joints[j];
    if (J.uses.size() != 2) continue;
    ++report.edges_with_median;
    std::vector<Index> ids[2];
    std::vector<Point_3<double>> pts[2];
    std::vector<double> par[2];
    for (int side = 0; side < 2; ++side) {
      const Edge_use& u = J.uses[static_cast<std::size_t>(side)];
      const Trim_curve& c = Surface_model::loop(*faces[u.face].face, u.loop).curves[u.curve];
      ids[side] = faces[u.face].chains[u.loop][u.curve].vertices;
      if (c.reversed) std::reverse(ids[side].begin(), ids[side].end());
      for (Index i : ids[side]) pts[side].push_back(faces[u.face].points[i]);
      par[side] = arc_parameters(pts[side]);
    }
    (void)model;
    std::vector<double> all;
    std::merge(par[0].begin(), par[0].end(), par[1].begin(), par[1].end(), std::back_inserter(all));
    all.erase(std::unique(all.begin(), all.end()), all.end());
    const auto midpoint = [&](double s) {
      const Point_3<double> a = point_at(pts[0], par[0], s), b = point_at(pts[1], par[1], s);
      return Point_3<double>{0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.z + b.z)};
    };
    for (const auto& [v, s] : {std::pair{J.start_vertex, 0.0}, std::pair{J.end_vertex, 1.0}}) {
      auto& [sum, n] = corner_sum[v];
      const Point_3<double> m = midpoint(s);
      sum = {sum.x + m.x, sum.y + m.y, sum.z + m.z}, ++n;
    }
    for (int side = 0; side < 2; ++side) {
      Sewing_edit& E = edits[J.uses[static_cast<std::size_t>(side)].face];
      const std::vector<Index>& v = ids[side];
      const std::vector<double>& s = par[side];
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (i == 0) E.seam_key[v[i]] = {-1, J.start_vertex};
        else if (i + 1 == v.size()) E.seam_key[v[i]] = {-1, J.end_vertex};
        else E.seam_key[v[i]] = {static_cast<int>(j), s[i]}, E.points[v[i]] = midpoint(s[i]);
      }
      for (double x : all) {  // the other side's parameters, on this chain's segments
        const auto it = std::lower_bound(s.begin(), s.end(), x);
        if (it != s.end() && *it == x) continue;
        const std::size_t i = static_cast<std::size_t>(it - s.begin());  // between v[i-1] and v[i]
        E.inserts[{v[i - 1], v[i]}].push_back({(x - s[i - 1]) / (s[i] - s[i - 1]), E.points.size()});
        E.seam_key[static_cast<Index>(E.points.size())] = {static_cast<int>(j), x};
        E.points.push_back(midpoint(x));
      }
    }
  }
  for (Sewing_edit& E : edits)
    for (const auto& [v, key] : E.seam_key)
      if (key.first < 0) {
        const auto& [sum, n] = corner_sum[static_cast<int>(key.second)];
        if (n > 0) E.points[v] = {sum.x / n, sum.y / n, sum.z / n};
      }
  return edits;
}

/// Glues the sewn faces: seam vertices by key, the others per face; boundary
/// triangles split at the inserted points. Returns each face's triangles
/// over its own (edited) vertex numbering, and the seam vertices' global ids.
inline std::vector<std::vector<Triangle>> merge_sewn_faces(const std::vector<Face_state>& faces,
                                                           const std::vector<Sewing_edit>& edits, const Surface_model& model,
                                                           Join_result& result, std::set<Index>& seam_vertices) {
  Triangle_mesh<Point_3<double>>& m = result.mesh;
  std::map<std::pair<int, double>, Index> global;
  std::vector<std::vector<Triangle>> face_triangles(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Sewing_edit& E = edits[f];
    std::vector<Index> g(E.points.size());
    for (Index v = 0; v < E.points.size(); ++v) {
      const auto it = E.seam_key.find(v);
      if (it == E.seam_key.end()) {
        g[v] = static_cast<Index>(m.vertices.size()), m.vertices.push_back(E.points[v]);
        continue;
      }
      const auto [gi, inserted] = global.emplace(it->second, static_cast<Index>(m.vertices.size()));
      if (inserted) m.vertices.push_back(E.points[v]);
      g[v] = gi->second;
      seam_vertices.insert(gi->second);
    }
    for (const Triangle& tr : faces[f].triangles) {
      std::array<std::vector<std::int64_t>, 3> on_edge;
      for (int i = 0; i < 3; ++i) {
        auto it = E.inserts.find({tr[i], tr[(i + 1) % 3]});
        const bool forward = it != E.inserts.end();
        if (!forward) it = E.inserts.find({tr[(i + 1) % 3], tr[i]});
        if (it == E.inserts.end()) continue;
        auto list = it->second;
        std::sort(list.begin(), list.end());
        if (!forward) std::reverse(list.begin(), list.end());
        for (const auto& [w, id] : list) on_edge[i].push_back(static_cast<std::int64_t>(id));
      }
      std::vector<std::array<std::int64_t, 3>> pieces;
      split_triangle({tr[0], tr[1], tr[2]}, on_edge, pieces);
      for (const auto& p : pieces) face_triangles[f].push_back({static_cast<Index>(p[0]), static_cast<Index>(p[1]), static_cast<Index>(p[2])});
    }
    for (const Triangle& tr : face_triangles[f]) {
      Triangle gt{g[tr[0]], g[tr[1]], g[tr[2]]};
      if (model.faces[f].reversed()) std::swap(gt[1], gt[2]);
      m.faces.push_back(gt);
      result.face_of_triangle.push_back(static_cast<Index>(f));
    }
  }
  return face_triangles;
}

/// The sewn faces measured like the joiner's (projected again onto their
/// faces; certified orientation and overlaps), and the whole mesh.
template <OrientationKernel_2 K>
void measure_sewn(std::vector<Face_state>& faces, const std::vector<Sewing_edit>& edits,
                  const std::vector<std::vector<Triangle>>& face_triangles, const std::set<Index>& seam_vertices,
                  Join_result& result, const K& k) {
  Join_report& report = result.report;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    Face_state& s = faces[f];
    Height_field h;
    for (Index v = 0; v < edits[f].points.size(); ++v) {
      const std::optional<Point_2<double>> hint = v < s.input.uv.size() ? std::optional(s.input.uv[v]) : std::nullopt;
      const Surface_projection p = s.projector->project(edits[f].points[v], hint);
      h.uv.push_back(p.uv), h.height.push_back(p.height);
    }
    s.report.central_triangles = s.triangles.size();
    measure_sewn_face(s, face_triangles[f], h, report, k);
  }
  measure_sewn_mesh(
      result.mesh, [&](Index a, Index b) { return seam_vertices.count(a) && seam_vertices.count(b); }, report);
}

}  // namespace internal::join

/// \brief Naive midpoint sewing of the mesh patches along the model's
/// shared edges (thesis Sec. 4.1); free edges are left as they are.
/// \throws as join_meshes for bad input.
template <OrientationKernel_2 K = Filtered_exact_kernel>
Join_result naive_sewing(const Surface_model& model, const std::vector<Triangle_mesh<Point_3<double>>>& meshes,
                         const K& k = K{}, const Join_options& options = {}) {
  using namespace internal::join;
  const internal::Stopwatch start;
  Join_result result = started_join_result("naive_sewing", "naive-midpoint", K::name(), model, meshes.size());
  Join_report& report = result.report;
  const auto step = [&](const char* name, auto&& f) { timed_step(report, name, f); };
  std::vector<Face_state> faces;
  step("projection", [&] { faces = prepare_faces(model, meshes, options, k); });
  std::vector<Sewing_edit> edits;
  step("sewing", [&] {
    std::vector<Joint> joints = make_joints(model, faces);
    assign_vertices(faces, joints);
    edits = sew_shared_edges(faces, joints, model, report);
  });
  std::vector<std::vector<Triangle>> face_triangles;
  std::set<Index> seam_vertices;
  step("merge", [&] { face_triangles = merge_sewn_faces(faces, edits, model, result, seam_vertices); });
  step("measures", [&] { measure_sewn(faces, edits, face_triangles, seam_vertices, result, k); });
  report.total_seconds = start.elapsed();
  return result;
}

// The instances relgeo::compiled makes (src/compiled/joining.cpp).
#define RELGEO_NAIVE_SEWING_INSTANCE(PREFIX, K)                                                                          \
  PREFIX Join_result naive_sewing<K>(const Surface_model&, const std::vector<Triangle_mesh<Point_3<double>>>&, const K&, \
                          const Join_options&);
#if defined(RELGEO_COMPILED_JOINING) && RELGEO_COMPILED_JOINING
RELGEO_JOINING_COMPILED_KERNELS(RELGEO_NAIVE_SEWING_INSTANCE, extern template)
#endif

}  // namespace relgeo
