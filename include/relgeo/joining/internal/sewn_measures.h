// relgeo/joining/internal/sewn_measures.h — what the two sewing peers of the
// joiner (naive_sewing.h, occt_sewing.h) share: a sewn face measured in (u,v)
// like the joiner's faces, and the topology and seams of the whole sewn mesh.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "relgeo/joining/internal/join_steps.h"

namespace relgeo::internal::join {

/// One sewn face, its `triangles` over the (u,v) and heights `h`: errors
/// after, certified orientation and overlaps; appended to the report.
template <class K>
void measure_sewn_face(Face_state& s, const std::vector<Triangle>& triangles, const Height_field& h, Join_report& report,
                       const K& k) {
  Join_face_report& r = s.report;
  const Patch_errors after = patch_errors(triangles, h);
  r.after = r.after_reprojected = {after.absolute_error, after.normal_vector_error};
  const Orientation_report o = uv_orientations<K>(triangles, h.uv, Certified_sign::positive, k);
  r.orientation_after = {o.positive, o.flipped, o.degenerate, o.undecided};
  const Overlap_report ov = uv_overlaps<K>(triangles, h.uv, k);
  r.overlaps_after = ov.overlapping.size(), r.overlaps_undecided_after = ov.undecided.size();
  r.output_vertices = h.uv.size(), r.output_triangles = triangles.size();
  r.guarantees_hold = o.all_positive() && ov.is_embedding();
  report.flipped_triangles += o.flipped;
  report.faces.push_back(r);
}

/// The whole sewn mesh `m`: its size, edge defects, boundary edges and those
/// of them on a seam (`on_seam(a, b)` for the edge's vertices), and the
/// verdicts (after every face was measured).
template <class On_seam>
void measure_sewn_mesh(const Triangle_mesh<Point_3<double>>& m, On_seam&& on_seam, Join_report& report) {
  const Mesh_topology topo = measured_topology(m, report);
  for (Index e = 0; e < topo.number_of_edges(); ++e)
    if (topo.is_boundary_edge(e)) {
      ++report.boundary_edges;
      const Edge ab = topo.edge_vertices(e);
      report.seam_boundary_edges += on_seam(ab.a, ab.b);
    }
  report.conforming = report.non_manifold_edges == 0 && report.inconsistent_orientations == 0;
  report.watertight_seams = report.seam_boundary_edges == 0;
  report.guarantees_hold = std::all_of(report.faces.begin(), report.faces.end(), [](const auto& r) { return r.guarantees_hold; });
}

}  // namespace relgeo::internal::join
