// relgeo/subdivision/internal/patch_classification.h — which faces of a Loop
// mesh are regular patches (box splines over 12 control points, ghost points
// across regular creases) and their control slots and nets.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "relgeo/kernel/point.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/box_spline.h"
#include "relgeo/subdivision/internal/loop_rules.h"
#include "relgeo/subdivision/internal/point_algebra.h"
#include "relgeo/subdivision/loop_patch_kind.h"
#include "relgeo/subdivision/loop_weights.h"

namespace relgeo::internal {

/// A control point of a regular patch: vertex a, or the ghost a + b - c.
struct Patch_slot {
  Index a = invalid_index, b = invalid_index, c = invalid_index;
  bool is_ghost() const { return b != invalid_index; }
  friend bool operator==(const Patch_slot&, const Patch_slot&) = default;
};

/// Whether the corner `corner` of face f is a regular vertex of the patch:
/// smooth of valence 6 whose edges all follow the standard rule, or a crease
/// vertex with 3 faces in the sector holding f.
inline bool patch_corner_is_regular(const Mesh_topology& t, const Loop_rule_data& d, const Loop_options& o,
                                    Index f, int corner) {
  const Index h = 3 * f + Index(corner), a = t.source(h);
  switch (d.kind[a]) {
    case Vertex_kind::smooth:
      return !t.is_boundary_vertex(a) && t.number_of_incident_faces(a) == 6 && standard_weights_around(t, d, o, a);
    case Vertex_kind::crease: return d.sector[h] == 3;
    default: return false;
  }
}

/// Classifies face f and, for regular ones, fills its 12 control slots
/// (box_spline.h order). A crease vertex's sector p_0..p_3 (3 faces) is
/// completed by the ghosts a + p_3 - p_2 and a + p_0 - p_1; a conflict
/// between the slots found from different corners (only in degenerate tiny
/// meshes) makes the patch irregular.
inline Loop_patch_kind classify_loop_patch(const Mesh_topology& t, const Loop_rule_data& d, const Loop_options& o,
                                           Index f, std::array<Patch_slot, 12>* slots) {
  for (int k = 0; k < 3; ++k)
    if (!patch_corner_is_regular(t, d, o, f, k)) return Loop_patch_kind::irregular;
  static constexpr int dirs[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
  static constexpr int start[3] = {0, 2, 4};
  std::array<Patch_slot, 12> s{};
  std::array<bool, 12> set{};
  bool any_crease = false;
  for (int k = 0; k < 3; ++k) {
    const Index h = 3 * f + Index(k), a = t.source(h);
    std::array<Patch_slot, 6> cycle;
    if (d.kind[a] == Vertex_kind::smooth) {
      Index g = h;
      for (int m = 0; m < 6; ++m, g = t.ccw_outgoing(g)) cycle[m] = Patch_slot{t.target(g)};
    } else {  // crease vertex, 3 faces in this sector
      any_crease = true;
      Index first = h;  // clockwise to the crease half-edge starting the sector
      for (int guard = 0; guard < 3 && !d.crease[first]; ++guard) first = Mesh_topology::next(t.opposite(first));
      if (!d.crease[first]) return Loop_patch_kind::irregular;
      std::array<Index, 4> p{};
      int pos = -1;
      Index g = first;
      for (int i = 0; i < 3; ++i) {
        if (g == invalid_index) return Loop_patch_kind::irregular;
        if (g == h) pos = i;
        p[i] = t.target(g);
        if (i == 2) p[3] = t.source(Mesh_topology::prev(g));
        g = t.ccw_outgoing(g);
      }
      if (pos < 0) return Loop_patch_kind::irregular;
      // ghosts with (a, b) sorted: the same ghost is found from both crease ends
      const auto ghost = [](Index x, Index y, Index z) { return Patch_slot{std::min(x, y), std::max(x, y), z}; };
      const std::array<Patch_slot, 6> sector{{{p[0]}, {p[1]}, {p[2]}, {p[3]}, ghost(a, p[3], p[2]), ghost(a, p[0], p[1])}};
      for (int m = 0; m < 6; ++m) cycle[m] = sector[(pos + m) % 6];
    }
    const int cx = k == 1 ? 1 : 0, cy = k == 2 ? 1 : 0;
    const auto put = [&](int x, int y, const Patch_slot& ps) {
      for (int i = 0; i < 12; ++i)
        if (loop_patch_lattice[i][0] == x && loop_patch_lattice[i][1] == y) {
          if (set[i] && !(s[i] == ps)) return false;
          s[i] = ps, set[i] = true;
          return true;
        }
      return false;  // unreachable: every neighbour of a corner is a slot
    };
    if (!put(cx, cy, Patch_slot{a})) return Loop_patch_kind::irregular;
    for (int m = 0; m < 6; ++m) {
      const int* dxy = dirs[(start[k] + m) % 6];
      if (!put(cx + dxy[0], cy + dxy[1], cycle[m])) return Loop_patch_kind::irregular;
    }
  }
  if (slots) *slots = s;
  return any_crease ? Loop_patch_kind::regular_crease : Loop_patch_kind::regular;
}

/// The dim values of a control slot: vertex a's, or the ghost's a + b - c.
/// value(v) points to the dim values of vertex v.
template <class FT, class Value>
void slot_values(const Patch_slot& s, std::size_t dim, Value&& value, FT* out) {
  const FT* a = value(s.a);
  if (!s.is_ghost()) {
    for (std::size_t d = 0; d < dim; ++d) out[d] = a[d];
    return;
  }
  const FT *b = value(s.b), *c = value(s.c);
  for (std::size_t d = 0; d < dim; ++d) out[d] = FT(FT(a[d] + b[d]) - c[d]);
}

/// The 12 x dim control values of a regular patch (row-major), ghosts resolved.
template <class FT, class Value>
std::vector<FT> patch_net(const std::array<Patch_slot, 12>& s, std::size_t dim, Value&& value) {
  std::vector<FT> net(12 * dim);
  for (int i = 0; i < 12; ++i) slot_values(s[i], dim, value, net.data() + i * dim);
  return net;
}

/// The point of a control slot: the vertex's point itself, or the ghost
/// computed into `ghost`.
template <class FT>
const Point_3<FT>& slot_point(const Patch_slot& s, const std::vector<Point_3<FT>>& points, Point_3<FT>& ghost) {
  if (!s.is_ghost()) return points[s.a];
  ghost = point_difference(point_sum(points[s.a], points[s.b]), points[s.c]);
  return ghost;
}

}  // namespace relgeo::internal
