// relgeo/boolean/subdivision_validation.h — a-posteriori validation of a
// Loop subdivision solid (thesis Sec. 5.4.2): its control mesh is a closed,
// oriented 2-manifold with consistent tags, and pieces of its limit surface
// that should be disjoint are certified disjoint (see Subdivision_validation
// for what is and is not certified).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/boolean/subdivision_boolean_types.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/solid_validation.h"
#include "relgeo/subdivision/loop_features.h"

namespace relgeo {
namespace internal {

// The control points the limit over a face depends on: its vertices and
// their neighbours (sorted).
inline std::vector<std::vector<Index>> face_supports(const Mesh_topology& t) {
  std::vector<std::vector<Index>> s(t.number_of_faces());
  for (Index f = 0; f < t.number_of_faces(); ++f) {
    for (Index v : t.faces()[f]) {
      s[f].push_back(v);
      for (Index w : t.vertex_ring(v)) s[f].push_back(w);
    }
    std::sort(s[f].begin(), s[f].end());
    s[f].erase(std::unique(s[f].begin(), s[f].end()), s[f].end());
  }
  return s;
}

inline bool share_a_point(const std::vector<Index>& a, const std::vector<Index>& b) {
  for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    if (a[i] == b[j]) return true;
    a[i] < b[j] ? ++i : ++j;
  }
  return false;
}

// Whether a plane normal to `axis` separates the hulls of the two point
// sets. Each projection is computed in double under round-to-nearest
// (Default_fp_environment) and widened by its a-priori error bound
// gamma_3 sum |a_i p_i| <= 4u sum |a_i p_i| (plus the underflow allowance),
// so a reported separation holds for the exact hulls.
inline bool separated_along(const std::array<double, 3>& axis, std::span<const Index> a, std::span<const Index> b,
                            const std::vector<Point_3<double>>& p) {
  constexpr double u4 = 4 * 0x1p-53, tiny = 0x1p-1020;
  const auto range = [&](std::span<const Index> s) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (Index v : s) {
      const Point_3<double>& q = p[v];
      const double d = axis[0] * q.x + axis[1] * q.y + axis[2] * q.z;
      const double e = u4 * (std::abs(axis[0] * q.x) + std::abs(axis[1] * q.y) + std::abs(axis[2] * q.z)) + tiny;
      lo = std::min(lo, d - e), hi = std::max(hi, d + e);
    }
    return std::pair{lo, hi};
  };
  const auto [alo, ahi] = range(a);
  const auto [blo, bhi] = range(b);
  return ahi < blo || bhi < alo;
}

inline std::array<double, 3> face_normal(const std::vector<Point_3<double>>& p, const Triangle& t) {
  const Point_3<double>&a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
  const double u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, v[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// Candidate separating directions for two far pieces: both face normals,
// their sum, the line between the supports' centres and its part
// tangent to the mean normal.
inline bool separated(std::span<const Index> a, std::span<const Index> b, const Triangle& fa, const Triangle& fb,
                      const std::vector<Point_3<double>>& p) {
  const auto centre = [&](std::span<const Index> s) {
    std::array<double, 3> c{0, 0, 0};
    for (Index v : s) c[0] += p[v].x, c[1] += p[v].y, c[2] += p[v].z;
    for (double& x : c) x /= static_cast<double>(s.size());
    return c;
  };
  const auto na = face_normal(p, fa), nb = face_normal(p, fb);
  const auto ca = centre(a), cb = centre(b);
  const std::array<double, 3> d{cb[0] - ca[0], cb[1] - ca[1], cb[2] - ca[2]};
  const auto unit = [](std::array<double, 3> v) {
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0) v[0] /= l, v[1] /= l, v[2] /= l;
    return v;
  };
  const auto n = unit({unit(na)[0] + unit(nb)[0], unit(na)[1] + unit(nb)[1], unit(na)[2] + unit(nb)[2]});
  const double along = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
  const std::array<double, 3> tangent{d[0] - along * n[0], d[1] - along * n[1], d[2] - along * n[2]};
  for (const auto& axis : {na, nb, n, d, tangent})
    if (std::isfinite(axis[0] + axis[1] + axis[2]) && separated_along(axis, a, b, p)) return true;
  return false;
}

}  // namespace internal

/// \brief Validates a Loop subdivision solid given by its control mesh and
/// crease/corner tags (see Subdivision_validation for what each check
/// certifies). Never throws for bad input: every defect is reported.
/// Complexity O(n log n + k) for n faces and k pairs of overlapping support
/// boxes (each pair O(support size)).
inline Subdivision_validation validate_subdivision_solid(const Triangle_mesh<Point_3<double>>& control,
                                                         const Loop_options& loop = {},
                                                         const Subdivision_validation_options& options = {}) {
  const Default_fp_environment environment;  // the separation margins assume round-to-nearest
  Subdivision_validation r;
  r.vertices = control.vertices.size(), r.faces = control.faces.size();
  Solid_validation_options so{.check_self_intersections = false, .check_orientation = false,
                              .exact_volume_string = false, .max_listed = options.max_listed};
  const Solid_report s = validate_solid<Filtered_exact_kernel>(control, so);
  r.closed = s.closed, r.edge_manifold = s.edge_manifold, r.vertex_manifold = s.vertex_manifold;
  r.consistently_oriented = s.consistently_oriented, r.valid_tags = s.valid_tags;
  const char* adjacent_note =
      "pieces sharing a control point meet along their common boundary; intersections elsewhere between them need the "
      "thesis' Bezier criteria, not implemented";
  const bool usable = s.valid_indices.passed() && s.finite_coordinates.passed() && r.closed.passed() &&
                      r.edge_manifold.passed() && r.vertex_manifold.passed() && r.consistently_oriented.passed() &&
                      r.valid_tags.passed();
  if (!usable) {
    internal::not_checked(r.separated_pieces, "needs a closed, oriented, manifold control mesh with valid tags");
    internal::not_checked(r.adjacent_pieces, adjacent_note);
    return r;
  }
  const Mesh_topology t = Mesh_topology::build(control);
  try {
    require_no_faces_sharing_two_edges(t, "subdivision solid");
  } catch (const Invalid_input& e) {
    internal::record(r.valid_tags, {Mesh_defect::invalid_tag, {invalid_index, invalid_index}}, options.max_listed);
    r.valid_tags.status = Check_status::fail;
    r.valid_tags.note = e.what();
    internal::not_checked(r.separated_pieces, "Loop's rules do not apply to this control mesh");
    internal::not_checked(r.adjacent_pieces, adjacent_note);
    return r;
  }
  if (loop.crease_rules != Loop_crease_rules::hoppe && loop.crease_rules != Loop_crease_rules::biermann_levin_zorin) {
    internal::not_checked(r.separated_pieces, "unknown crease rules");
    internal::not_checked(r.adjacent_pieces, adjacent_note);
    return r;
  }
  const std::vector<std::vector<Index>> support = internal::face_supports(t);
  std::vector<Box_3> boxes(support.size());
  for (Index f = 0; f < support.size(); ++f)
    for (Index v : support[f]) boxes[f].extend(control.vertices[v].x, control.vertices[v].y, control.vertices[v].z);
  const Face_bvh bvh(boxes);
  std::size_t undecided = 0;
  bvh.for_each_overlapping_pair([&](Index f, Index g) {
    ++r.candidate_pairs;
    if (internal::share_a_point(support[f], support[g])) {
      ++r.adjacent_pairs;
      return;
    }
    if (internal::separated(support[f], support[g], control.faces[f], control.faces[g], control.vertices)) {
      ++r.separated_pairs;
      return;
    }
    ++undecided;
    if (r.undecided_pairs.size() < options.max_listed) r.undecided_pairs.emplace_back(std::min(f, g), std::max(f, g));
    internal::record(r.separated_pieces, {Mesh_defect::undecided, {std::min(f, g), std::max(f, g)}}, options.max_listed);
  });
  internal::conclude(r.separated_pieces, undecided > 0);
  r.separated_pieces.note = std::to_string(r.separated_pairs) + " pairs separated by a plane, " +
                            std::to_string(undecided) + " undecided";
  internal::not_checked(r.adjacent_pieces, adjacent_note);
  r.adjacent_pieces.count = r.adjacent_pairs;
  return r;
}

}  // namespace relgeo
