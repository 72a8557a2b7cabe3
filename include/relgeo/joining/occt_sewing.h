// relgeo/joining/occt_sewing.h — OpenCASCADE's way as a peer (SPEC Sec. 6):
// the faces sewn into a shell (BRepBuilderAPI_Sewing) and tessellated
// (BRepMesh_IncrementalMesh). It does not join the given meshes: it throws
// them away and meshes the CAD model anew, conforming along the sewn edges.
// Measured like the other methods (the same certified checks in (u,v), the
// heights of its vertices over the faces), so the comparison tables line up.
//
// Needs relgeo::occt and Eigen (relgeo::eigen, for the measures).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "relgeo/joining/internal/join_steps.h"
#include "relgeo/joining/internal/occt_tessellation.h"
#include "relgeo/joining/internal/sewn_measures.h"
#include "relgeo/joining/occt_sewing_options.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/surfaces/occt_conversion.h"

namespace relgeo {

/// \brief Sews the model's faces with OpenCASCADE and tessellates the shell
/// (the input meshes are only measured, as "before").
/// \throws Joining_failure when OpenCASCADE fails; bad input as join_meshes.
template <OrientationKernel_2 K = Filtered_exact_kernel>
Join_result occt_sewing(const Surface_model& model, const std::vector<Triangle_mesh<Point_3<double>>>& meshes,
                        const K& k = K{}, const Occt_sewing_options& options = {}) {
  using namespace internal::join;
  const internal::Stopwatch start;
  Join_result result = started_join_result("occt_sewing", "occt-sewing", K::name(), model, meshes.size());
  Join_report& report = result.report;
  std::vector<Face_state> faces = prepare_faces(model, meshes, Join_options{}, k);
  const double scale = meshes_diagonal(meshes);
  std::vector<Handle(Geom_Surface)> surfaces;
  const TopoDS_Shape sewn = sew_and_tessellate(model, options.sewing_tolerance * scale, options.linear_deflection * scale,
                                                options.angular_deflection, surfaces, report);
  internal::Stopwatch t;
  const std::vector<Sewn_face_part> parts = Tessellation_merge(faces, surfaces, result).merge(sewn);
  report.seconds.push_back({"merge", t.lap()});
  for (std::size_t f = 0; f < faces.size(); ++f) measure_sewn_face(faces[f], parts[f].triangles, parts[f].field, report, k);
  const std::vector<std::set<Index>> faces_of = model_faces_of_vertices(result);
  measure_sewn_mesh(
      result.mesh, [&](Index a, Index b) { return faces_of[a].size() >= 2 && faces_of[b].size() >= 2; }, report);
  report.seconds.push_back({"measures", t.elapsed()});
  report.total_seconds = start.elapsed();
  return result;
}

}  // namespace relgeo
