// relgeo/joining/error_measures.h — how far a mesh patch is from its surface
// (thesis Sec. 4.2), and whether its image in the (u,v) domain is a valid
// planar triangulation.
//
// A mesh patch over a surface F is a height field: each vertex has
// parameters p_i = (u_i, v_i) and a height eta_i with vertex = F(p_i) +
// eta_i n(p_i) (projection.h). Then
//  * the absolute error is sup |eta| (over the vertices: the mesh is
//    measured where it is defined, a one-sided Hausdorff distance);
//  * the normal-vector error is the largest slope of the height field
//    between two corners of a triangle, |eta_i - eta_j| / |p_i - p_j|, the
//    thesis' computable proxy for the Lipschitz constant of eta (Sec. 4.2).
// Both are reported rounded upward (directed rounding, core/rounding.h), so a
// reported bound is never below the exact value of the data.
//
// In the (u,v) domain, triangles are certified (kernel K's orientation_2)
// as positively oriented, flipped, degenerate or undecided, and pairs of
// triangles whose interiors overlap are found (a folded triangulation) by the
// separating-edge test, with a uniform grid as the broad phase.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/errors.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/rounding.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// A mesh patch over a surface: per vertex its parameters and height.
struct Height_field {
  std::vector<Point_2<double>> uv;
  std::vector<double> height;
  std::size_t size() const { return uv.size(); }
};

/// Upper bound of |eta_p - eta_q| / |p - q| (directed rounding; +inf when p
/// and q coincide with different heights, 0 when the heights are equal).
/// \pre the default floating-point environment (callers hold one).
inline double slope_upper_bound(const Point_2<double>& p, double eta_p, const Point_2<double>& q, double eta_q) {
  const Double_bounds de = add_bounds(eta_p, -eta_q);
  const double rise = std::max(std::abs(de.lo), std::abs(de.hi));
  if (rise == 0) return 0;
  const Double_bounds dx = add_bounds(p.x, -q.x), dy = add_bounds(p.y, -q.y);
  const auto low_abs = [](const Double_bounds& b) { return b.lo > 0 ? b.lo : (b.hi < 0 ? -b.hi : 0.0); };
  const double ax = low_abs(dx), ay = low_abs(dy);
  const double run = sqrt_down(add_down(mul_down(ax, ax), mul_down(ay, ay)));
  if (run == 0) return std::numeric_limits<double>::infinity();
  return div_up(rise, run);
}

/// The error measures of one mesh patch (thesis Sec. 4.2).
struct Patch_errors {
  /// sup |eta| over the vertices (exact: the largest |height|).
  double absolute_error = 0;
  /// Largest slope between two corners of a triangle (rounded upward).
  double normal_vector_error = 0;
  Index worst_vertex = invalid_index;    ///< where the absolute error is attained
  Index worst_triangle = invalid_index;  ///< where the normal-vector error is attained
  /// Per triangle (filled when asked for): max |eta| of its corners, max slope.
  std::vector<double> triangle_absolute, triangle_slope;
};

/// \brief Absolute and normal-vector error of the triangles `faces` over the
/// height field `h` (thesis Sec. 4.2); per triangle when `per_triangle`.
/// \throws Invalid_input for an index out of range or a non-finite value.
inline Patch_errors patch_errors(std::span<const Triangle> faces, const Height_field& h, bool per_triangle = false) {
  const Default_fp_environment environment;
  Patch_errors e;
  const std::size_t n = h.size();
  if (h.height.size() != n) throw Invalid_input("patch_errors: " + std::to_string(n) + " parameters, " +
                                                std::to_string(h.height.size()) + " heights");
  std::vector<char> used(n, 0);
  if (per_triangle) e.triangle_absolute.resize(faces.size()), e.triangle_slope.resize(faces.size());
  for (Index f = 0; f < faces.size(); ++f) {
    const Triangle& t = faces[f];
    double a = 0, s = 0;
    for (int k = 0; k < 3; ++k) {
      const Index i = t[k], j = t[(k + 1) % 3];
      if (i >= n || j >= n) throw Invalid_input("patch_errors: face " + std::to_string(f) + " has an index out of range");
      if (!std::isfinite(h.height[i]) || !std::isfinite(h.uv[i].x) || !std::isfinite(h.uv[i].y))
        throw Non_finite_input("patch_errors: vertex " + std::to_string(i) + " is not finite");
      used[i] = 1;
      a = std::max(a, std::abs(h.height[i]));
      s = std::max(s, slope_upper_bound(h.uv[i], h.height[i], h.uv[j], h.height[j]));
    }
    if (per_triangle) e.triangle_absolute[f] = a, e.triangle_slope[f] = s;
    if (s > e.normal_vector_error || e.worst_triangle == invalid_index) e.normal_vector_error = s, e.worst_triangle = f;
  }
  for (Index v = 0; v < n; ++v)
    if (used[v] && (std::abs(h.height[v]) > e.absolute_error || e.worst_vertex == invalid_index))
      e.absolute_error = std::abs(h.height[v]), e.worst_vertex = v;
  return e;
}

namespace internal {

/// K's orientation of three (u,v) points, with coincident points (equal
/// coordinates, bit for bit) answered `zero` without the kernel: a fail-safe
/// or interval kernel cannot certify the zero of (p, q, p).
template <OrientationKernel_2 K>
Certified_sign uv_orientation(const K& k, const Point_2<double>& a, const Point_2<double>& b, const Point_2<double>& c) {
  const auto same = [](const Point_2<double>& p, const Point_2<double>& q) { return p.x == q.x && p.y == q.y; };
  if (same(a, b) || same(b, c) || same(a, c)) return Certified_sign::zero;
  const auto pt = k.construct_point_2_object();
  return k.orientation_2_object()(pt(a.x, a.y), pt(b.x, b.y), pt(c.x, c.y));
}

}  // namespace internal

/// Certified orientation of the triangles of a mesh in the (u,v) domain.
struct Orientation_report {
  std::size_t positive = 0;   ///< oriented as expected
  std::size_t flipped = 0;    ///< opposite orientation (a fold)
  std::size_t degenerate = 0; ///< collinear corners
  std::size_t undecided = 0;  ///< the kernel could not decide
  std::vector<Index> flipped_faces, degenerate_faces, undecided_faces;
  bool all_positive() const { return flipped == 0 && degenerate == 0 && undecided == 0; }
};

/// \brief Classifies every triangle's orientation in (u,v) with K's
/// certified orientation_2; `expected` is the orientation of a valid triangle
/// (positive for a face whose outward normal is Su x Sv, negative for a
/// reversed face).
template <OrientationKernel_2 K>
Orientation_report uv_orientations(std::span<const Triangle> faces, std::span<const Point_2<double>> uv,
                                   Certified_sign expected = Certified_sign::positive, const K& k = K{}) {
  Orientation_report r;
  for (Index f = 0; f < faces.size(); ++f) {
    const Triangle& t = faces[f];
    for (Index v : t)
      if (v >= uv.size()) throw Invalid_input("uv_orientations: face " + std::to_string(f) + " has an index out of range");
    const Certified_sign s = internal::uv_orientation(k, uv[t[0]], uv[t[1]], uv[t[2]]);
    if (!is_certain(s))
      ++r.undecided, r.undecided_faces.push_back(f);
    else if (certainly(s, Certified_sign::zero))
      ++r.degenerate, r.degenerate_faces.push_back(f);
    else if (s == expected) ++r.positive;
    else ++r.flipped, r.flipped_faces.push_back(f);
  }
  return r;
}

/// Pairs of triangles whose images in (u,v) overlap.
struct Overlap_report {
  std::vector<std::pair<Index, Index>> overlapping;  ///< interiors certainly not disjoint (f < g)
  std::vector<std::pair<Index, Index>> undecided;    ///< the kernel could not decide ((f, f): f's own orientation)
  bool is_embedding() const { return overlapping.empty() && undecided.empty(); }
};

/// \brief Pairs of triangles whose (u,v) images overlap in their interiors:
/// a triangulation of the domain must have none. Decided by the separating
/// edge theorem (two convex polygons with disjoint interiors are separated by
/// the line of one of their edges) with K's certified orientation_2;
/// candidates from a uniform grid over the triangles' boxes. Degenerate
/// triangles (collinear in (u,v)) have no interior and overlap nothing.
template <OrientationKernel_2 K>
Overlap_report uv_overlaps(std::span<const Triangle> faces, std::span<const Point_2<double>> uv, const K& k = K{}) {
  Overlap_report report;
  // Positively oriented corners per face (degenerate faces are skipped).
  std::vector<std::array<Point_2<double>, 3>> tri;
  std::vector<Index> id;
  std::vector<std::array<double, 4>> box;  // xmin, ymin, xmax, ymax
  for (Index f = 0; f < faces.size(); ++f) {
    const Triangle& t = faces[f];
    for (Index v : t)
      if (v >= uv.size()) throw Invalid_input("uv_overlaps: face " + std::to_string(f) + " has an index out of range");
    std::array<Point_2<double>, 3> c{uv[t[0]], uv[t[1]], uv[t[2]]};
    const Certified_sign s = internal::uv_orientation(k, c[0], c[1], c[2]);
    if (certainly(s, Certified_sign::zero)) continue;
    if (!is_certain(s)) {  // orientation unknown: cannot test it
      report.undecided.push_back({f, f});
      continue;
    }
    if (certainly(s, Certified_sign::negative)) std::swap(c[1], c[2]);
    tri.push_back(c), id.push_back(f);
    box.push_back({std::min({c[0].x, c[1].x, c[2].x}), std::min({c[0].y, c[1].y, c[2].y}),
                   std::max({c[0].x, c[1].x, c[2].x}), std::max({c[0].y, c[1].y, c[2].y})});
  }
  if (tri.empty()) return report;
  double x0 = box[0][0], y0 = box[0][1], x1 = box[0][2], y1 = box[0][3], sum = 0;
  for (const auto& b : box) {
    x0 = std::min(x0, b[0]), y0 = std::min(y0, b[1]), x1 = std::max(x1, b[2]), y1 = std::max(y1, b[3]);
    sum += (b[2] - b[0]) + (b[3] - b[1]);
  }
  const double cell = std::max(sum / (2.0 * static_cast<double>(box.size())), 1e-300);
  const auto nx = static_cast<std::size_t>(std::clamp((x1 - x0) / cell, 1.0, 2048.0));
  const auto ny = static_cast<std::size_t>(std::clamp((y1 - y0) / cell, 1.0, 2048.0));
  const double cx = (x1 - x0) / static_cast<double>(nx), cy = (y1 - y0) / static_cast<double>(ny);
  const auto cell_of = [](double x, double origin, double size, std::size_t n) {
    if (!(size > 0)) return std::size_t{0};
    return std::min(n - 1, static_cast<std::size_t>(std::max(0.0, (x - origin) / size)));
  };
  std::vector<std::vector<std::uint32_t>> grid(nx * ny);
  for (std::uint32_t i = 0; i < tri.size(); ++i)
    for (std::size_t gx = cell_of(box[i][0], x0, cx, nx); gx <= cell_of(box[i][2], x0, cx, nx); ++gx)
      for (std::size_t gy = cell_of(box[i][1], y0, cy, ny); gy <= cell_of(box[i][3], y0, cy, ny); ++gy)
        grid[gx * ny + gy].push_back(i);
  // Whether the line of an edge of a has every corner of b on its closed
  // outer side: positive (separated), negative (no edge of a separates),
  // uncertain (an edge might, the kernel cannot tell).
  const auto separated_by_edges_of = [&](const std::array<Point_2<double>, 3>& a,
                                         const std::array<Point_2<double>, 3>& b) {
    bool doubt = false;
    for (int e = 0; e < 3; ++e) {
      bool all_out = true, edge_doubt = false;
      for (int c = 0; c < 3 && all_out; ++c) {
        const Certified_sign s = internal::uv_orientation(k, a[e], a[(e + 1) % 3], b[c]);
        if (certainly(s, Certified_sign::positive))
          all_out = false;
        else if (!is_certain(s))
          edge_doubt = true;
      }
      if (all_out && !edge_doubt) return Certified_sign::positive;
      if (all_out) doubt = true;
    }
    return doubt ? Certified_sign::uncertain : Certified_sign::negative;
  };
  for (const auto& bucket : grid)
    for (std::size_t a = 0; a < bucket.size(); ++a)
      for (std::size_t b = a + 1; b < bucket.size(); ++b) {
        const std::uint32_t i = bucket[a], j = bucket[b];
        if (box[i][2] < box[j][0] || box[j][2] < box[i][0] || box[i][3] < box[j][1] || box[j][3] < box[i][1]) continue;
        const Certified_sign s1 = separated_by_edges_of(tri[i], tri[j]);
        if (certainly(s1, Certified_sign::positive)) continue;
        const Certified_sign s2 = separated_by_edges_of(tri[j], tri[i]);
        if (certainly(s2, Certified_sign::positive)) continue;
        const std::pair<Index, Index> key{std::min(id[i], id[j]), std::max(id[i], id[j])};
        if (!is_certain(s1) || !is_certain(s2))
          report.undecided.push_back(key);
        else report.overlapping.push_back(key);
      }
  const auto unique = [](std::vector<std::pair<Index, Index>>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  };
  unique(report.overlapping), unique(report.undecided);
  return report;
}

}  // namespace relgeo
