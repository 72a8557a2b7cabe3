// relgeo/joining/boundary_chains.h — the boundary of a mesh patch split
// along its face's trim curves, the joint polylines built from it or from
// the edges' 3D curves, and the loop deletion of thesis Sec. 4.3.3.
//
//  * boundary_loops: the boundary cycles of an oriented mesh (interior on the
//    left);
//  * split_boundary: each cycle matched to a trim loop and cut at the trim
//    corners into one chain per trim curve (the mesh vertices nearest to the
//    corners in (u,v) end the chains);
//  * median_polyline: the surrogate of a missing edge curve, the midpoints of
//    the two meshes' chains paired by normalised arc length (Sec. 4.3.3);
//  * sample_curve: an edge's 3D curve as a polyline of a given spacing
//    (Sec. 4.3.2 step 2);
//  * delete_loops: cut the loops out of a polyline in (u,v), deciding every
//    crossing with K's certified orientation_2.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/joining/joining_errors.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/point.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/surfaces/nurbs_curve.h"
#include "relgeo/surfaces/surface_model.h"
#include "relgeo/surfaces/trimmed_surface.h"

namespace relgeo {

/// The boundary cycles of a mesh, each a vertex sequence along its
/// boundary half-edges (the mesh's interior on the left).
/// \pre `t` was built from an edge- and vertex-manifold mesh.
inline std::vector<std::vector<Index>> boundary_loops(const Mesh_topology& t) {
  std::vector<std::vector<Index>> loops;
  std::vector<char> seen(t.number_of_halfedges(), 0);
  for (Index h = 0; h < t.number_of_halfedges(); ++h) {
    if (!t.is_boundary_halfedge(h) || seen[h]) continue;
    std::vector<Index> loop;
    Index cur = h;
    while (!seen[cur]) {
      seen[cur] = 1;
      loop.push_back(t.source(cur));
      const Index next = t.vertex_halfedge(t.target(cur));  // the outgoing boundary half-edge
      if (next == invalid_index || !t.is_boundary_halfedge(next)) break;
      cur = next;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

namespace internal {

inline double distance_to_segment(const Point_2<double>& p, const Point_2<double>& a, const Point_2<double>& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}
inline double distance_to_polyline(const Point_2<double>& p, std::span<const Point_2<double>> pl, bool closed) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = pl.size();
  for (std::size_t i = 0; i + (closed ? 0 : 1) < n; ++i) best = std::min(best, distance_to_segment(p, pl[i], pl[(i + 1) % n]));
  return best;
}
template <class P>
double distance_3(const P& a, const P& b) {
  return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z);
}

}  // namespace internal

/// The mesh vertices along one trim curve, in the loop's direction, from the
/// vertex nearest its start corner to the vertex nearest its end corner.
struct Boundary_chain {
  std::vector<Index> vertices;
};

/// \brief Cuts the boundary cycles of a mesh patch into one chain per trim
/// curve of `face`: chains[l][c] for curve c of trim loop l (0 = outer).
/// `uv` holds the mesh vertices' parameters; the mesh is oriented
/// counter-clockwise in (u,v).
/// \throws Joining_input_error when the cycles do not match the trim loops
/// (different numbers, corners out of order).
inline std::vector<std::vector<Boundary_chain>> split_boundary(const Trimmed_surface& face,
                                                               const std::vector<std::vector<Index>>& cycles,
                                                               std::span<const Point_2<double>> uv) {
  const auto& polygon = face.domain_polygon();
  const std::size_t nl = polygon.size();
  if (cycles.size() != nl)
    throw Joining_input_error("mesh patch has " + std::to_string(cycles.size()) + " boundary cycles, its face " +
                              std::to_string(nl) + " trim loops");
  // Match cycles to loops by mean distance (greedy on the best pairs).
  std::vector<std::vector<double>> cost(nl, std::vector<double>(nl));
  for (std::size_t c = 0; c < nl; ++c)
    for (std::size_t l = 0; l < nl; ++l) {
      double s = 0;
      for (Index v : cycles[c]) s += internal::distance_to_polyline(uv[v], polygon[l], true);
      cost[c][l] = s / static_cast<double>(cycles[c].size());
    }
  std::vector<int> loop_of(nl, -1);
  std::vector<char> taken(nl, 0);
  for (std::size_t round = 0; round < nl; ++round) {
    double best = std::numeric_limits<double>::infinity();
    std::size_t bc = 0, bl = 0;
    for (std::size_t c = 0; c < nl; ++c)
      for (std::size_t l = 0; l < nl; ++l)
        if (loop_of[c] < 0 && !taken[l] && cost[c][l] < best) best = cost[c][l], bc = c, bl = l;
    loop_of[bc] = static_cast<int>(bl), taken[bl] = 1;
  }
  std::vector<std::vector<Boundary_chain>> chains(nl);
  for (std::size_t c = 0; c < nl; ++c) {
    const std::size_t l = static_cast<std::size_t>(loop_of[c]);
    const Trim_loop& loop = Surface_model::loop(face, l);
    const std::vector<Index>& cyc = cycles[c];
    const std::size_t m = cyc.size(), k = loop.curves.size();
    // The cycle position nearest to each corner (start of curve j).
    std::vector<std::size_t> pos(k);
    for (std::size_t j = 0; j < k; ++j) {
      const Point_2<double> corner = loop.curves[j].start();
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < m; ++i) {
        const double d = std::hypot(uv[cyc[i]].x - corner.x, uv[cyc[i]].y - corner.y);
        if (d < best) best = d, pos[j] = i;
      }
    }
    // Corners must appear in loop order along the cycle.
    for (std::size_t j = 0; j + 1 < k; ++j) {
      const std::size_t a = (pos[j + 1] + m - pos[0]) % m, b = (pos[j] + m - pos[0]) % m;
      if (a < b)
        throw Joining_input_error("mesh patch boundary: the corners of trim loop " + std::to_string(l) +
                                  " are not in order along the mesh boundary (mesh too coarse or misplaced)");
    }
    chains[l].resize(k);
    for (std::size_t j = 0; j < k; ++j) {
      const std::size_t from = pos[j], to = pos[(j + 1) % k];
      std::size_t len = (to + m - from) % m;
      if (k == 1) len = m;  // one closed curve: the whole cycle, back to its start
      for (std::size_t s = 0; s <= len; ++s) chains[l][j].vertices.push_back(cyc[(from + s) % m]);
    }
  }
  return chains;
}

/// \brief The median of two 3D polylines running the same way: both are
/// parametrised by normalised arc length, the union of their parameters
/// taken, and at each the midpoint of the two points (thesis Sec. 4.3.3;
/// the same pairing naive sewing uses, Sec. 4.1).
/// \throws Joining_input_error for a polyline of fewer than 2 points or of
/// zero length.
inline std::vector<Point_3<double>> median_polyline(std::span<const Point_3<double>> a, std::span<const Point_3<double>> b) {
  const auto parameters = [](std::span<const Point_3<double>> p) {
    if (p.size() < 2) throw Joining_input_error("median_polyline: a chain of fewer than 2 points");
    std::vector<double> s{0};
    for (std::size_t i = 1; i < p.size(); ++i) s.push_back(s.back() + internal::distance_3(p[i], p[i - 1]));
    if (!(s.back() > 0)) throw Joining_input_error("median_polyline: a chain of zero length");
    for (double& x : s) x /= s.back();
    s.back() = 1;
    return s;
  };
  const std::vector<double> sa = parameters(a), sb = parameters(b);
  const auto at = [](std::span<const Point_3<double>> p, const std::vector<double>& s, double t) {
    std::size_t i = static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), t) - s.begin());
    i = std::clamp<std::size_t>(i, 1, s.size() - 1);
    const double w = s[i] > s[i - 1] ? (t - s[i - 1]) / (s[i] - s[i - 1]) : 0.0;
    return Point_3<double>{p[i - 1].x + w * (p[i].x - p[i - 1].x), p[i - 1].y + w * (p[i].y - p[i - 1].y),
                           p[i - 1].z + w * (p[i].z - p[i - 1].z)};
  };
  std::vector<double> merged, s;
  std::merge(sa.begin(), sa.end(), sb.begin(), sb.end(), std::back_inserter(merged));
  // Parameters closer than 1e-9 are one (two vertices at nearly the same
  // place would make a needle in dR); 0 and 1 are kept.
  for (double t : merged)
    if (s.empty() || t - s.back() > 1e-9) s.push_back(t);
  if (s.back() != 1) s.back() = 1;
  std::vector<Point_3<double>> m;
  for (double t : s) {
    const Point_3<double> p = at(a, sa, t), q = at(b, sb, t);
    const Point_3<double> mid{0.5 * (p.x + q.x), 0.5 * (p.y + q.y), 0.5 * (p.z + q.z)};
    if (m.empty() || m.back() != mid) m.push_back(mid);
  }
  return m;
}

/// \brief A 3D edge curve as a polyline of about `spacing` between
/// consecutive points (at least `min_segments` segments), evenly in arc
/// length: a NURBS curve is measured on a dense sampling and evaluated at the
/// parameters found; a polyline is resampled along its own segments.
inline std::vector<Point_3<double>> sample_edge(const Model_edge& edge, double spacing, std::size_t min_segments = 2) {
  std::vector<Point_3<double>> dense;
  std::vector<double> param;
  if (edge.curve) {
    const auto [t0, t1] = edge.curve->domain();
    const std::size_t n = 64 * edge.curve->number_of_control_points();
    for (std::size_t i = 0; i <= n; ++i) {
      const double t = i == n ? t1 : t0 + (t1 - t0) * static_cast<double>(i) / static_cast<double>(n);
      dense.push_back(edge.curve->evaluate(t)), param.push_back(t);
    }
  } else {
    dense = edge.polyline;
  }
  if (dense.size() < 2) throw Joining_input_error("sample_edge: the edge has no 3D geometry");
  std::vector<double> s{0};
  for (std::size_t i = 1; i < dense.size(); ++i) s.push_back(s.back() + internal::distance_3(dense[i], dense[i - 1]));
  const double length = s.back();
  const std::size_t segments =
      std::max<std::size_t>(min_segments, static_cast<std::size_t>(std::ceil(length / std::max(spacing, 1e-300))));
  std::vector<Point_3<double>> out{dense.front()};
  std::size_t i = 1;
  for (std::size_t k = 1; k < segments; ++k) {
    const double target = length * static_cast<double>(k) / static_cast<double>(segments);
    while (i + 1 < s.size() && s[i] < target) ++i;
    const double w = s[i] > s[i - 1] ? (target - s[i - 1]) / (s[i] - s[i - 1]) : 0.0;
    if (edge.curve) {
      out.push_back(edge.curve->evaluate(param[i - 1] + w * (param[i] - param[i - 1])));
    } else {
      const Point_3<double>& p = dense[i - 1];
      const Point_3<double>& q = dense[i];
      out.push_back({p.x + w * (q.x - p.x), p.y + w * (q.y - p.y), p.z + w * (q.z - p.z)});
    }
  }
  out.push_back(dense.back());
  return out;
}

namespace internal {

/// Whether closed segments ab and cd intersect (certified: empty when K
/// cannot decide). Coincident endpoints (bitwise) are decided without K.
template <OrientationKernel_2 K>
std::optional<bool> segments_intersect(const K& k, const Point_2<double>& a, const Point_2<double>& b,
                                       const Point_2<double>& c, const Point_2<double>& d) {
  const auto same = [](const Point_2<double>& p, const Point_2<double>& q) { return p.x == q.x && p.y == q.y; };
  if (same(a, c) || same(a, d) || same(b, c) || same(b, d)) return true;
  if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
      std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
    return false;  // disjoint boxes (exact comparisons)
  const auto pt = k.construct_point_2_object();
  const auto o = k.orientation_2_object();
  const auto A = pt(a.x, a.y), B = pt(b.x, b.y), C = pt(c.x, c.y), D = pt(d.x, d.y);
  const Certified_sign o1 = o(A, B, C), o2 = o(A, B, D), o3 = o(C, D, A), o4 = o(C, D, B);
  for (Certified_sign s : {o1, o2, o3, o4})
    if (!is_certain(s)) return std::nullopt;
  const auto sgn = [](Certified_sign s) { return to_int(s); };
  if (sgn(o1) * sgn(o2) < 0 && sgn(o3) * sgn(o4) < 0) return true;
  const auto on = [](const Point_2<double>& p, const Point_2<double>& q, const Point_2<double>& r) {  // r in box(p, q)
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
  };
  if (certainly(o1, Certified_sign::zero) && on(a, b, c)) return true;
  if (certainly(o2, Certified_sign::zero) && on(a, b, d)) return true;
  if (certainly(o3, Certified_sign::zero) && on(c, d, a)) return true;
  if (certainly(o4, Certified_sign::zero) && on(c, d, b)) return true;
  return false;
}

}  // namespace internal

/// \brief Removes the loops of an open polyline in (u,v): while two
/// non-adjacent segments i and j > i + 1 intersect, the points i+1..j are
/// cut out (the polyline goes from point i to point j+1). Returns the indices
/// of the points kept (first and last always kept). Every intersection is
/// decided with K's certified orientation_2; an undecidable one counts as an
/// intersection (the loop is cut: never a crossing left in place).
/// O(n^2) segment tests per pass.
template <OrientationKernel_2 K>
std::vector<std::size_t> delete_loops(std::span<const Point_2<double>> p, const K& k = K{}) {
  std::vector<std::size_t> keep(p.size());
  for (std::size_t i = 0; i < keep.size(); ++i) keep[i] = i;
  bool changed = true;
  while (changed && keep.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i + 2 < keep.size() - 1 && !changed; ++i)
      for (std::size_t j = keep.size() - 2; j >= i + 2 && !changed; --j) {
        const auto hit = internal::segments_intersect(k, p[keep[i]], p[keep[i + 1]], p[keep[j]], p[keep[j + 1]]);
        if (hit && !*hit) continue;
        keep.erase(keep.begin() + static_cast<std::ptrdiff_t>(i) + 1, keep.begin() + static_cast<std::ptrdiff_t>(j) + 1);
        changed = true;
      }
  }
  return keep;
}

}  // namespace relgeo
