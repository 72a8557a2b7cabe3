// relgeo/joining/domain_mesher.h — quality triangulation of a region of the
// (u,v) plane bounded by closed polylines: Ruppert's Delaunay refinement
// (CGAL Mesh_2; thesis Sec. 4.3.2 step 4), with the provenance of every
// vertex (an input point, or a Steiner point splitting an input segment at a
// parameter t) so that the caller can keep neighbouring meshes conforming.
//
// The region is the set of points of odd nesting depth (inside an odd number
// of loops): an outer loop with holes, or the ring between a domain boundary
// and a central mesh. Loops must be simple and disjoint (constraints that
// cross make Invalid_input). Needs CGAL (link relgeo::cgal); Mesh_2 is heavy:
// include this header only where it is used.
#pragma once

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <queue>
#include <string>
#include <unordered_map>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/kernel/point.h"
#include "relgeo/joining/domain_mesh.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

namespace internal {

struct Domain_vertex_info {
  int loop = -1;
  std::size_t index = 0;
};
using Mesh_2_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh_2_vertex_base = CGAL::Triangulation_vertex_base_with_info_2<Domain_vertex_info, Mesh_2_kernel,
                                                                       CGAL::Delaunay_mesh_vertex_base_2<Mesh_2_kernel>>;
using Mesh_2_tds = CGAL::Triangulation_data_structure_2<Mesh_2_vertex_base, CGAL::Delaunay_mesh_face_base_2<Mesh_2_kernel>>;
using Mesh_2_cdt = CGAL::Constrained_Delaunay_triangulation_2<Mesh_2_kernel, Mesh_2_tds,
                                                              CGAL::No_constraint_intersection_requiring_constructions_tag>;

inline double triangle_min_angle(const Point_2<double>& a, const Point_2<double>& b, const Point_2<double>& c) {
  const auto angle = [](const Point_2<double>& o, const Point_2<double>& p, const Point_2<double>& q) {
    const double ux = p.x - o.x, uy = p.y - o.y, vx = q.x - o.x, vy = q.y - o.y;
    return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)}) * 180.0 / M_PI;
}

/// The loops' points inserted into `cdt`, each vertex knowing its (loop,
/// index), then their segments as constraints.
inline void insert_loops(Mesh_2_cdt& cdt, const std::vector<std::vector<Point_2<double>>>& loops) {
  using CDT = Mesh_2_cdt;
  using P = Mesh_2_kernel::Point_2;
  std::vector<std::vector<CDT::Vertex_handle>> handles(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (loops[l].size() < 3) throw Invalid_input("mesh_domain: loop " + std::to_string(l) + " has fewer than 3 points");
    for (std::size_t i = 0; i < loops[l].size(); ++i) {
      const Point_2<double>& q = loops[l][i];
      if (!all_finite(q.x, q.y)) throw Non_finite_input("mesh_domain: loop " + std::to_string(l) + " is not finite");
      const CDT::Vertex_handle v = cdt.insert(P(q.x, q.y));
      if (v->info().loop >= 0)
        throw Invalid_input("mesh_domain: point " + std::to_string(i) + " of loop " + std::to_string(l) +
                            " repeats point " + std::to_string(v->info().index) + " of loop " + std::to_string(v->info().loop));
      v->info() = {static_cast<int>(l), i};
      handles[l].push_back(v);
    }
  }
  try {
    for (const auto& h : handles)
      for (std::size_t i = 0; i < h.size(); ++i) cdt.insert_constraint(h[i], h[(i + 1) % h.size()]);
  } catch (const CDT::Intersection_of_constraints_exception&) {
    throw Invalid_input("mesh_domain: the boundary loops cross each other");
  }
}

/// Marks the faces of odd nesting depth as in the domain: breadth-first
/// search from the infinite face, one level deeper across each constrained
/// edge.
inline void mark_odd_depth_faces(Mesh_2_cdt& cdt) {
  using CDT = Mesh_2_cdt;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(false);
  std::vector<CDT::Face_handle> level{cdt.infinite_face()};
  std::unordered_map<CDT::Face_handle, int> depth;  // visited faces
  depth[cdt.infinite_face()] = 0;
  int d = 0;
  while (!level.empty()) {
    std::vector<CDT::Face_handle> next;
    std::queue<CDT::Face_handle> queue;
    for (auto f : level) queue.push(f);
    while (!queue.empty()) {
      const CDT::Face_handle f = queue.front();
      queue.pop();
      f->set_in_domain(d % 2 == 1);
      for (int i = 0; i < 3; ++i) {
        const CDT::Face_handle n = f->neighbor(i);
        if (depth.count(n)) continue;
        if (cdt.is_constrained({f, i})) next.push_back(n);
        else depth[n] = d, queue.push(n);
      }
    }
    ++d;
    level.clear();
    for (auto f : next)
      if (!depth.count(f)) depth[f] = d, level.push_back(f);
  }
}

/// The triangles of the domain (counter-clockwise, as CGAL's) and their
/// vertices; `id` receives each vertex's index in the result.
inline Domain_mesh domain_triangles(const Mesh_2_cdt& cdt, std::unordered_map<Mesh_2_cdt::Vertex_handle, Index>& id) {
  Domain_mesh out;
  const auto vertex_id = [&](Mesh_2_cdt::Vertex_handle v) {
    auto [it, inserted] = id.emplace(v, static_cast<Index>(out.vertices.size()));
    if (inserted) {
      Domain_vertex dv;
      dv.uv = {v->point().x(), v->point().y()};
      dv.loop = v->info().loop, dv.index = v->info().index;
      out.vertices.push_back(dv);
    }
    return it->second;
  };
  out.min_angle_degrees = 180;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    const Triangle t{vertex_id(f->vertex(0)), vertex_id(f->vertex(1)), vertex_id(f->vertex(2))};  // CGAL: counter-clockwise
    out.triangles.push_back(t);
    out.min_angle_degrees = std::min(out.min_angle_degrees,
                                     triangle_min_angle(out.vertices[t[0]].uv, out.vertices[t[1]].uv, out.vertices[t[2]].uv));
  }
  return out;
}

/// The input vertex reached by walking along the constraint from `prev`
/// through `cur` (Steiner points have loop < 0).
inline Mesh_2_cdt::Vertex_handle walk_constraint(const Mesh_2_cdt& cdt, Mesh_2_cdt::Vertex_handle prev,
                                                 Mesh_2_cdt::Vertex_handle cur) {
  using CDT = Mesh_2_cdt;
  while (cur->info().loop < 0) {
    CDT::Vertex_handle step = cur;
    auto ce = cdt.incident_edges(cur), cdone = ce;
    do {
      if (cdt.is_constrained(*ce)) {
        const CDT::Vertex_handle a = ce->first->vertex(CDT::cw(ce->second)), b = ce->first->vertex(CDT::ccw(ce->second));
        const CDT::Vertex_handle other = a == cur ? b : a;
        if (other != prev) {
          step = other;
          break;
        }
      }
    } while (++ce != cdone);
    if (step == cur) break;
    prev = cur, cur = step;
  }
  return cur;
}

/// Steiner points on input segments: follows the constrained edges from
/// each new vertex to the input points at both ends, and records the
/// segment and the parameter t on it.
inline void locate_steiner_points(const Mesh_2_cdt& cdt, const std::unordered_map<Mesh_2_cdt::Vertex_handle, Index>& id,
                                  const std::vector<std::vector<Point_2<double>>>& loops, Domain_mesh& out) {
  using CDT = Mesh_2_cdt;
  for (const auto& [v, i] : id) {
    if (v->info().loop >= 0) continue;
    std::vector<CDT::Vertex_handle> ends;
    auto e = cdt.incident_edges(v), done = e;
    if (e == nullptr) continue;
    do {
      if (cdt.is_constrained(*e)) {
        // Walk along the constraint away from v until an input vertex.
        const CDT::Vertex_handle next = e->first->vertex(CDT::cw(e->second)) == v ? e->first->vertex(CDT::ccw(e->second))
                                                                                 : e->first->vertex(CDT::cw(e->second));
        ends.push_back(walk_constraint(cdt, v, next));
      }
    } while (++e != done && ends.size() < 2);
    if (ends.size() != 2 || ends[0]->info().loop < 0 || ends[0]->info().loop != ends[1]->info().loop) continue;
    const int l = ends[0]->info().loop;
    const std::size_t n = loops[static_cast<std::size_t>(l)].size();
    std::size_t a = ends[0]->info().index, b = ends[1]->info().index;
    if ((a + 1) % n != b) std::swap(a, b);
    if ((a + 1) % n != b) continue;
    const Point_2<double>& pa = loops[static_cast<std::size_t>(l)][a];
    const Point_2<double>& pb = loops[static_cast<std::size_t>(l)][b];
    const double dx = pb.x - pa.x, dy = pb.y - pa.y;
    Domain_vertex& dv = out.vertices[i];
    dv.segment_loop = l, dv.segment = a;
    dv.t = std::clamp(((dv.uv.x - pa.x) * dx + (dv.uv.y - pa.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  }
}

}  // namespace internal

/// \brief Triangulates the region of odd nesting depth of `loops` (each a
/// closed polyline, last point != first) by constrained Delaunay refinement
/// (Ruppert; CGAL::Delaunay_mesher_2 with Delaunay_mesh_size_criteria_2).
/// \throws Invalid_input for a loop of fewer than 3 points, non-finite
/// points, repeated points, or crossing loops.
inline Domain_mesh mesh_domain(const std::vector<std::vector<Point_2<double>>>& loops,
                               const Domain_mesh_options& options = {}) {
  using namespace internal;
  Mesh_2_cdt cdt;
  insert_loops(cdt, loops);
  mark_odd_depth_faces(cdt);
  using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Mesh_2_cdt>;
  CGAL::Delaunay_mesher_2<Mesh_2_cdt, Criteria> mesher(cdt, Criteria(options.shape_bound, options.max_edge_length));
  mesher.init(true);  // keep our marks (the infinite component stays outside)
  mesher.refine_mesh();
  std::unordered_map<Mesh_2_cdt::Vertex_handle, Index> id;
  Domain_mesh out = domain_triangles(cdt, id);
  locate_steiner_points(cdt, id, loops, out);
  return out;
}

}  // namespace relgeo
