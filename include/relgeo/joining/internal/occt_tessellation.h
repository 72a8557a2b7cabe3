// relgeo/joining/internal/occt_tessellation.h — the OpenCASCADE steps of
// occt_sewing.h: the model's faces sewn and tessellated, the tessellation
// merged into one mesh and carried back to the model's faces.
//
// Needs relgeo::occt.
#pragma once

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "relgeo/joining/internal/join_steps.h"
#include "relgeo/surfaces/occt_conversion.h"

namespace relgeo::internal::join {

/// The diagonal of the input meshes' bounding box: occt_sewing's unit of
/// length.
inline double meshes_diagonal(const std::vector<Triangle_mesh<Point_3<double>>>& meshes) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const auto& mesh : meshes)
    for (const auto& p : mesh.vertices) {
      const double xyz[3] = {p.x, p.y, p.z};
      for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], xyz[c]), hi[c] = std::max(hi[c], xyz[c]);
    }
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

/// The model's faces sewn into a shell and tessellated (lengths absolute;
/// times in the report); `surfaces` receives the surface of each model face.
/// \throws Joining_failure when OpenCASCADE fails.
inline TopoDS_Shape sew_and_tessellate(const Surface_model& model, double sewing_tolerance, double linear_deflection,
                                       double angular_deflection, std::vector<Handle(Geom_Surface)>& surfaces,
                                       Join_report& report) {
  TopoDS_Shape sewn;
  internal::Stopwatch t;
  try {
    const TopoDS_Compound compound = shape_from_surface_model(model, &surfaces);
    BRepBuilderAPI_Sewing sewing(sewing_tolerance);
    for (TopExp_Explorer x(compound, TopAbs_FACE); x.More(); x.Next()) sewing.Add(x.Current());
    sewing.Perform();
    sewn = sewing.SewedShape();
    report.seconds.push_back({"sewing", t.lap()});
    BRepMesh_IncrementalMesh mesher(sewn, linear_deflection, Standard_False, angular_deflection, Standard_True);
    report.seconds.push_back({"meshing", t.lap()});
  } catch (const Standard_Failure& e) {
    throw Joining_failure(std::string("OpenCASCADE: ") + e.GetMessageString());
  }
  return sewn;
}

/// One model face's part of the tessellation: its triangles over the (u,v)
/// (counter-clockwise) and the heights of their nodes over the face.
struct Sewn_face_part {
  Height_field field;
  std::vector<Triangle> triangles;
};

/// The tessellation of the sewn shell merged into `result`'s mesh by
/// identical node coordinates (BRepMesh discretises a shared edge once for
/// both faces), each face's part carried back to its model face.
class Tessellation_merge {
 public:
  Tessellation_merge(std::vector<Face_state>& faces, const std::vector<Handle(Geom_Surface)>& surfaces, Join_result& result)
      : faces_(faces), surfaces_(surfaces), result_(result), parts_(faces.size()) {}

  std::vector<Sewn_face_part> merge(const TopoDS_Shape& sewn) && {
    for (TopExp_Explorer x(sewn, TopAbs_FACE); x.More(); x.Next()) add_face(TopoDS::Face(x.Current()));
    return std::move(parts_);
  }

 private:
  /// The model face whose surface the sewn face kept.
  std::size_t model_face(const TopoDS_Face& face) const {
    const Handle(Geom_Surface) gs = BRep_Tool::Surface(face);
    std::size_t f = 0;
    while (f < surfaces_.size() && surfaces_[f] != gs) ++f;
    if (f == surfaces_.size()) throw Joining_failure("OpenCASCADE: a sewn face lost its surface");
    return f;
  }

  void add_face(const TopoDS_Face& face) {
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull()) throw Joining_failure("OpenCASCADE left a face without triangulation");
    const std::size_t f = model_face(face);
    Triangle_mesh<Point_3<double>>& m = result_.mesh;
    std::vector<Index> global(static_cast<std::size_t>(tri->NbNodes()) + 1);
    std::vector<Index> local(global.size());
    for (int i = 1; i <= tri->NbNodes(); ++i) {
      gp_Pnt p = tri->Node(i);
      if (!loc.IsIdentity()) p.Transform(loc.Transformation());
      auto [it, inserted] = node_index_.emplace(std::tuple{p.X(), p.Y(), p.Z()}, static_cast<Index>(m.vertices.size()));
      if (inserted) m.vertices.push_back({p.X(), p.Y(), p.Z()});
      global[i] = it->second;
      // Its height over the face (OCC's parameters as the start).
      const gp_Pnt2d uv = tri->HasUVNodes() ? tri->UVNode(i) : gp_Pnt2d(0, 0);
      const Surface_projection pr = faces_[f].projector->project({p.X(), p.Y(), p.Z()},
                                                                 tri->HasUVNodes() ? std::optional(Point_2<double>{uv.X(), uv.Y()}) : std::nullopt);
      Height_field& field = parts_[f].field;
      local[i] = static_cast<Index>(field.uv.size());
      field.uv.push_back(pr.uv), field.height.push_back(pr.height);
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int i = 1; i <= tri->NbTriangles(); ++i) {
      int a, b, c;
      tri->Triangle(i).Get(a, b, c);
      parts_[f].triangles.push_back({local[a], local[b], local[c]});  // counter-clockwise in (u,v)
      Triangle g{global[a], global[b], global[c]};
      if (reversed) std::swap(g[1], g[2]);
      m.faces.push_back(g);
      result_.face_of_triangle.push_back(static_cast<Index>(f));
    }
  }

  std::vector<Face_state>& faces_;
  const std::vector<Handle(Geom_Surface)>& surfaces_;
  Join_result& result_;
  std::vector<Sewn_face_part> parts_;
  std::map<std::tuple<double, double, double>, Index> node_index_;
};

/// The model faces around each vertex of the merged mesh. Seams: boundary
/// edges whose two faces' sides both exist are gaps; here, a boundary edge
/// counts as a seam gap when its vertices are used by two faces of the model.
inline std::vector<std::set<Index>> model_faces_of_vertices(const Join_result& result) {
  const Triangle_mesh<Point_3<double>>& m = result.mesh;
  std::vector<std::set<Index>> faces_of(m.vertices.size());
  for (std::size_t i = 0; i < m.faces.size(); ++i)
    for (Index v : m.faces[i]) faces_of[v].insert(result.face_of_triangle[i]);
  return faces_of;
}

}  // namespace relgeo::internal::join
