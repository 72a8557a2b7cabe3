// relgeo/joining/test_models.h — joining inputs made by the library itself
// (SPEC Sec. 6): trimmed bicubic patches and rational pieces, tessellated by
// Ruppert refinement (CGAL Mesh_2) and perturbed by controlled noise; models
// of two and three faces meeting along curves, with or without the edges'
// 3D curves (thesis case 1 / case 2); the folding configuration of thesis
// Figs. 4.2 and 4.7-4.9. Used by the tests, the benchmarks and the
// experiment. Needs CGAL (relgeo::cgal) for the tessellation.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "relgeo/joining/domain_mesher.h"
#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/surfaces/nurbs_curve.h"
#include "relgeo/surfaces/nurbs_surface.h"
#include "relgeo/surfaces/surface_model.h"
#include "relgeo/surfaces/trimmed_surface.h"

namespace relgeo {

/// A surface model with one mesh patch per face.
struct Joining_case {
  std::string name;
  Surface_model model;
  std::vector<Triangle_mesh<Point_3<double>>> meshes;
};

/// A tessellated face: the mesh (counter-clockwise seen from the face's
/// outward normal) and its vertices' parameters.
struct Tessellated_face {
  Triangle_mesh<Point_3<double>> mesh;
  std::vector<Point_2<double>> uv;
};

/// \brief The trimmed face's domain triangulated by Ruppert refinement
/// (edges at most `max_edge_uv` in (u,v)) and mapped to the surface.
inline Tessellated_face tessellate(const Trimmed_surface& face, double max_edge_uv) {
  const Domain_mesh d = mesh_domain(face.domain_polygon(), {.shape_bound = 0.125, .max_edge_length = max_edge_uv});
  Tessellated_face t;
  for (const Domain_vertex& v : d.vertices) {
    t.uv.push_back(v.uv);
    t.mesh.vertices.push_back(face.surface().evaluate(v.uv.x, v.uv.y));
  }
  for (Triangle tr : d.triangles) {
    if (face.reversed()) std::swap(tr[1], tr[2]);
    t.mesh.faces.push_back(tr);
  }
  return t;
}

/// \brief Controlled noise: every vertex moved in (u,v) by up to
/// `tangential` (uniform in a disk, in parameter units) and placed at height
/// uniform in [-normal, normal] along the unit normal. Deterministic in `seed`.
inline void perturb(Tessellated_face& t, const Trimmed_surface& face, double normal, double tangential, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> r(-1, 1);
  for (std::size_t i = 0; i < t.uv.size(); ++i) {
    double dx, dy;
    do dx = r(rng), dy = r(rng);
    while (dx * dx + dy * dy > 1);
    t.uv[i] = {t.uv[i].x + tangential * dx, t.uv[i].y + tangential * dy};
    const Surface_derivatives<double> d = face.surface().derivatives(t.uv[i].x, t.uv[i].y, 1);
    const Vector_3<double> n = unit_normal(d);
    const double h = normal * r(rng);
    t.mesh.vertices[i] = {d.point.x + h * n[0], d.point.y + h * n[1], d.point.z + h * n[2]};
  }
}

namespace internal {

// A straight trim curve from a to b (its natural direction); `reversed`:
// the loop runs from b to a.
inline Trim_curve segment_curve(Point_2<double> a, Point_2<double> b, int edge, bool reversed = false) {
  return {std::vector<Point_2<double>>{a, b}, reversed, edge};
}
inline Trim_curve cubic_curve(std::vector<Point_2<double>> control, int edge, bool reversed = false) {
  return {Nurbs_curve_2<double>(3, {0, 0, 0, 0, 1, 1, 1, 1}, std::move(control)), reversed, edge};
}
/// The surface curve S(c(t)) as a dense 3D polyline (an edge's "given"
/// curve), in the trim curve's natural direction.
inline Model_edge surface_curve_edge(const Nurbs_surface<double>& s, const Trim_curve& c, std::size_t n = 400) {
  Model_edge e;
  for (std::size_t i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n);
    Point_2<double> p;
    if (c.is_polyline()) {  // a segment (the test models' polylines have two points)
      const auto& pl = std::get<0>(c.geometry);
      p = {pl.front().x + t * (pl.back().x - pl.front().x), pl.front().y + t * (pl.back().y - pl.front().y)};
    } else {
      p = std::get<1>(c.geometry).evaluate(t);
    }
    e.polyline.push_back(s.evaluate(p.x, p.y));
  }
  return e;
}

}  // namespace internal

/// A smooth bicubic Bezier patch over [0,1]^2 spanning [0, width] x [0, 1]
/// in x, y; `bump` adds a small deviation (a second surface within `bump`
/// of the first, as two CAD faces within their tolerance).
inline Nurbs_surface<double> bicubic_surface(double width = 2, double bump = 0) {
  std::vector<Point_3<double>> P;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      P.push_back({width * i / 3.0, j / 3.0,
                   0.25 * std::sin(1.0 + i) * std::cos(0.7 * j) + bump * std::cos(2.0 * i + j)});
  return Nurbs_surface<double>(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4, std::move(P));
}

/// \brief Two faces of two slightly different bicubic surfaces (within
/// `gap`) meeting along a wavy curve u = c(v): face 0 left of it, face 1
/// right. Edge 0 is the shared edge; with `edge_curve` it carries the 3D
/// curve (on face 0's surface: case 1), otherwise none (case 2). The other
/// edges are free; with `free_edge_curves` they carry their 3D curves too
/// (each on its own face's surface: every boundary height is then the
/// surfaces' own discrepancy, not the mesh's noise).
inline Surface_model two_face_model(bool edge_curve, double gap = 2e-3, bool free_edge_curves = false) {
  const Nurbs_surface<double> s0 = bicubic_surface(2, 0), s1 = bicubic_surface(2, gap);
  const Trim_curve c = internal::cubic_curve({{0.5, 0}, {0.42, 0.35}, {0.58, 0.65}, {0.5, 1}}, 0);
  Surface_model m;
  m.edges.resize(7);
  if (edge_curve) m.edges[0] = internal::surface_curve_edge(s0, c);
  Trim_loop a;
  a.curves = {internal::segment_curve({0, 0}, {0.5, 0}, 1), c, internal::segment_curve({0.5, 1}, {0, 1}, 2),
              internal::segment_curve({0, 1}, {0, 0}, 3)};
  Trim_curve back = c;
  back.reversed = true;
  Trim_loop b;
  b.curves = {internal::segment_curve({0.5, 0}, {1, 0}, 4), internal::segment_curve({1, 0}, {1, 1}, 5),
              internal::segment_curve({1, 1}, {0.5, 1}, 6), back};
  if (free_edge_curves) {
    for (std::size_t i = 0; i < a.curves.size(); ++i)
      if (a.curves[i].edge != 0) m.edges[static_cast<std::size_t>(a.curves[i].edge)] = internal::surface_curve_edge(s0, a.curves[i]);
    for (std::size_t i = 0; i < b.curves.size(); ++i)
      if (b.curves[i].edge != 0) m.edges[static_cast<std::size_t>(b.curves[i].edge)] = internal::surface_curve_edge(s1, b.curves[i]);
  }
  m.faces.emplace_back(s0, a);
  m.faces.emplace_back(s1, b);
  return m;
}

/// \brief Three faces meeting at a point (a Y junction): bottom-left,
/// bottom-right and top of the unit square, bounded by three wavy curves
/// (edges 0-2, shared); each face on its own surface, within `gap` of the
/// others. With `edge_curves` the shared edges carry their 3D curves (on the
/// first surface).
inline Surface_model three_face_model(bool edge_curves, double gap = 1.5e-3) {
  const Nurbs_surface<double> s[3] = {bicubic_surface(1.5, 0), bicubic_surface(1.5, gap), bicubic_surface(1.5, -gap)};
  const Point_2<double> j{0.5, 0.5};
  const Trim_curve c0 = internal::cubic_curve({{0.5, 0}, {0.45, 0.2}, {0.56, 0.33}, j}, 0);    // bottom -> J
  const Trim_curve c1 = internal::cubic_curve({{0, 0.5}, {0.2, 0.44}, {0.33, 0.56}, j}, 1);    // left -> J
  const Trim_curve c2 = internal::cubic_curve({j, {0.66, 0.45}, {0.8, 0.56}, {1, 0.5}}, 2);    // J -> right
  const auto rev = [](Trim_curve c) {
    c.reversed = true;
    return c;
  };
  Surface_model m;
  m.edges.resize(11);
  if (edge_curves)
    m.edges[0] = internal::surface_curve_edge(s[0], c0), m.edges[1] = internal::surface_curve_edge(s[0], c1),
    m.edges[2] = internal::surface_curve_edge(s[0], c2);
  Trim_loop a, b, c;
  a.curves = {internal::segment_curve({0, 0}, {0.5, 0}, 3), c0, rev(c1), internal::segment_curve({0, 0.5}, {0, 0}, 4)};
  b.curves = {internal::segment_curve({0.5, 0}, {1, 0}, 5), internal::segment_curve({1, 0}, {1, 0.5}, 6), rev(c2), rev(c0)};
  c.curves = {c1, c2, internal::segment_curve({1, 0.5}, {1, 1}, 7), internal::segment_curve({1, 1}, {0, 1}, 8),
              internal::segment_curve({0, 1}, {0, 0.5}, 9)};
  m.faces.emplace_back(s[0], a);
  m.faces.emplace_back(s[1], b);
  m.faces.emplace_back(s[2], c);
  return m;
}

/// \brief A rational piece: a quarter cylinder (radius 1, height 2, exact
/// rational B-spline) and the tangent plane y = 1 continuing it, meeting
/// along the line x = 0, y = 1 (edge 0, with its exact 3D curve when
/// `edge_curve`).
inline Surface_model cylinder_and_plane_model(bool edge_curve) {
  const Nurbs_surface<double> cylinder(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, 3, 2,
                                       {{1, 0, 0}, {1, 0, 2}, {1, 1, 0}, {1, 1, 2}, {0, 1, 0}, {0, 1, 2}},
                                       {1, 1, 1, 1, 2, 2});
  const Nurbs_surface<double> plane(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                                    {{0, 1, 0}, {0, 1, 2}, {-1, 1, 0}, {-1, 1, 2}});
  Surface_model m;
  m.edges.resize(7);
  if (edge_curve) m.edges[0].curve = Nurbs_curve_3<double>(1, {0, 0, 1, 1}, {{0, 1, 0}, {0, 1, 2}});
  Trim_loop a, b;
  a.curves = {internal::segment_curve({0, 0}, {1, 0}, 1), internal::segment_curve({1, 0}, {1, 1}, 0),
              internal::segment_curve({1, 1}, {0, 1}, 2), internal::segment_curve({0, 1}, {0, 0}, 3)};
  b.curves = {internal::segment_curve({0, 0}, {1, 0}, 4), internal::segment_curve({1, 0}, {1, 1}, 5),
              internal::segment_curve({1, 1}, {0, 1}, 6), internal::segment_curve({0, 0}, {0, 1}, 0, true)};
  m.faces.emplace_back(cylinder, a);
  m.faces.emplace_back(plane, b);
  return m;
}

/// The Delaunay triangulation of planar points (CGAL, exact predicates), as
/// counter-clockwise triangles over their indices.
inline std::vector<Triangle> delaunay_triangles(const std::vector<Point_2<double>>& pts) {
  using Kd = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<Index, Kd>;
  using Dt = CGAL::Delaunay_triangulation_2<Kd, CGAL::Triangulation_data_structure_2<Vb>>;
  std::vector<std::pair<Kd::Point_2, Index>> in;
  for (Index i = 0; i < pts.size(); ++i) in.push_back({Kd::Point_2(pts[i].x, pts[i].y), i});
  Dt dt(in.begin(), in.end());
  std::vector<Triangle> out;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    out.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return out;
}

/// \brief The folding configuration (thesis Figs. 4.2, 4.7-4.9): two plane
/// patches x in [0,1] and [1,2] meeting along x = 1 (edge 0, no curve:
/// case 2). Patch 0's mesh has a thin strip of triangles along its boundary
/// (inner corners 0.005 from it); patch 1's mesh overlaps it by 0.02 (its
/// boundary at x = 0.98, within a joining tolerance) with another spacing.
/// Midpoint sewing moves patch 0's boundary to x = 0.99, past the strip's
/// inner corners: its triangles flip. The Whitney joiner removes the strip
/// with the peripheral layer and triangulates anew.
inline Joining_case folding_case() {
  const Nurbs_surface<double> left(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}});
  const Nurbs_surface<double> right(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, {{1, 0, 0}, {1, 1, 0}, {2, 0, 0}, {2, 1, 0}});
  Surface_model m;
  m.edges.resize(7);
  Trim_loop a, b;
  a.curves = {internal::segment_curve({0, 0}, {1, 0}, 1), internal::segment_curve({1, 0}, {1, 1}, 0),
              internal::segment_curve({1, 1}, {0, 1}, 2), internal::segment_curve({0, 1}, {0, 0}, 3)};
  b.curves = {internal::segment_curve({0, 0}, {1, 0}, 4), internal::segment_curve({1, 0}, {1, 1}, 5),
              internal::segment_curve({1, 1}, {0, 1}, 6), internal::segment_curve({0, 0}, {0, 1}, 0, true)};
  m.faces.emplace_back(left, a);
  m.faces.emplace_back(right, b);
  // Patch 0: a grid up to x = 0.9, the thin strip, the boundary at x = 1.
  std::vector<Point_2<double>> pa, pb;
  for (int i = 0; i <= 9; ++i)
    for (int j = 0; j <= 10; ++j) pa.push_back({i / 10.0, j / 10.0});
  for (int j = 0; j < 10; ++j) pa.push_back({0.995, j / 10.0 + 0.05});
  for (int j = 0; j <= 10; ++j) pa.push_back({1.0, j / 10.0});
  // Patch 1: from x = 0.98 (overlap) to 2, rows every 1/8.
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) pb.push_back({i == 0 ? 0.98 : 1 + i / 8.0, j / 8.0});
  Joining_case c{"folding", std::move(m), {}};
  for (const auto* pts : {&pa, &pb}) {
    Triangle_mesh<Point_3<double>> mesh;
    for (const auto& p : *pts) mesh.vertices.push_back({p.x, p.y, 0});
    mesh.faces = delaunay_triangles(*pts);
    c.meshes.push_back(std::move(mesh));
  }
  return c;
}

/// Options of make_joining_case.
struct Test_mesh_options {
  /// Largest (u,v) edge of each face's tessellation (faces meshed at
  /// different sizes do not match along their shared edges).
  std::vector<double> max_edge_uv{0.05, 0.035, 0.045};
  /// Height noise (amplitude along the normal) and (u,v) jitter (parameter units).
  double normal_noise = 1e-3;
  double tangential_noise = 2e-3;
  std::uint64_t seed = 1;
};

/// A model with one tessellated, perturbed mesh patch per face.
inline Joining_case make_joining_case(std::string name, Surface_model model, const Test_mesh_options& o = {}) {
  Joining_case c{std::move(name), std::move(model), {}};
  for (std::size_t f = 0; f < c.model.faces.size(); ++f) {
    const Trimmed_surface& face = c.model.faces[f];
    Tessellated_face t = tessellate(face, o.max_edge_uv[f % o.max_edge_uv.size()] * face.parameter_scale() / std::sqrt(2.0));
    perturb(t, face, o.normal_noise, o.tangential_noise * face.parameter_scale(), o.seed * 7919 + f);
    c.meshes.push_back(std::move(t.mesh));
  }
  return c;
}

}  // namespace relgeo
