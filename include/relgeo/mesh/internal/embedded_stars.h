// relgeo/mesh/internal/embedded_stars.h — faces projected to the coordinate
// planes, and the vertices whose star such a projection maps one to one:
// the self-intersection test's certificate for neighbouring faces.
//
// Two faces that share a vertex v are most of the candidate pairs of a
// self-intersection test (about 120K of 124K on a 20K-face sphere), each
// decided by two or more orientation predicates. One test per vertex
// decides them all at once. Let the faces around an interior vertex v of an
// oriented 2-manifold project along a coordinate axis with the same strict
// orientation, and let the link (the closed polygon of the edges opposite
// v) wind once around the projection v' of v. Then the projected faces are
// wedges at v' with positive angles summing to 2 pi: they tile the plane
// around v' without overlap, two of them meeting in v' alone or, when
// consecutive, in their common edge. The projection is one to one on each
// face (non-degenerate in the plane), so two faces of the star that met
// beyond what they share would project to a common point beyond the
// projection of that part: they do not meet beyond it.
//
// Everything is decided by the kernel's predicates on the exact projected
// coordinates (dropping a coordinate is exact): the orientations of the
// projected faces and, for the winding number (Sunday's crossing rule on
// the ray from v' along the first axis: an edge counts when it crosses the
// line of v' upward with v' strictly to its left, or downward with v'
// strictly to its right), comparisons of one coordinate. An uncertain
// answer leaves the vertex uncertified; its pairs are then tested one by
// one.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

/// The three coordinate planes, each with its two coordinates in order: xy,
/// yz and zx (the orientation of a face projected to plane p is the sign of
/// its normal's z, x or y component).
template <class K>
typename K::Point_2 project_to_plane(const typename K::Point_3& p, int plane) {
  using A = Point_access<typename K::Point_3>;
  using P2 = typename K::Point_2;
  switch (plane) {
    case 0: return P2{A::x(p), A::y(p)};
    case 1: return P2{A::y(p), A::z(p)};
    default: return P2{A::z(p), A::x(p)};
  }
}

/// The orientation of face t projected to coordinate plane `plane`.
template <class K, class Points>
Certified_sign projected_orientation(const K& k, const Points& point, const Triangle& t, int plane) {
  return k.orientation_2_object()(project_to_plane<K>(point[t[0]], plane), project_to_plane<K>(point[t[1]], plane),
                                  project_to_plane<K>(point[t[2]], plane));
}

/// The orientation of every face projected to each coordinate plane.
/// Faces with a repeated vertex get `zero` in all three. Without
/// `every_plane` a face's planes after its first strict sign are left
/// `uncertain` (not computed): enough to tell degenerate faces, not for
/// embedded_star_flags (whose stars of such faces are then not certified).
/// `every_plane_of`, when given, asks every plane of the faces it flags only.
template <class K, class Points>
std::vector<std::array<Certified_sign, 3>> projected_orientations(
    const K& k, const Points& point, const std::vector<Triangle>& faces, bool every_plane = true,
    const std::vector<unsigned char>* every_plane_of = nullptr) {
  std::vector<std::array<Certified_sign, 3>> s(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Triangle& t = faces[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      s[f].fill(Certified_sign::zero);
      continue;
    }
    s[f].fill(Certified_sign::uncertain);
    for (int plane = 0; plane < 3; ++plane) {
      s[f][plane] = projected_orientation(k, point, t, plane);
      if (!(every_plane && (!every_plane_of || (*every_plane_of)[f])) &&
          (certainly(s[f][plane], Certified_sign::positive) || certainly(s[f][plane], Certified_sign::negative)))
        break;
    }
  }
  return s;
}

/// The planes in which a face projects with a strict orientation: bit p
/// for positive in plane p, bit 3 + p for negative (0 for a face left out).
inline unsigned char strict_sign_bits(const std::array<Certified_sign, 3>& projected) {
  unsigned char bits = 0;
  for (int plane = 0; plane < 3; ++plane) {
    if (certainly(projected[plane], Certified_sign::positive)) bits |= static_cast<unsigned char>(1u << plane);
    if (certainly(projected[plane], Certified_sign::negative)) bits |= static_cast<unsigned char>(8u << plane);
  }
  return bits;
}

/// Sunday's crossing rule (file comment) for the link edge (a, b) of v in
/// `plane` (0-2) of a star whose faces all project counterclockwise
/// (`left`: v' is left of every link edge) or all clockwise: whether the
/// edge counts as a crossing of the ray from v'; empty when a comparison
/// is uncertain.
template <class K>
std::optional<bool> link_edge_crosses(const K& k, const typename K::Point_3& v, const typename K::Point_3& a,
                                      const typename K::Point_3& b, int plane, bool left) {
  using A = Point_access<typename K::Point_3>;
  using P2 = typename K::Point_2;
  const auto compare = k.compare_xy_2_object();
  // The sign of u's second coordinate in `plane` minus v's (P2{w, w}
  // compares w alone through the kernel's lexicographic comparison).
  const auto compare_second = [&](const typename K::Point_3& u) {
    switch (plane) {
      case 0: return compare(P2{A::y(u), A::y(u)}, P2{A::y(v), A::y(v)});
      case 1: return compare(P2{A::z(u), A::z(u)}, P2{A::z(v), A::z(v)});
      default: return compare(P2{A::x(u), A::x(u)}, P2{A::x(v), A::x(v)});
    }
  };
  const Certified_sign ca = compare_second(a), cb = compare_second(b);
  if (!is_certain(ca) || !is_certain(cb)) return std::nullopt;
  const bool a_above = certainly(ca, Certified_sign::positive), b_above = certainly(cb, Certified_sign::positive);
  return left ? (!a_above && b_above) : (a_above && !b_above);
}

/// For each vertex, 1 when its star is certified embedded by a projection
/// (file comment), 0 otherwise; `projected` computed on every plane. `skip`:
/// faces left out of the test (degenerate or undecided); a vertex of one is
/// not certified. `patch`, when given, puts faces in groups whose pairs are
/// decided otherwise (projected_patches.h): a vertex whose faces are all in
/// one is not tried.
/// \pre `t` is the topology of `faces`, an edge- and vertex-manifold,
/// consistently oriented mesh (boundary vertices are never certified).
template <class K, class Points>
std::vector<unsigned char> embedded_star_flags(const K& k, const Points& point, const std::vector<Triangle>& faces,
                                               const std::vector<std::array<Certified_sign, 3>>& projected,
                                               const std::vector<unsigned char>& skip, const Mesh_topology& t,
                                               const std::vector<std::uint16_t>* patch = nullptr) {
  const std::size_t nv = t.number_of_vertices();
  // Per vertex: the planes in which every face around it projects with
  // positive (bits 0-2) or negative (bits 3-5) orientation.
  std::vector<unsigned char> same(nv, 63);
  // The patch of every face around each vertex (0: none or several; unset
  // for a vertex of no face).
  constexpr std::uint32_t unset = 0xFFFFFFFFu;
  std::vector<std::uint32_t> one_patch(patch ? nv : 0, unset);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const unsigned char bits = skip[f] ? 0 : strict_sign_bits(projected[f]);
    for (Index v : faces[f]) {
      same[v] &= bits;
      if (patch) one_patch[v] = one_patch[v] == unset || one_patch[v] == (*patch)[f] ? (*patch)[f] : 0;
    }
  }
  if (patch)
    for (Index v = 0; v < nv; ++v)
      if (one_patch[v] != unset && one_patch[v] != 0) same[v] = 0;
  // One such plane per vertex (the first), and the link's crossings of the
  // line of v' in it: upward (counted when v' is left of every link edge)
  // or downward (right of every one), saturating at 2.
  std::vector<signed char> plane_of(nv, -1);
  for (Index v = 0; v < nv; ++v)
    if (same[v] && !t.is_isolated(v) && !t.is_boundary_vertex(v))
      plane_of[v] = static_cast<signed char>(std::countr_zero(static_cast<unsigned>(same[v])));  // 0-5
  std::vector<unsigned char> crossings(nv, 0);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Triangle& tri = faces[f];
    for (int i = 0; i < 3; ++i) {
      const Index v = tri[i];
      if (plane_of[v] < 0) continue;
      const std::optional<bool> crosses = link_edge_crosses(k, point[v], point[tri[(i + 1) % 3]],
                                                            point[tri[(i + 2) % 3]], plane_of[v] % 3, plane_of[v] < 3);
      if (!crosses) {
        plane_of[v] = -1;
        continue;
      }
      if (*crosses) crossings[v] = static_cast<unsigned char>(std::min(crossings[v] + 1, 2));
    }
  }
  // Winding number 1 (or -1 for a clockwise projection).
  std::vector<unsigned char> embedded(nv, 0);
  for (Index v = 0; v < nv; ++v) embedded[v] = plane_of[v] >= 0 && crossings[v] == 1;
  return embedded;
}

/// The same certificate for one vertex v from its star alone, for a mesh
/// whose topology is not built (the rounding repair's): `star` lists every
/// face around v, `projected(f)` gives a face's orientations in the three
/// planes. The faces must form one closed fan: the link edges (a, b) of
/// the faces (v, a, b) make one cycle through all of them, each link vertex
/// starting one edge and ending one. That is what an interior vertex of a
/// consistently oriented 2-manifold has, whatever the mesh is elsewhere,
/// and all the file comment's argument uses.
template <class K, class Points, class Projected>
bool star_embedded(const K& k, const Points& point, const std::vector<Triangle>& faces, Index v,
                   std::span<const Index> star, Projected&& projected) {
  constexpr std::size_t most = 64;  // a longer star is left to the pair tests
  const std::size_t n = star.size();
  if (n < 3 || n > most) return false;
  std::array<Index, most> from, to;
  unsigned char same = 63;
  for (std::size_t i = 0; i < n; ++i) {
    const Triangle& t = faces[star[i]];
    const int at = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    from[i] = t[(at + 1) % 3], to[i] = t[(at + 2) % 3];
    if (from[i] == v || to[i] == v) return false;  // a repeated vertex
    same &= strict_sign_bits(projected(star[i]));
  }
  if (!same) return false;
  // One cycle: from each edge to the only one starting where it ends (so
  // no link vertex starts two edges), back to the first after all of them.
  std::size_t at = 0, steps = 0;
  do {
    std::size_t next = n, starting = 0;
    for (std::size_t j = 0; j < n; ++j)
      if (from[j] == to[at]) next = j, ++starting;
    if (starting != 1) return false;
    at = next, ++steps;
  } while (at != 0 && steps < n);
  if (at != 0 || steps != n) return false;
  const int plane_bit = std::countr_zero(static_cast<unsigned>(same));
  int crossings = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::optional<bool> crosses =
        link_edge_crosses(k, point[v], point[from[i]], point[to[i]], plane_bit % 3, plane_bit < 3);
    if (!crosses) return false;
    crossings += *crosses;
  }
  return crossings == 1;
}

/// Whether faces f and g share a vertex whose star is certified embedded
/// (they then meet in nothing but what they share).
inline bool share_embedded_star(const Triangle& f, const Triangle& g, const std::vector<unsigned char>& embedded) {
  for (Index v : f)
    if (embedded[v] && (v == g[0] || v == g[1] || v == g[2])) return true;
  return false;
}

}  // namespace relgeo::internal
