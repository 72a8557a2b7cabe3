// relgeo/mesh/internal/component_winding.h — for each connected component
// C of a closed, oriented mesh without self-intersections, the winding
// number W_C of all the other components around C (at one of C's
// vertices), decided exactly.
//
// Why it decides orientation. The components are disjoint closed embedded
// surfaces, so each other component D has a winding number w_D in {0, s_D}
// (s_D = the sign of D's signed volume) constant on C, and W_C = sum of w_D.
// Just outside C the mesh's winding number is W_C, just inside W_C + s_C.
// The mesh is the outward boundary of a solid (winding number 1 inside, 0
// outside) iff for every C: W_C = 0 and s_C = +1 (an outer shell) or
// W_C = 1 and s_C = -1 (a cavity).
//
// How. W_C is the signed count of crossings of a segment from a vertex p of
// C to a point q outside the mesh's box with the faces of the other
// components (+1 where the segment leaves a face's back side). Each crossing
// is decided by orientations (internal/face_pair_predicates.h); a segment
// through an edge or a vertex, or lying in a face's plane, is degenerate
// and another direction is tried (under an exact kernel the degenerate
// directions are a set of measure zero; under a fail-safe kernel an
// uncertain sign also moves on). The faces tested are those whose box the
// segment meets (Face_bvh).
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "relgeo/core/number_traits.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/internal/face_pair_predicates.h"
#include "relgeo/mesh/internal/mesh_components.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

/// W_C of every component (empty where every direction tried was
/// degenerate or undecided). \pre the mesh is as the file comment says;
/// `point` are its vertices as K's points, `bvh` over its faces.
template <class K, class P, class Points>
std::vector<std::optional<int>> component_windings(const K& k, const Triangle_mesh<P>& m, const Points& point,
                                                   const Face_bvh& bvh, const Face_components& comps,
                                                   int directions = 16) {
  using A = Point_access<P>;
  std::vector<std::optional<int>> winding(comps.size());
  if (comps.size() == 1) {
    winding[0] = 0;
    return winding;
  }
  const Box_3& box = bvh.bounds();
  double diagonal = 0;
  for (int i = 0; i < 3; ++i) diagonal += box.hi[i] - box.lo[i];
  const double length = 2 * diagonal + 1;
  const auto make = k.construct_point_3_object();
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  const auto uniform = [&state] {  // xorshift64*: a fixed sequence of directions
    state ^= state >> 12, state ^= state << 25, state ^= state >> 27;
    return double((state * 0x2545F4914F6CDD1Dull) >> 11) * 0x1p-53 * 2 - 1;
  };
  for (std::size_t c = 0; c < comps.size(); ++c) {
    const Index v = m.faces[comps.first_face[c]][0];
    const P& pv = m.vertices[v];
    const Point_3<double> p{nearest_double(A::x(pv)), nearest_double(A::y(pv)), nearest_double(A::z(pv))};
    const double slack = std::max({upper_double(A::x(pv)) - lower_double(A::x(pv)),
                                   upper_double(A::y(pv)) - lower_double(A::y(pv)),
                                   upper_double(A::z(pv)) - lower_double(A::z(pv))});
    for (int attempt = 0; attempt < directions && !winding[c]; ++attempt) {
      double d[3] = {uniform(), uniform(), uniform()};
      const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (!(norm > 0.1)) continue;
      const Point_3<double> q{p.x + length * d[0] / norm, p.y + length * d[1] / norm, p.z + length * d[2] / norm};
      const bool outside = q.x < box.lo[0] || q.x > box.hi[0] || q.y < box.lo[1] || q.y > box.hi[1] ||
                           q.z < box.lo[2] || q.z > box.hi[2];
      if (!outside) continue;
      const auto kq = make(q.x, q.y, q.z);
      int sum = 0;
      bool degenerate = false;
      bvh.for_each_face_on_segment(
          p, q,
          [&](Index f) {
            if (degenerate || comps.component[f] == c) return;
            const Triangle& t = m.faces[f];
            const std::optional<int> crossing = segment_crossing(k, point[v], kq, point[t[0]], point[t[1]], point[t[2]]);
            if (!crossing) degenerate = true;
            else sum += *crossing;
          },
          slack);
      if (!degenerate) winding[c] = sum;
    }
  }
  return winding;
}

}  // namespace relgeo::internal
