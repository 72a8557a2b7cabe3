// relgeo/joining/central_mesh.h — the central mesh of thesis Sec. 4.3.2
// step 3: the projected mesh patch without its peripheral triangles, so that
// what remains lies strictly inside the projected boundary curves dR, at a
// clearance that leaves room for well-shaped triangles of the external
// region, and is a valid planar triangulation (every triangle positively
// oriented, no two overlapping, a manifold with simple boundary cycles: the
// constraints of the external region's triangulation).
//
// A triangle is removed when
//  1. a corner is within `layers` rings of the mesh boundary (at least one
//     layer goes, as the thesis requires);
//  2. an edge meets dR (certified segment tests, K) or a corner lies outside
//     dR (one certified winding number per connected piece of the mesh cut
//     along the crossing edges);
//  3. a corner is closer to dR than `clearance` times its mean edge length;
//  4. it is not certainly positively oriented, or overlaps another (folds of
//     the input);
//  5. a corner would be non-manifold (several fans) — repeated until none.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <queue>
#include <span>
#include <vector>

#include "relgeo/core/internal/union_find.h"
#include "relgeo/joining/boundary_chains.h"
#include "relgeo/joining/error_measures.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/point.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/surfaces/trimmed_surface.h"

namespace relgeo {

/// Options of central_mesh.
struct Central_mesh_options {
  /// Rings of triangles around the mesh boundary removed (at least 1) [1].
  int layers = 1;
  /// Corners kept at least clearance x (their mean edge length in (u,v))
  /// from dR [0.5].
  double clearance = 0.5;
};

/// Which triangles form the central mesh, and why the others were removed.
struct Central_mesh {
  std::vector<char> keep;
  std::size_t removed_periphery = 0, removed_outside = 0, removed_clearance = 0, removed_invalid = 0,
              removed_non_manifold = 0;
  std::size_t kept() const { return static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 1)); }
};

namespace internal {

/// A uniform grid over the segments of closed loops, for proximity queries.
class Segment_grid {
 public:
  struct Segment {
    Point_2<double> a, b;
  };
  Segment_grid(const std::vector<std::vector<Point_2<double>>>& loops, double cell) {
    for (const auto& l : loops)
      for (std::size_t i = 0; i < l.size(); ++i) segments_.push_back({l[i], l[(i + 1) % l.size()]});
    x0_ = y0_ = std::numeric_limits<double>::infinity();
    double x1 = -x0_, y1 = -y0_;
    for (const auto& s : segments_)
      for (const auto& p : {s.a, s.b}) x0_ = std::min(x0_, p.x), y0_ = std::min(y0_, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    cell_ = std::max(cell, 1e-12 * std::max(x1 - x0_, y1 - y0_));
    nx_ = static_cast<std::size_t>(std::clamp((x1 - x0_) / cell_, 0.0, 4095.0)) + 1;
    ny_ = static_cast<std::size_t>(std::clamp((y1 - y0_) / cell_, 0.0, 4095.0)) + 1;
    cell_ = std::max((x1 - x0_) / static_cast<double>(nx_), (y1 - y0_) / static_cast<double>(ny_));
    cell_ = std::max(cell_, 1e-300);
    cells_.resize(nx_ * ny_);
    for (std::uint32_t i = 0; i < segments_.size(); ++i) {
      const auto& s = segments_[i];
      for_cells(std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y), std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y),
                [&](std::size_t c) { cells_[c].push_back(i); });
    }
  }
  const std::vector<Segment>& segments() const { return segments_; }
  /// Calls f(segment index) for segments whose cells meet the box (maybe twice).
  template <class F>
  void near_box(double x0, double y0, double x1, double y1, F&& f) const {
    for_cells(x0, y0, x1, y1, [&](std::size_t c) {
      for (std::uint32_t i : cells_[c]) f(i);
    });
  }
  /// Distance from p to the loops if below r; otherwise >= r (infinity).
  double distance_within(const Point_2<double>& p, double r) const {
    double best = std::numeric_limits<double>::infinity();
    near_box(p.x - r, p.y - r, p.x + r, p.y + r,
             [&](std::uint32_t i) { best = std::min(best, distance_to_segment(p, segments_[i].a, segments_[i].b)); });
    return best;
  }

 private:
  template <class F>
  void for_cells(double x0, double y0, double x1, double y1, F&& f) const {
    const auto cx = [&](double x) {
      return static_cast<std::size_t>(std::clamp((x - x0_) / cell_, 0.0, static_cast<double>(nx_ - 1)));
    };
    const auto cy = [&](double y) {
      return static_cast<std::size_t>(std::clamp((y - y0_) / cell_, 0.0, static_cast<double>(ny_ - 1)));
    };
    for (std::size_t i = cx(x0); i <= cx(x1); ++i)
      for (std::size_t j = cy(y0); j <= cy(y1); ++j) f(i * ny_ + j);
  }
  std::vector<Segment> segments_;
  std::vector<std::vector<std::uint32_t>> cells_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  std::size_t nx_ = 1, ny_ = 1;
};

/// central_mesh's removal rules as steps over one patch (file comment); each
/// step clears `keep` of the triangles it removes and counts them.
template <class K>
class Central_mesh_builder {
 public:
  Central_mesh_builder(std::span<const Triangle> faces, std::span<const Point_2<double>> uv, const Mesh_topology& topology,
                       const std::vector<std::vector<Point_2<double>>>& boundary, const Central_mesh_options& options,
                       const K& k)
      : faces_(faces), uv_(uv), topology_(topology), boundary_(boundary), options_(options), k_(k),
        nf_(faces.size()), nv_(uv.size()) {
    c_.keep.assign(nf_, 1);
    measure_edge_lengths();
  }

  Central_mesh build() && {
    remove_periphery();
    const Segment_grid grid(boundary_, 2 * median_edge_);
    remove_outside(grid);
    remove_close_to_boundary(grid);
    remove_invalid();
    remove_non_manifold_corners();
    return std::move(c_);
  }

 private:
  void remove(Index f, std::size_t& counter) {
    if (c_.keep[f]) c_.keep[f] = 0, ++counter;
  }

  /// The mean edge length per vertex, and the median edge length.
  void measure_edge_lengths() {
    mean_edge_.assign(nv_, 0.0);
    std::vector<int> degree(nv_, 0);
    std::vector<double> lengths;
    for (const Triangle& t : faces_)
      for (int i = 0; i < 3; ++i) {
        const double l = std::hypot(uv_[t[i]].x - uv_[t[(i + 1) % 3]].x, uv_[t[i]].y - uv_[t[(i + 1) % 3]].y);
        mean_edge_[t[i]] += l, mean_edge_[t[(i + 1) % 3]] += l, ++degree[t[i]], ++degree[t[(i + 1) % 3]];
        lengths.push_back(l);
      }
    for (std::size_t v = 0; v < nv_; ++v) mean_edge_[v] = degree[v] ? mean_edge_[v] / degree[v] : 0.0;
    std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
    median_edge_ = lengths.empty() ? 1.0 : lengths[lengths.size() / 2];
  }

  /// 1. Rings around the mesh boundary.
  void remove_periphery() {
    std::vector<int> ring(nv_, -1);
    std::queue<Index> queue;
    for (Index v = 0; v < nv_; ++v)
      if (!topology_.is_isolated(v) && topology_.is_boundary_vertex(v)) ring[v] = 0, queue.push(v);
    while (!queue.empty()) {
      const Index v = queue.front();
      queue.pop();
      if (ring[v] + 1 >= options_.layers) continue;
      for (Index w : topology_.vertex_ring(v))
        if (ring[w] < 0) ring[w] = ring[v] + 1, queue.push(w);
    }
    for (Index f = 0; f < nf_; ++f)
      for (Index v : faces_[f])
        if (ring[v] >= 0 && ring[v] < std::max(1, options_.layers)) remove(f, c_.removed_periphery);
  }

  /// 2. Edges meeting dR; corners outside it.
  void remove_outside(const Segment_grid& grid) {
    const std::vector<char> crossing = crossing_edges(grid);
    Union_find<Index> sides(nv_);  // vertices joined by edges that cross no boundary
    for (Index e = 0; e < topology_.number_of_edges(); ++e)
      if (!crossing[e]) {
        const Edge ab = topology_.edge_vertices(e);
        sides.unite(ab.a, ab.b);
      }
    std::vector<signed char> inside(nv_, -1);  // per component root: 1 inside, 0 not (or undecided)
    for (Index v = 0; v < nv_; ++v) {
      const Index r = sides.find(v);
      if (inside[r] < 0) inside[r] = is_certainly_inside(uv_[v]) ? 1 : 0;
    }
    for (Index f = 0; f < nf_; ++f) {
      bool out = false;
      for (int i = 0; i < 3; ++i) {
        out = out || inside[sides.find(faces_[f][i])] != 1;
        const Index he = 3 * f + static_cast<Index>(i);
        out = out || crossing[topology_.edge(he)];
      }
      if (out) remove(f, c_.removed_outside);
    }
  }

  /// The edges that meet dR, or may (certified segment tests).
  std::vector<char> crossing_edges(const Segment_grid& grid) const {
    std::vector<char> crossing(topology_.number_of_edges(), 0);
    for (Index e = 0; e < topology_.number_of_edges(); ++e) {
      const Edge ab = topology_.edge_vertices(e);
      const Point_2<double>&a = uv_[ab.a], &b = uv_[ab.b];
      grid.near_box(std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y), [&](std::uint32_t s) {
        if (crossing[e]) return;
        const auto hit = segments_intersect(k_, a, b, grid.segments()[s].a, grid.segments()[s].b);
        if (!hit || *hit) crossing[e] = 1;
      });
    }
    return crossing;
  }

  /// Whether p certainly lies inside dR (a certified, non-zero winding number).
  bool is_certainly_inside(const Point_2<double>& p) const {
    int winding = 0;
    for (const auto& loop : boundary_) {
      const auto w = Trimmed_surface::winding_number(loop, p, k_);
      if (!w || *w == Trimmed_surface::on_boundary_code) return false;
      winding += *w;
    }
    return winding != 0;
  }

  /// 3. Clearance from dR.
  void remove_close_to_boundary(const Segment_grid& grid) {
    for (Index f = 0; f < nf_; ++f) {
      if (!c_.keep[f]) continue;
      for (Index v : faces_[f]) {
        const double r = options_.clearance * mean_edge_[v];
        if (grid.distance_within(uv_[v], r) < r) {
          remove(f, c_.removed_clearance);
          break;
        }
      }
    }
  }

  /// 4. Orientation and overlaps.
  void remove_invalid() {
    std::vector<Triangle> kept_faces;
    std::vector<Index> kept_id;
    for (Index f = 0; f < nf_; ++f)
      if (c_.keep[f]) {
        if (!certainly(uv_orientation(k_, uv_[faces_[f][0]], uv_[faces_[f][1]], uv_[faces_[f][2]]),
                       Certified_sign::positive))
          remove(f, c_.removed_invalid);
        else kept_faces.push_back(faces_[f]), kept_id.push_back(f);
      }
    const Overlap_report overlaps = uv_overlaps<K>(kept_faces, uv_, k_);
    for (const auto& list : {overlaps.overlapping, overlaps.undecided})
      for (const auto& [a, b] : list) remove(kept_id[a], c_.removed_invalid), remove(kept_id[b], c_.removed_invalid);
  }

  /// 5. Non-manifold corners: a vertex with more than two boundary edges of
  /// the kept set sits where several fans meet.
  void remove_non_manifold_corners() {
    for (bool changed = true; changed;) {
      changed = false;
      std::vector<int> boundary_edges(nv_, 0);
      for (Index e = 0; e < topology_.number_of_edges(); ++e) {
        const Index h0 = topology_.edge_halfedge(e), h1 = topology_.opposite(h0);
        const int kept = c_.keep[Mesh_topology::face(h0)] + (h1 == invalid_index ? 0 : c_.keep[Mesh_topology::face(h1)]);
        if (kept == 1) {
          const Edge ab = topology_.edge_vertices(e);
          ++boundary_edges[ab.a], ++boundary_edges[ab.b];
        }
      }
      for (Index f = 0; f < nf_; ++f) {
        if (!c_.keep[f]) continue;
        for (Index v : faces_[f])
          if (boundary_edges[v] > 2) {
            remove(f, c_.removed_non_manifold);
            changed = true;
            break;
          }
      }
    }
  }

  std::span<const Triangle> faces_;
  std::span<const Point_2<double>> uv_;
  const Mesh_topology& topology_;
  const std::vector<std::vector<Point_2<double>>>& boundary_;
  const Central_mesh_options& options_;
  const K& k_;
  std::size_t nf_, nv_;
  Central_mesh c_;
  std::vector<double> mean_edge_;  ///< per vertex, in (u,v)
  double median_edge_ = 1;
};

}  // namespace internal

/// \brief The central mesh of a projected mesh patch (file comment).
/// \param faces the patch's triangles, counter-clockwise in (u,v);
/// \param uv the vertices' parameters; \param topology of `faces`;
/// \param boundary dR: closed loops in (u,v) (outer and holes).
template <OrientationKernel_2 K>
Central_mesh central_mesh(std::span<const Triangle> faces, std::span<const Point_2<double>> uv, const Mesh_topology& topology,
                          const std::vector<std::vector<Point_2<double>>>& boundary, const Central_mesh_options& options = {},
                          const K& k = K{}) {
  return internal::Central_mesh_builder<K>(faces, uv, topology, boundary, options, k).build();
}

}  // namespace relgeo
