// relgeo/joining/joiner.h — reliable joining of mesh patches to trimmed
// NURBS faces with the Whitney extension (thesis Sec. 4.3; SPEC Sec. 6).
//
// Input: a surface model (trimmed faces sharing edges) and one mesh patch
// per face approximating it. Output: one conforming triangle mesh whose
// seams along shared edges are watertight, and a report (join_report.h).
//
// Steps (thesis Sec. 4.3.2, with Sec. 4.3.3 where curves are missing):
//  1. project every mesh vertex onto its face: parameters and height;
//  2. the boundary dR of each face: for each edge, its 3D curve sampled at the
//     meshes' spacing (case 1), else the median polyline of the two meshes'
//     boundary chains (case 2), else the mesh's own chain (a free edge), the
//     loops of both deleted; projected onto the face: (u,v) and height e;
//  3. the central mesh: the projected mesh without its peripheral triangles
//     (central_mesh.h);
//  4. the external region between dR and the central mesh triangulated by
//     Ruppert refinement (CGAL Mesh_2, shape bound 0.125: 20.7 degrees); the
//     points it adds on a shared edge are added to the other face's dR too,
//     and both remeshed until the two sides have the same points
//     (conformity rounds);
//  5. reprojection: every vertex not on dR at F(p) + a(p) n(p), a the Whitney
//     extension of the data (dR, e) (whitney_extension.h), vertices on dR at
//     their joint points (one point per joint vertex, shared by the faces);
//  6. merge: central triangles along the central boundary are split at the
//     points Ruppert added there, the faces' pieces glued along the shared
//     joint vertices.
// The result is then measured (errors before and after, certified
// orientation and overlap checks in (u,v) with kernel K, conformity,
// watertightness, angles, time per step).
//
// Needs CGAL (relgeo::cgal) and Eigen (relgeo::eigen).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/joining/compiled_kernels.h"
#include "relgeo/joining/domain_mesher.h"
#include "relgeo/joining/internal/join_steps.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/surfaces/surface_model.h"

namespace relgeo {

namespace internal::join {

// ---- step 4: the external region -------------------------------------------------
/// The key of a point Ruppert added on segment `segment` of dR loop `loop`
/// at parameter t. The position along the edge is rounded to a multiple of
/// 2^-24 of the edge's segment, so that the same point reached from both
/// faces (their segments run opposite ways: the rounding of from + (to -
/// from) t differs) has one key.
inline Point_key steiner_key(const Face_state& s, std::size_t loop, std::size_t segment, double t) {
  const Segment_on_edge& g = s.segments[loop][segment];
  const double pos = g.from + (g.to - g.from) * t;
  Point_key key;
  key.edge = g.edge;
  key.segment = static_cast<std::uint32_t>(std::floor(std::min(g.from, g.to)));
  key.t = std::clamp(std::round((pos - key.segment) * 0x1p24) * 0x1p-24, 0x1p-24, 1 - 0x1p-24);
  return key;
}

/// Triangulates the external region of face s; records the points added on
/// dR (as keys of their edges).
inline void mesh_external_region(Face_state& s, std::vector<Joint>& joints, const Join_options& o) {
  std::vector<std::vector<Point_2<double>>> loops = boundary_polygons(s);
  for (const auto& c : s.central_cycles) {
    loops.emplace_back();
    for (Index v : c) loops.back().push_back(s.input.uv[v]);
  }
  Domain_mesh_options mo = o.external;
  if (mo.max_edge_length <= 0) mo.max_edge_length = 1.5 * s.median_edge_uv;
  try {
    s.external = mesh_domain(loops, mo);
  } catch (const Invalid_input& e) {
    throw Joining_failure(std::string("external region: ") + e.what());
  }
  s.keys_present.clear();
  for (const auto& l : s.boundary)
    for (const auto& p : l) s.keys_present.insert(p.key);
  for (const Domain_vertex& v : s.external.vertices) {
    if (!v.is_on_segment() || static_cast<std::size_t>(v.segment_loop) >= s.boundary.size()) continue;
    const Point_key key = steiner_key(s, static_cast<std::size_t>(v.segment_loop), v.segment, v.t);
    s.keys_present.insert(key);
    joints[static_cast<std::size_t>(key.edge)].extra.insert({key.segment, key.t});
  }
}

// ---- steps 5 and 6: reprojection and merge ----------------------------------------
/// This face's part of the result: local vertices (not on dR) with their
/// parameters, Whitney heights and points; triangles over global indices.
struct Face_output {
  std::vector<Point_2<double>> uv;
  std::vector<double> height;
  std::vector<Point_3<double>> points;
  std::vector<std::array<std::int64_t, 3>> triangles;  ///< >= 0: local vertex; < 0: -(global joint index) - 1
  Height_field field;                                   ///< all vertices used (local then joint), for the measures
  std::vector<Triangle> field_triangles;
};

/// Step 4 over all faces: external regions meshed, and remeshed while a
/// shared edge carries points one of its faces lacks.
inline void conform_external_regions(std::vector<Face_state>& faces, std::vector<Joint>& joints,
                                     const std::map<int, Point_3<double>>& vertex_points, const Join_options& o,
                                     Join_report& report) {
  std::vector<char> needs(faces.size(), 1);
  for (int round = 0;; ++round) {
    if (round == o.max_conformity_rounds)
      throw Joining_failure("the points on shared edges did not agree after " + std::to_string(round) + " rounds");
    for (std::size_t f = 0; f < faces.size(); ++f)
      if (needs[f]) {
        if (round > 0) build_boundary(faces[f], joints, vertex_points);
        mesh_external_region(faces[f], joints, o);
      }
    report.conformity_rounds = static_cast<std::size_t>(round) + 1;
    bool any = false;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      needs[f] = 0;
      for (const auto& row : faces[f].curve_edge)
        for (int e : row)
          for (const auto& [seg, t] : joints[static_cast<std::size_t>(e)].extra)
            if (!faces[f].keys_present.count(Point_key{-1, e, seg, t})) needs[f] = 1;
      any = any || needs[f];
    }
    if (!any) return;
  }
}

/// The joint vertices of the result: one per key (model vertices, joint
/// points), numbered in order of first use.
class Joint_vertices {
 public:
  Joint_vertices(const std::vector<Joint>& joints, const std::map<int, Point_3<double>>& vertex_points)
      : joints_(joints), vertex_points_(vertex_points) {}
  Index id(const Point_key& key) {
    auto [it, inserted] = index_.emplace(key, static_cast<Index>(points_.size()));
    if (inserted) points_.push_back(key_point(joints_, key, vertex_points_)), keys_.push_back(key);
    return it->second;
  }
  const std::vector<Point_3<double>>& points() const { return points_; }
  const Point_key& key(Index v) const { return keys_[v]; }
  std::size_t size() const { return keys_.size(); }

 private:
  const std::vector<Joint>& joints_;
  const std::map<int, Point_3<double>>& vertex_points_;
  std::map<Point_key, Index> index_;
  std::vector<Point_3<double>> points_;
  std::vector<Point_key> keys_;
};

/// Steps 5 and 6 for one face: the Whitney data (dR points of the final
/// external mesh), the local vertices and their heights, the external and
/// (split) central triangles.
inline Face_output reproject_face(Face_state& s, const std::vector<Joint>& joints,
                                  const std::map<int, Point_3<double>>& vertex_points, Joint_vertices& joint_vertices,
                                  const Join_options& o) {
  Face_output out;
  std::vector<Whitney_sample> samples;
  std::vector<std::int64_t> ext_id(s.external.vertices.size(), 0);
  std::map<Index, Index> local_of_input;  // central mesh vertex -> local index
  const auto local_input = [&](Index v) {
    auto [it, inserted] = local_of_input.emplace(v, static_cast<Index>(out.uv.size()));
    if (inserted) out.uv.push_back(s.input.uv[v]);
    return static_cast<std::int64_t>(it->second);
  };
  // Points Ruppert added on central boundary edges (a, b): (t from a, local id).
  std::map<std::pair<Index, Index>, std::vector<std::pair<double, std::int64_t>>> central_splits;
  const std::size_t nb = s.boundary.size();
  for (std::size_t i = 0; i < s.external.vertices.size(); ++i) {
    const Domain_vertex& v = s.external.vertices[i];
    std::optional<Point_key> joint;
    if (v.is_input() && static_cast<std::size_t>(v.loop) < nb)
      joint = s.boundary[static_cast<std::size_t>(v.loop)][v.index].key;
    else if (v.is_on_segment() && static_cast<std::size_t>(v.segment_loop) < nb)
      joint = steiner_key(s, static_cast<std::size_t>(v.segment_loop), v.segment, v.t);
    if (joint) {
      const auto [uv, h] = project_key(s, joints, *joint, vertex_points, v.uv);
      samples.push_back({uv, h});
      ext_id[i] = -static_cast<std::int64_t>(joint_vertices.id(*joint)) - 1;
    } else if (v.is_input()) {  // a central boundary vertex
      ext_id[i] = local_input(s.central_cycles[static_cast<std::size_t>(v.loop) - nb][v.index]);
    } else {
      ext_id[i] = static_cast<std::int64_t>(out.uv.size());
      out.uv.push_back(v.uv);
      if (v.is_on_segment()) {
        const auto& cyc = s.central_cycles[static_cast<std::size_t>(v.segment_loop) - nb];
        central_splits[{cyc[v.segment], cyc[(v.segment + 1) % cyc.size()]}].push_back({v.t, ext_id[i]});
      }
    }
  }
  for (const Triangle& t : s.external.triangles) out.triangles.push_back({ext_id[t[0]], ext_id[t[1]], ext_id[t[2]]});
  for (Index tf = 0; tf < s.triangles.size(); ++tf) {
    if (!s.central.keep[tf]) continue;
    const Triangle& t = s.triangles[tf];
    const std::array<std::int64_t, 3> tri{local_input(t[0]), local_input(t[1]), local_input(t[2])};
    std::array<std::vector<std::int64_t>, 3> on_edge;
    for (int i = 0; i < 3; ++i) {
      // Central cycles run along the kept triangles' own boundary edges.
      const auto it = central_splits.find({t[i], t[(i + 1) % 3]});
      if (it == central_splits.end()) continue;
      auto pts = it->second;
      std::sort(pts.begin(), pts.end());
      for (const auto& [param, id] : pts) on_edge[i].push_back(id);  // from t[i] to t[i+1]
    }
    split_triangle(tri, on_edge, out.triangles);
  }
  Join_face_report& r = s.report;
  r.external_triangles = s.external.triangles.size();
  r.central_triangles = s.central.kept();
  r.removed_triangles = s.triangles.size() - s.central.kept();
  const Whitney_extension w(samples, o.whitney);
  r.boundary_samples = w.samples().size();
  r.boundary_max_abs_height = w.max_abs_height();
  r.lipschitz_constant = w.lipschitz_constant();
  r.data_lipschitz_constant = w.data_lipschitz_constant();
  for (const Whitney_value& v : w.evaluate_all(out.uv)) {
    out.height.push_back(v.height);
    r.max_deviation = std::max(r.max_deviation, v.deviation);
    r.whitney_fallbacks += v.fallback, r.whitney_uncertified += !v.certified;
  }
  for (std::size_t i = 0; i < out.uv.size(); ++i) out.points.push_back(s.projector->lift(out.uv[i], out.height[i]));
  return out;
}

/// The measures of one face's part of the result (file comment).
template <OrientationKernel_2 K>
void measure_face(Face_state& s, const Face_output& out, const std::vector<Joint>& joints,
                  const std::map<int, Point_3<double>>& vertex_points, const Joint_vertices& joint_vertices, const K& k) {
  // The face's height field: local vertices, then its joint vertices.
  Height_field hf{out.uv, out.height};
  std::map<Index, Index> joint_local;
  std::vector<Triangle> tris;
  for (const auto& t : out.triangles) {
    Triangle g;
    for (int i = 0; i < 3; ++i) {
      if (t[i] >= 0) {
        g[i] = static_cast<Index>(t[i]);
        continue;
      }
      const Index j = static_cast<Index>(-t[i] - 1);
      const auto [it, inserted] = joint_local.emplace(j, static_cast<Index>(hf.uv.size()));
      if (inserted) {
        const auto [uv, h] = project_key(s, joints, joint_vertices.key(j), vertex_points, std::nullopt);
        hf.uv.push_back(uv), hf.height.push_back(h);
      }
      g[i] = it->second;
    }
    tris.push_back(g);
  }
  Join_face_report& r = s.report;
  r.output_vertices = hf.uv.size(), r.output_triangles = tris.size();
  const Patch_errors after = patch_errors(tris, hf);
  r.after = {after.absolute_error, after.normal_vector_error};
  double shortest = std::numeric_limits<double>::infinity();
  for (const Triangle& t : tris)
    for (int i = 0; i < 3; ++i) {
      const Point_2<double>&a = hf.uv[t[i]], &b = hf.uv[t[(i + 1) % 3]];
      r.edges_above_lipschitz +=
          slope_upper_bound(a, hf.height[t[i]], b, hf.height[t[(i + 1) % 3]]) > r.lipschitz_constant;
      shortest = std::min(shortest, std::hypot(a.x - b.x, a.y - b.y));
    }
  const Orientation_report o = uv_orientations<K>(tris, hf.uv, Certified_sign::positive, k);
  r.orientation_after = {o.positive, o.flipped, o.degenerate, o.undecided};
  const Overlap_report ov = uv_overlaps<K>(tris, hf.uv, k);
  r.overlaps_after = ov.overlapping.size(), r.overlaps_undecided_after = ov.undecided.size();
  r.min_angle_external = s.external.min_angle_degrees;
  // The result's points projected onto the face again.
  Height_field re;
  for (std::size_t i = 0; i < hf.uv.size(); ++i) {
    const Surface_projection p = s.projector->project(s.projector->lift(hf.uv[i], hf.height[i]), hf.uv[i]);
    re.uv.push_back(p.uv), re.height.push_back(p.height);
  }
  const Patch_errors again = patch_errors(tris, re);
  r.after_reprojected = {again.absolute_error, again.normal_vector_error};
  // A slope above L can only come from the deviation of a^ (G3): at most
  // 2 max_deviation / shortest edge.
  const double slope_allowance = r.lipschitz_constant + 2 * r.max_deviation / shortest;
  r.guarantees_hold = r.after.absolute <= r.boundary_max_abs_height && r.after.normal_vector <= slope_allowance &&
                      r.whitney_uncertified == 0 && o.all_positive() && ov.is_embedding();
}

/// Conformity, seams and angles of the whole result.
inline void measure_mesh(const Triangle_mesh<Point_3<double>>& m, const std::vector<Joint>& joints,
                         const Joint_vertices& joint_vertices, Join_report& report) {
  const Mesh_topology t = measured_topology(m, report);
  // A boundary edge of the result between two joint vertices of one shared
  // edge is a gap in a seam.
  const auto on_edge = [&](Index v, std::size_t j) {
    if (v >= joint_vertices.size()) return false;
    const Point_key& key = joint_vertices.key(v);
    if (key.vertex < 0) return key.edge == static_cast<int>(j);
    return key.vertex == joints[j].start_vertex || key.vertex == joints[j].end_vertex;
  };
  for (Index e = 0; e < t.number_of_edges(); ++e) {
    if (!t.is_boundary_edge(e)) continue;
    ++report.boundary_edges;
    const Edge ab = t.edge_vertices(e);
    bool gap = false;
    for (std::size_t j = 0; j < joints.size() && !gap; ++j)
      gap = joints[j].uses.size() == 2 && on_edge(ab.a, j) && on_edge(ab.b, j) &&
            (joint_vertices.key(ab.a).vertex < 0 || joint_vertices.key(ab.b).vertex < 0 || joints[j].points.size() == 2);
    report.seam_boundary_edges += gap;
  }
  report.conforming = report.non_manifold_edges == 0 && report.inconsistent_orientations == 0 && report.seam_boundary_edges == 0;
  report.watertight_seams = report.seam_boundary_edges == 0;
  report.min_angle_3d = 180;
  const auto angle = [&](Index o, Index p, Index q) {
    const auto &A = m.vertices[o], &B = m.vertices[p], &C = m.vertices[q];
    const double ux = B.x - A.x, uy = B.y - A.y, uz = B.z - A.z, vx = C.x - A.x, vy = C.y - A.y, vz = C.z - A.z;
    const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), ux * vx + uy * vy + uz * vz) * 180 / M_PI;
  };
  for (const Triangle& f : m.faces)
    report.min_angle_3d = std::min({report.min_angle_3d, angle(f[0], f[1], f[2]), angle(f[1], f[2], f[0]), angle(f[2], f[0], f[1])});
}

}  // namespace internal::join

/// \brief Joins the mesh patches `meshes` (one per face of `model`, in
/// order) along the model's edges with the Whitney extension (file comment).
/// \tparam K kernel of the certified checks (point in dR, crossings, loop
/// deletion, orientation and overlap of the result in (u,v)).
/// \throws Joining_input_error, Projection_error, Invalid_mesh,
/// Non_finite_input, Degenerate_surface for bad input; Joining_failure when a
/// step fails (e.g. no central mesh left, conformity rounds exhausted).
template <OrientationKernel_2 K = Filtered_exact_kernel>
Join_result join_meshes(const Surface_model& model, const std::vector<Triangle_mesh<Point_3<double>>>& meshes,
                        const K& k = K{}, const Join_options& options = {}) {
  using namespace internal::join;
  const internal::Stopwatch start;
  Join_result result = started_join_result("join_meshes", "whitney", K::name(), model, meshes.size());
  Join_report& report = result.report;
  const auto step = [&](const char* name, auto&& f) { timed_step(report, name, f); };

  std::vector<Face_state> faces;
  step("projection", [&] { faces = prepare_faces(model, meshes, options, k); });

  std::vector<Joint> joints;
  std::map<int, Point_3<double>> vertex_points;
  step("boundary curves", [&] {
    joints = make_joints(model, faces);
    assign_vertices(faces, joints);
    build_joint_polylines(model, faces, joints, options, report);
    delete_joint_loops(faces, joints, k);
    for (const Joint& J : joints)
      if (!J.uses.empty()) vertex_points[J.start_vertex] = J.points.front(), vertex_points[J.end_vertex] = J.points.back();
    for (Face_state& s : faces) build_boundary(s, joints, vertex_points);
  });

  step("central mesh", [&] {
    for (std::size_t f = 0; f < faces.size(); ++f) {
      Face_state& s = faces[f];
      s.central = central_mesh<K>(s.triangles, s.input.uv, s.topology, boundary_polygons(s), options.central, k);
      if (s.central.kept() == 0)
        throw Joining_failure("face " + std::to_string(f) + ": no central mesh left (the patch is too coarse for its boundary)");
      s.central_cycles = central_cycles(s);
    }
  });

  step("external region", [&] { conform_external_regions(faces, joints, vertex_points, options, report); });

  Joint_vertices joint_vertices(joints, vertex_points);
  std::vector<Face_output> outputs;
  step("whitney reprojection", [&] {
    for (Face_state& s : faces) outputs.push_back(reproject_face(s, joints, vertex_points, joint_vertices, options));
  });

  step("merge", [&] {
    Triangle_mesh<Point_3<double>>& m = result.mesh;
    m.vertices = joint_vertices.points();
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const Index base = static_cast<Index>(m.vertices.size());
      m.vertices.insert(m.vertices.end(), outputs[f].points.begin(), outputs[f].points.end());
      for (const auto& t : outputs[f].triangles) {
        Triangle g;
        for (int i = 0; i < 3; ++i) g[i] = t[i] >= 0 ? base + static_cast<Index>(t[i]) : static_cast<Index>(-t[i] - 1);
        if (model.faces[f].reversed()) std::swap(g[1], g[2]);
        m.faces.push_back(g);
        result.face_of_triangle.push_back(static_cast<Index>(f));
      }
    }
  });

  step("measures", [&] {
    for (std::size_t f = 0; f < faces.size(); ++f) {
      measure_face(faces[f], outputs[f], joints, vertex_points, joint_vertices, k);
      report.flipped_triangles += faces[f].report.orientation_after.flipped;
      report.faces.push_back(faces[f].report);
    }
    measure_mesh(result.mesh, joints, joint_vertices, report);
    report.guarantees_hold = std::all_of(report.faces.begin(), report.faces.end(),
                                         [](const Join_face_report& r) { return r.guarantees_hold; });
  });
  report.total_seconds = start.elapsed();
  return result;
}

// The instances relgeo::compiled makes (src/compiled/joining.cpp).
#define RELGEO_JOIN_MESHES_INSTANCE(PREFIX, K)                                                                          \
  PREFIX Join_result join_meshes<K>(const Surface_model&, const std::vector<Triangle_mesh<Point_3<double>>>&, const K&, \
                          const Join_options&);
#if defined(RELGEO_COMPILED_JOINING) && RELGEO_COMPILED_JOINING
RELGEO_JOINING_COMPILED_KERNELS(RELGEO_JOIN_MESHES_INSTANCE, extern template)
#endif

}  // namespace relgeo
