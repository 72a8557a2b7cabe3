// relgeo/joining/occt_sewing.h — OpenCASCADE's way as a peer (SPEC Sec. 6):
// the faces sewn into a shell (BRepBuilderAPI_Sewing) and tessellated
// (BRepMesh_IncrementalMesh). It does not join the given meshes: it throws
// them away and meshes the CAD model anew, conforming along the sewn edges.
// Measured like the other methods (the same certified checks in (u,v), the
// heights of its vertices over the faces), so the comparison tables line up.
//
// Needs relgeo::occt and Eigen (relgeo::eigen, for the measures).
#pragma once

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "relgeo/joining/internal/join_steps.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/surfaces/occt_conversion.h"

namespace relgeo {

/// Options of occt_sewing (lengths relative to the model's size: the
/// diagonal of the input meshes' bounding box).
struct Occt_sewing_options {
  double sewing_tolerance = 1e-3;   ///< BRepBuilderAPI_Sewing's tolerance [1e-3]
  double linear_deflection = 2e-4;  ///< BRepMesh's chordal deflection [2e-4]
  double angular_deflection = 0.3;  ///< radians [0.3]
};

/// \brief Sews the model's faces with OpenCASCADE and tessellates the shell
/// (the input meshes are only measured, as "before").
/// \throws Joining_failure when OpenCASCADE fails; bad input as join_meshes.
template <OrientationKernel_2 K = Filtered_exact_kernel>
Join_result occt_sewing(const Surface_model& model, const std::vector<Triangle_mesh<Point_3<double>>>& meshes,
                        const K& k = K{}, const Occt_sewing_options& options = {}) {
  using namespace internal::join;
  const internal::Stopwatch start;
  Join_result result;
  Join_report& report = result.report;
  report.method = "occt-sewing", report.kernel = K::name();
  if (model.faces.empty() || meshes.size() != model.faces.size())
    throw Joining_input_error("occt_sewing: " + std::to_string(meshes.size()) + " meshes for " +
                              std::to_string(model.faces.size()) + " faces");
  std::vector<Face_state> faces(model.faces.size());
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (std::size_t f = 0; f < faces.size(); ++f) {
    faces[f].face = &model.faces[f];
    prepare_face(faces[f], meshes[f], f, Join_options{}, k);
    for (const auto& p : meshes[f].vertices) {
      const double xyz[3] = {p.x, p.y, p.z};
      for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], xyz[c]), hi[c] = std::max(hi[c], xyz[c]);
    }
  }
  const double scale = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  std::vector<Handle(Geom_Surface)> surfaces;
  TopoDS_Shape sewn;
  internal::Stopwatch t;
  try {
    const TopoDS_Compound compound = shape_from_surface_model(model, &surfaces);
    BRepBuilderAPI_Sewing sewing(options.sewing_tolerance * scale);
    for (TopExp_Explorer x(compound, TopAbs_FACE); x.More(); x.Next()) sewing.Add(x.Current());
    sewing.Perform();
    sewn = sewing.SewedShape();
    report.seconds.push_back({"sewing", t.lap()});
    BRepMesh_IncrementalMesh mesher(sewn, options.linear_deflection * scale, Standard_False, options.angular_deflection,
                                    Standard_True);
    report.seconds.push_back({"meshing", t.lap()});
  } catch (const Standard_Failure& e) {
    throw Joining_failure(std::string("OpenCASCADE: ") + e.GetMessageString());
  }
  // Triangulations per face, merged by identical node coordinates (BRepMesh
  // discretises a shared edge once for both faces).
  t.restart();
  Triangle_mesh<Point_3<double>>& m = result.mesh;
  std::map<std::tuple<double, double, double>, Index> node_index;
  std::vector<Height_field> fields(faces.size());
  std::vector<std::vector<Triangle>> tris(faces.size());
  for (TopExp_Explorer x(sewn, TopAbs_FACE); x.More(); x.Next()) {
    const TopoDS_Face face = TopoDS::Face(x.Current());
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull()) throw Joining_failure("OpenCASCADE left a face without triangulation");
    const Handle(Geom_Surface) gs = BRep_Tool::Surface(face);
    std::size_t f = 0;
    while (f < surfaces.size() && surfaces[f] != gs) ++f;
    if (f == surfaces.size()) throw Joining_failure("OpenCASCADE: a sewn face lost its surface");
    std::vector<Index> global(static_cast<std::size_t>(tri->NbNodes()) + 1);
    std::vector<Index> local(global.size());
    for (int i = 1; i <= tri->NbNodes(); ++i) {
      gp_Pnt p = tri->Node(i);
      if (!loc.IsIdentity()) p.Transform(loc.Transformation());
      auto [it, inserted] = node_index.emplace(std::tuple{p.X(), p.Y(), p.Z()}, static_cast<Index>(m.vertices.size()));
      if (inserted) m.vertices.push_back({p.X(), p.Y(), p.Z()});
      global[i] = it->second;
      // Its height over the face (OCC's parameters as the start).
      const gp_Pnt2d uv = tri->HasUVNodes() ? tri->UVNode(i) : gp_Pnt2d(0, 0);
      const Surface_projection pr = faces[f].projector->project({p.X(), p.Y(), p.Z()},
                                                                tri->HasUVNodes() ? std::optional(Point_2<double>{uv.X(), uv.Y()}) : std::nullopt);
      local[i] = static_cast<Index>(fields[f].uv.size());
      fields[f].uv.push_back(pr.uv), fields[f].height.push_back(pr.height);
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int i = 1; i <= tri->NbTriangles(); ++i) {
      int a, b, c;
      tri->Triangle(i).Get(a, b, c);
      tris[f].push_back({local[a], local[b], local[c]});  // counter-clockwise in (u,v)
      Triangle g{global[a], global[b], global[c]};
      if (reversed) std::swap(g[1], g[2]);
      m.faces.push_back(g);
      result.face_of_triangle.push_back(static_cast<Index>(f));
    }
  }
  report.seconds.push_back({"merge", t.lap()});
  for (std::size_t f = 0; f < faces.size(); ++f) {
    Join_face_report& r = faces[f].report;
    const Patch_errors after = patch_errors(tris[f], fields[f]);
    r.after = r.after_reprojected = {after.absolute_error, after.normal_vector_error};
    const Orientation_report o = uv_orientations<K>(tris[f], fields[f].uv, Certified_sign::positive, k);
    r.orientation_after = {o.positive, o.flipped, o.degenerate, o.undecided};
    const Overlap_report ov = uv_overlaps<K>(tris[f], fields[f].uv, k);
    r.overlaps_after = ov.overlapping.size(), r.overlaps_undecided_after = ov.undecided.size();
    r.output_vertices = fields[f].uv.size(), r.output_triangles = tris[f].size();
    r.guarantees_hold = o.all_positive() && ov.is_embedding();
    report.flipped_triangles += o.flipped;
    report.faces.push_back(r);
  }
  report.vertices = m.vertices.size(), report.triangles = m.faces.size();
  std::vector<Mesh_issue> issues;
  const Mesh_topology topo = Mesh_topology::build_checked(m.vertices.size(), m.faces, issues);
  for (const Mesh_issue& i : issues) {
    report.non_manifold_edges += i.defect == Mesh_defect::non_manifold_edge;
    report.inconsistent_orientations += i.defect == Mesh_defect::inconsistent_orientation;
  }
  // Seams: boundary edges whose two faces' sides both exist are gaps; here,
  // a boundary edge counts as a seam gap when its vertices are used by two
  // faces of the model.
  std::vector<std::set<Index>> faces_of(m.vertices.size());
  for (std::size_t i = 0; i < m.faces.size(); ++i)
    for (Index v : m.faces[i]) faces_of[v].insert(result.face_of_triangle[i]);
  for (Index e = 0; e < topo.number_of_edges(); ++e)
    if (topo.is_boundary_edge(e)) {
      ++report.boundary_edges;
      const Edge ab = topo.edge_vertices(e);
      report.seam_boundary_edges += faces_of[ab.a].size() >= 2 && faces_of[ab.b].size() >= 2;
    }
  report.conforming = report.non_manifold_edges == 0 && report.inconsistent_orientations == 0;
  report.watertight_seams = report.seam_boundary_edges == 0;
  report.guarantees_hold = std::all_of(report.faces.begin(), report.faces.end(), [](const auto& r) { return r.guarantees_hold; });
  report.seconds.push_back({"measures", t.elapsed()});
  report.total_seconds = start.elapsed();
  return result;
}

}  // namespace relgeo
