// relgeo/surfaces/occt_conversion.h — relgeo's NURBS curves, surfaces and
// surface models to and from OpenCASCADE (link relgeo::occt).
//
// OpenCASCADE keeps knots with multiplicities and 1-based arrays; relgeo a
// flat knot vector and 0-based arrays. Shapes are converted to NURBS first
// (BRepBuilderAPI_NurbsConvert), which also rewrites the p-curves so that
// they stay consistent with the converted surfaces (a cylinder's angle is not
// the parameter of its rational B-spline). Periodic splines are made
// non-periodic (same parametrisation).
#pragma once

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <ShapeFix_Face.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/surfaces/nurbs_curve.h"
#include "relgeo/surfaces/nurbs_surface.h"
#include "relgeo/surfaces/surface_model.h"
#include "relgeo/surfaces/trimmed_surface.h"

namespace relgeo {

namespace internal {

// Flat knot vector from OCC's distinct knots and multiplicities.
inline std::vector<double> flat_knots(const TColStd_Array1OfReal& knots, const TColStd_Array1OfInteger& mults) {
  std::vector<double> flat;
  for (int i = knots.Lower(); i <= knots.Upper(); ++i)
    for (int m = 0; m < mults(i); ++m) flat.push_back(knots(i));
  return flat;
}
// Distinct knots and multiplicities from a flat knot vector.
inline std::pair<TColStd_Array1OfReal, TColStd_Array1OfInteger> occt_knots(const std::vector<double>& flat) {
  std::vector<double> k;
  std::vector<int> m;
  for (double x : flat) {
    if (!k.empty() && k.back() == x) ++m.back();
    else k.push_back(x), m.push_back(1);
  }
  TColStd_Array1OfReal knots(1, static_cast<int>(k.size()));
  TColStd_Array1OfInteger mults(1, static_cast<int>(k.size()));
  for (std::size_t i = 0; i < k.size(); ++i) knots(static_cast<int>(i) + 1) = k[i], mults(static_cast<int>(i) + 1) = m[i];
  return {knots, mults};
}

}  // namespace internal

/// A relgeo surface from an OpenCASCADE B-spline surface (made non-periodic first).
inline Nurbs_surface<double> nurbs_surface_from_occt(const Handle(Geom_BSplineSurface) & input) {
  Handle(Geom_BSplineSurface) s = Handle(Geom_BSplineSurface)::DownCast(input->Copy());
  if (s->IsUPeriodic()) s->SetUNotPeriodic();
  if (s->IsVPeriodic()) s->SetVNotPeriodic();
  const int nu = s->NbUPoles(), nv = s->NbVPoles();
  std::vector<Point_3<double>> pts;
  std::vector<double> w;
  const bool rational = s->IsURational() || s->IsVRational();
  for (int i = 1; i <= nu; ++i)
    for (int j = 1; j <= nv; ++j) {
      const gp_Pnt p = s->Pole(i, j);
      pts.push_back({p.X(), p.Y(), p.Z()});
      if (rational) w.push_back(s->Weight(i, j));
    }
  TColStd_Array1OfReal ku(1, s->NbUKnots()), kv(1, s->NbVKnots());
  TColStd_Array1OfInteger mu(1, s->NbUKnots()), mv(1, s->NbVKnots());
  s->UKnots(ku), s->VKnots(kv), s->UMultiplicities(mu), s->VMultiplicities(mv);
  return Nurbs_surface<double>(s->UDegree(), s->VDegree(), internal::flat_knots(ku, mu), internal::flat_knots(kv, mv),
                               static_cast<std::size_t>(nu), static_cast<std::size_t>(nv), std::move(pts),
                               std::move(w));
}

/// An OpenCASCADE B-spline surface from a relgeo surface.
inline Handle(Geom_BSplineSurface) to_occt(const Nurbs_surface<double>& s) {
  const int nu = static_cast<int>(s.count_u()), nv = static_cast<int>(s.count_v());
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  TColStd_Array2OfReal weights(1, nu, 1, nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const auto& p = s.control_point(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
      poles(i + 1, j + 1) = gp_Pnt(p.x, p.y, p.z);
      weights(i + 1, j + 1) = s.is_rational() ? s.weights()[static_cast<std::size_t>(i * nv + j)] : 1.0;
    }
  const auto [ku, mu] = internal::occt_knots(s.knots_u());
  const auto [kv, mv] = internal::occt_knots(s.knots_v());
  if (s.is_rational()) return new Geom_BSplineSurface(poles, weights, ku, kv, mu, mv, s.degree_u(), s.degree_v());
  return new Geom_BSplineSurface(poles, ku, kv, mu, mv, s.degree_u(), s.degree_v());
}

/// A relgeo space curve from an OpenCASCADE B-spline curve.
inline Nurbs_curve_3<double> nurbs_curve_from_occt(const Handle(Geom_BSplineCurve) & input) {
  Handle(Geom_BSplineCurve) c = Handle(Geom_BSplineCurve)::DownCast(input->Copy());
  if (c->IsPeriodic()) c->SetNotPeriodic();
  std::vector<Point_3<double>> pts;
  std::vector<double> w;
  for (int i = 1; i <= c->NbPoles(); ++i) {
    const gp_Pnt p = c->Pole(i);
    pts.push_back({p.X(), p.Y(), p.Z()});
    if (c->IsRational()) w.push_back(c->Weight(i));
  }
  TColStd_Array1OfReal k(1, c->NbKnots());
  TColStd_Array1OfInteger m(1, c->NbKnots());
  c->Knots(k), c->Multiplicities(m);
  return Nurbs_curve_3<double>(c->Degree(), internal::flat_knots(k, m), std::move(pts), std::move(w));
}

/// A relgeo plane curve from an OpenCASCADE 2D B-spline curve.
inline Nurbs_curve_2<double> nurbs_curve_from_occt(const Handle(Geom2d_BSplineCurve) & input) {
  Handle(Geom2d_BSplineCurve) c = Handle(Geom2d_BSplineCurve)::DownCast(input->Copy());
  if (c->IsPeriodic()) c->SetNotPeriodic();
  std::vector<Point_2<double>> pts;
  std::vector<double> w;
  for (int i = 1; i <= c->NbPoles(); ++i) {
    const gp_Pnt2d p = c->Pole(i);
    pts.push_back({p.X(), p.Y()});
    if (c->IsRational()) w.push_back(c->Weight(i));
  }
  TColStd_Array1OfReal k(1, c->NbKnots());
  TColStd_Array1OfInteger m(1, c->NbKnots());
  c->Knots(k), c->Multiplicities(m);
  return Nurbs_curve_2<double>(c->Degree(), internal::flat_knots(k, m), std::move(pts), std::move(w));
}

/// OpenCASCADE B-spline curves from relgeo curves.
inline Handle(Geom_BSplineCurve) to_occt(const Nurbs_curve_3<double>& c) {
  const int n = static_cast<int>(c.number_of_control_points());
  TColgp_Array1OfPnt poles(1, n);
  TColStd_Array1OfReal w(1, n);
  for (int i = 0; i < n; ++i) {
    const auto& p = c.control_points()[static_cast<std::size_t>(i)];
    poles(i + 1) = gp_Pnt(p.x, p.y, p.z);
    w(i + 1) = c.is_rational() ? c.weights()[static_cast<std::size_t>(i)] : 1.0;
  }
  const auto [k, m] = internal::occt_knots(c.knots());
  if (c.is_rational()) return new Geom_BSplineCurve(poles, w, k, m, c.degree());
  return new Geom_BSplineCurve(poles, k, m, c.degree());
}
inline Handle(Geom2d_BSplineCurve) to_occt(const Nurbs_curve_2<double>& c) {
  const int n = static_cast<int>(c.number_of_control_points());
  TColgp_Array1OfPnt2d poles(1, n);
  TColStd_Array1OfReal w(1, n);
  for (int i = 0; i < n; ++i) {
    const auto& p = c.control_points()[static_cast<std::size_t>(i)];
    poles(i + 1) = gp_Pnt2d(p.x, p.y);
    w(i + 1) = c.is_rational() ? c.weights()[static_cast<std::size_t>(i)] : 1.0;
  }
  const auto [k, m] = internal::occt_knots(c.knots());
  if (c.is_rational()) return new Geom2d_BSplineCurve(poles, w, k, m, c.degree());
  return new Geom2d_BSplineCurve(poles, k, m, c.degree());
}

/// A polyline as a degree-1 B-spline curve (knots at cumulative chord lengths).
inline Nurbs_curve_2<double> polyline_curve(const std::vector<Point_2<double>>& pl) {
  std::vector<double> knots{0.0};
  double t = 0;
  for (std::size_t i = 1; i < pl.size(); ++i) {
    t += std::hypot(pl[i].x - pl[i - 1].x, pl[i].y - pl[i - 1].y);
    knots.push_back(t);
  }
  knots.insert(knots.begin(), 0.0);
  knots.push_back(t);
  return Nurbs_curve_2<double>(1, std::move(knots), pl);
}

/// What surface_model_from_shape accepts.
struct Occt_read_options {
  /// Trim loop checks (CAD files meet within their own tolerances: looser
  /// than the default closure tolerance).
  Trim_options trim{.closure_tolerance = 1e-4, .flattening_tolerance = 1e-4};
};

/// \brief The faces of an OpenCASCADE shape as a relgeo surface model: every
/// face (converted to NURBS) with its wires as trim loops of p-curves, and
/// every edge of the shape as a model edge with its 3D curve (degenerate
/// edges, e.g. at a sphere's pole, get none). Two faces sharing a topological
/// edge share the model edge.
/// \throws Invalid_input when the shape has no face or OpenCASCADE fails on
/// it; the relgeo constructors' typed errors for data they refuse.
inline Surface_model surface_model_from_shape(const TopoDS_Shape& input, const Occt_read_options& options = {}) {
  TopoDS_Shape shape;
  try {
    BRepBuilderAPI_NurbsConvert convert(input, Standard_True);
    shape = convert.Shape();
  } catch (const Standard_Failure& e) {
    throw Invalid_input(std::string("OpenCASCADE: NURBS conversion failed: ") + e.GetMessageString());
  }
  Surface_model m;
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edges(i));
    Model_edge me;
    if (!BRep_Tool::Degenerated(e)) {
      double first = 0, last = 0;
      TopLoc_Location loc;
      Handle(Geom_Curve) c = BRep_Tool::Curve(e, loc, first, last);
      if (!c.IsNull()) {
        if (!loc.IsIdentity()) c = Handle(Geom_Curve)::DownCast(c->Transformed(loc.Transformation()));
        me.curve = nurbs_curve_from_occt(GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(c, first, last)));
      }
    }
    m.edges.push_back(std::move(me));
  }
  for (TopExp_Explorer fx(shape, TopAbs_FACE); fx.More(); fx.Next()) {
    const TopoDS_Face face = TopoDS::Face(fx.Current());
    TopLoc_Location loc;
    Handle(Geom_Surface) gs = BRep_Tool::Surface(face, loc);
    if (!loc.IsIdentity()) gs = Handle(Geom_Surface)::DownCast(gs->Transformed(loc.Transformation()));
    Handle(Geom_BSplineSurface) bs = Handle(Geom_BSplineSurface)::DownCast(gs);
    if (bs.IsNull()) bs = GeomConvert::SurfaceToBSplineSurface(gs);
    Nurbs_surface<double> surface = nurbs_surface_from_occt(bs);
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    Trim_loop outer_loop;
    std::vector<Trim_loop> inner;
    for (TopExp_Explorer wx(face, TopAbs_WIRE); wx.More(); wx.Next()) {
      const TopoDS_Wire wire = TopoDS::Wire(wx.Current());
      Trim_loop loop;
      for (BRepTools_WireExplorer ex(wire, face); ex.More(); ex.Next()) {
        const TopoDS_Edge& e = ex.Current();
        double first = 0, last = 0;
        Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(e, face, first, last);
        if (pc.IsNull()) throw Invalid_input("OpenCASCADE shape: an edge has no p-curve on its face");
        Trim_curve t;
        t.geometry = nurbs_curve_from_occt(Geom2dConvert::CurveToBSplineCurve(new Geom2d_TrimmedCurve(pc, first, last)));
        t.reversed = e.Orientation() == TopAbs_REVERSED;
        t.edge = edges.FindIndex(e) - 1;  // degenerate edges too (a model edge without geometry)
        loop.curves.push_back(std::move(t));
      }
      if (wire.IsSame(outer)) outer_loop = std::move(loop);
      else inner.push_back(std::move(loop));
    }
    m.faces.emplace_back(std::move(surface), std::move(outer_loop), std::move(inner),
                         face.Orientation() == TopAbs_REVERSED, options.trim);
  }
  if (m.faces.empty()) throw Invalid_input("OpenCASCADE shape: no face");
  return m;
}

/// \brief An OpenCASCADE compound of one face per relgeo face (surface,
/// wires made of the trim curves as p-curves, 3D curves built), not sewn.
/// `surfaces` (if given) receives the faces' surfaces in model order (OCC
/// keeps them when it sews, so they identify the faces afterwards).
inline TopoDS_Compound shape_from_surface_model(const Surface_model& m,
                                                std::vector<Handle(Geom_Surface)>* surfaces = nullptr) {
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  for (const Trimmed_surface& f : m.faces) {
    Handle(Geom_BSplineSurface) gs = to_occt(f.surface());
    if (surfaces) surfaces->push_back(gs);
    const auto make_wire = [&](const Trim_loop& loop) {
      BRepBuilderAPI_MakeWire mw;
      for (const Trim_curve& t : loop.curves) {
        Handle(Geom2d_BSplineCurve) pc = t.is_polyline() ? to_occt(polyline_curve(std::get<0>(t.geometry)))
                                                          : to_occt(std::get<1>(t.geometry));
        TopoDS_Edge e = BRepBuilderAPI_MakeEdge(pc, gs, pc->FirstParameter(), pc->LastParameter());
        if (t.reversed) e.Reverse();
        mw.Add(e);
      }
      if (!mw.IsDone()) throw Invalid_input("OpenCASCADE: a trim loop does not make a wire");
      return mw.Wire();
    };
    BRepBuilderAPI_MakeFace mf(gs, make_wire(f.outer_loop()), Standard_True);
    for (const Trim_loop& l : f.inner_loops()) mf.Add(make_wire(l));
    if (!mf.IsDone()) throw Invalid_input("OpenCASCADE: cannot make a face");
    TopoDS_Face face = mf.Face();
    BRepLib::BuildCurves3d(face);
    ShapeFix_Face fix(face);
    fix.Perform();
    face = fix.Face();
    if (f.reversed()) face.Reverse();
    builder.Add(compound, face);
  }
  return compound;
}

}  // namespace relgeo
