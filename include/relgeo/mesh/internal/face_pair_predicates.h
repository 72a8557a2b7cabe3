// relgeo/mesh/internal/face_pair_predicates.h — whether two faces of a mesh
// meet beyond what they share, and how a segment crosses a face, from the
// kernel's orientation predicates only (exact under exact kernels; an
// `uncertain` sign makes the answer empty, never wrong).
//
// Two non-degenerate triangles sharing
//  * no vertex meet iff the closed triangles intersect; after the usual
//    rejection by the orientations of each triangle's corners against the
//    other's plane, triangles whose planes cross are decided by two more
//    orientations (Guigue-Devillers: intersection/internal/cut_overlap.h),
//    coplanar ones by whether an edge of one meets the other (their common
//    part is convex, and its extreme points lie on edges).
//  * one vertex v, T1 = (v, a1, a2) and T2 = (v, b1, b2), meet beyond v iff
//    [a1, a2] meets T2 or [b1, b2] meets T1: T1 and T2 are convex, so if they
//    share a point other than v, the farthest point from v of their common
//    convex part lies on the boundary of one of them away from v, i.e. on an
//    opposite edge (or on an edge through v collinear with an edge of the
//    other, whose nearer end is then an opposite-edge endpoint in the other);
//  * an edge (u, w), T1 = (u, w, a) and T2 with third vertex b, meet beyond
//    the edge iff a and b lie in one plane with the edge and on the same side
//    of it (folded onto each other): otherwise the planes meet in the edge's
//    line, which each triangle meets in the edge only;
//  * three vertices coincide as sets: they meet everywhere.
// The same characterisation as CGAL's Polygon_mesh_processing::
// self_intersections (do_faces_intersect), written on orientations only.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <type_traits>

#include "relgeo/core/certified_sign.h"
#include "relgeo/intersection/internal/cut_overlap.h"
#include "relgeo/kernel/internal/orientation_against.h"
#include "relgeo/mesh/internal/embedded_stars.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

/// Certain true/false, or empty (undecided).
using Maybe = std::optional<bool>;

inline Maybe maybe_or(Maybe x, Maybe y) {
  if ((x && *x) || (y && *y)) return true;
  if (x && y) return false;
  return std::nullopt;
}

/// Whether the closed segment [p, q] meets the closed triangle (a, b, c),
/// given sp = orientation(a, b, c, p) and sq = orientation(a, b, c, q).
/// \pre p != q, the triangle is not degenerate.
template <class K>
Maybe segment_meets_triangle(const K& k, const typename K::Point_3& p, const typename K::Point_3& q,
                             const typename K::Point_3& a, const typename K::Point_3& b, const typename K::Point_3& c,
                             Certified_sign sp, Certified_sign sq) {
  const auto orient = k.orientation_3_object();
  const auto strict = [](Certified_sign s) {
    return certainly(s, Certified_sign::positive) || certainly(s, Certified_sign::negative);
  };
  if (strict(sp) && sp == sq) return false;  // one side of the plane
  if (!is_certain(sp) || !is_certain(sq)) return std::nullopt;
  if (certainly(sp, Certified_sign::zero) && certainly(sq, Certified_sign::zero)) {
    // In the triangle's plane: separated by an edge line of the triangle
    // (both ends strictly outside it) or by the segment's line (the three
    // corners strictly on one side), the axes of the 2D separation theorem.
    const auto side = k.coplanar_orientation_3_object();
    bool unknown = false;
    const std::array<const typename K::Point_3*, 3> t{&a, &b, &c};
    for (int e = 0; e < 3; ++e) {
      const auto& u = *t[e];
      const auto& v = *t[(e + 1) % 3];
      const auto& w = *t[(e + 2) % 3];
      const Certified_sign s0 = side(u, v, w, p), s1 = side(u, v, w, q);
      if (certainly(s0, Certified_sign::negative) && certainly(s1, Certified_sign::negative)) return false;
      unknown = unknown || !is_certain(s0) || !is_certain(s1);
    }
    const Certified_sign o0 = side(p, q, a), o1 = side(p, q, b), o2 = side(p, q, c);
    if (strict(o0) && o0 == o1 && o1 == o2) return false;
    if (unknown || !is_certain(o0) || !is_certain(o1) || !is_certain(o2)) return std::nullopt;
    return true;
  }
  // The segment reaches the plane in one point; the line through it meets
  // the closed triangle iff its orientations against the edges do not take
  // both strict signs.
  const Certified_sign s[3] = {orient(p, q, a, b), orient(p, q, b, c), orient(p, q, c, a)};
  bool positive = false, negative = false, unknown = false;
  for (Certified_sign x : s) {
    positive = positive || certainly(x, Certified_sign::positive);
    negative = negative || certainly(x, Certified_sign::negative);
    unknown = unknown || !is_certain(x);
  }
  if (positive && negative) return false;
  if (unknown) return std::nullopt;
  return true;
}

inline bool strictly_signed(Certified_sign s) {
  return certainly(s, Certified_sign::positive) || certainly(s, Certified_sign::negative);
}

/// Nearly parallel triangles (double coordinates whose normals, computed in
/// doubles, are within about a degree) are certainly disjoint when, in the
/// axis projection along the largest component of the first normal, the line
/// of an edge of one strictly separates the other: a point they shared would
/// project into both images. Decides the nearly coplanar pairs of a rounded
/// planar region from 2D signs, where the 3D orientations need exact
/// arithmetic; false (no decision) otherwise.
template <class K>
bool separated_in_projection(const K& k, const std::array<const typename K::Point_3*, 3>& a,
                             const std::array<const typename K::Point_3*, 3>& b) {
  using A = Point_access<typename K::Point_3>;
  if constexpr (!std::is_same_v<std::remove_cvref_t<typename A::FT>, double>) {
    return false;
  } else {
    const auto normal = [](const std::array<const typename K::Point_3*, 3>& t) {
      const double ux = A::x(*t[1]) - A::x(*t[0]), uy = A::y(*t[1]) - A::y(*t[0]), uz = A::z(*t[1]) - A::z(*t[0]);
      const double vx = A::x(*t[2]) - A::x(*t[0]), vy = A::y(*t[2]) - A::y(*t[0]), vz = A::z(*t[2]) - A::z(*t[0]);
      return std::array<double, 3>{uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
    };
    const std::array<double, 3> na = normal(a), nb = normal(b);
    const double dot = na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2];
    const double la2 = na[0] * na[0] + na[1] * na[1] + na[2] * na[2];
    const double lb2 = nb[0] * nb[0] + nb[1] * nb[1] + nb[2] * nb[2];
    // |cos| >= 0.9998, squared (no square roots on the path of most pairs,
    // which are not nearly parallel); a wrong guess costs time only.
    if (!(dot * dot >= 0.99960004 * la2 * lb2) || !(la2 > 0)) return false;
    const double ax = std::abs(na[0]), ay = std::abs(na[1]), az = std::abs(na[2]);
    const int plane = az >= ax && az >= ay ? 0 : (ax >= ay ? 1 : 2);  // xy, yz or zx (project_to_plane)
    const auto orient = k.orientation_2_object();
    using P2 = typename K::Point_2;
    const std::array<P2, 3> pa{project_to_plane<K>(*a[0], plane), project_to_plane<K>(*a[1], plane),
                               project_to_plane<K>(*a[2], plane)};
    const std::array<P2, 3> pb{project_to_plane<K>(*b[0], plane), project_to_plane<K>(*b[1], plane),
                               project_to_plane<K>(*b[2], plane)};
    const auto edge_separates = [&](const std::array<P2, 3>& t, const std::array<P2, 3>& other) {
      for (int i = 0; i < 3; ++i) {
        const Certified_sign own = orient(t[i], t[(i + 1) % 3], t[(i + 2) % 3]);
        if (!strictly_signed(own)) return false;  // the projection flattens t: no decision
        bool all_opposite = true;
        for (int j = 0; j < 3 && all_opposite; ++j) {
          const Certified_sign s = orient(t[i], t[(i + 1) % 3], other[j]);
          all_opposite = strictly_signed(s) && s != own;
        }
        if (all_opposite) return true;
      }
      return false;
    };
    return edge_separates(pa, pb) || edge_separates(pb, pa);
  }
}

/// Whether the closed triangles a and b intersect. \pre neither is degenerate.
template <class K>
Maybe triangles_meet(const K& k, const std::array<const typename K::Point_3*, 3>& a,
                     const std::array<const typename K::Point_3*, 3>& b) {
  if (separated_in_projection(k, a, b)) return false;
  const auto orient = k.orientation_3_object();
  const auto one_side = [](const std::array<Certified_sign, 3>& s) {
    return s[0] == s[1] && s[1] == s[2] &&
           (certainly(s[0], Certified_sign::positive) || certainly(s[0], Certified_sign::negative));
  };
  std::array<Certified_sign, 3> sb, sa;
  const auto against_a = orientation_against(k, *a[0], *a[1], *a[2]);
  for (int i = 0; i < 3; ++i) sb[i] = against_a(*b[i]);
  if (one_side(sb)) return false;
  const auto against_b = orientation_against(k, *b[0], *b[1], *b[2]);
  for (int i = 0; i < 3; ++i) sa[i] = against_b(*a[i]);
  if (one_side(sa)) return false;
  const auto decided = [](const std::array<Certified_sign, 3>& s) {
    return is_certain(s[0]) && is_certain(s[1]) && is_certain(s[2]);
  };
  // Planes that cross: two orientations compare the triangles' cuts along
  // their common line (on a gear's Boolean, 25,307 of 217,441 pairs got
  // here, each up to six segment tests of three orientations before).
  if (decided(sa) && decided(sb) && !all_zero(sa)) {
    const auto through = [&orient](const auto* p, const auto* q, const auto* r, const auto* s) {
      return orient(*p, *q, *r, *s);
    };
    if (const std::optional<bool> overlap = cuts_overlap(through, a, sa, b, sb)) return *overlap;
  }
  Maybe meet = false;
  for (int i = 0; i < 3 && !(meet && *meet); ++i) {
    const int j = (i + 1) % 3;
    meet = maybe_or(meet, segment_meets_triangle(k, *b[i], *b[j], *a[0], *a[1], *a[2], sb[i], sb[j]));
    meet = maybe_or(meet, segment_meets_triangle(k, *a[i], *a[j], *b[0], *b[1], *b[2], sa[i], sa[j]));
  }
  return meet;
}

/// Faces (v, a1, a2) and (v, b1, b2) sharing only v certainly meet in v
/// only when, in the first coordinate plane where both project with a
/// definite orientation, a line through v and a corner strictly separates
/// the other corners: a projection that keeps a face's orientation is one
/// to one on it, so a point shared beyond v would project into both images
/// beyond v's. Decides nearly coplanar neighbours (the pieces of one face
/// of a Boolean's operand) from well-conditioned 2D signs, where the 3D
/// orientations need exact arithmetic.
template <class K>
bool separated_around_vertex(const K& k, const typename K::Point_3& v, const typename K::Point_3& a1,
                             const typename K::Point_3& a2, const typename K::Point_3& b1,
                             const typename K::Point_3& b2) {
  const auto orient = k.orientation_2_object();
  for (int plane = 0; plane < 3; ++plane) {
    const auto pv = project_to_plane<K>(v, plane), pa1 = project_to_plane<K>(a1, plane),
               pa2 = project_to_plane<K>(a2, plane), pb1 = project_to_plane<K>(b1, plane),
               pb2 = project_to_plane<K>(b2, plane);
    if (!strictly_signed(orient(pv, pa1, pa2)) || !strictly_signed(orient(pv, pb1, pb2))) continue;
    // The line through v and `on` separates `alone` from `other1` and `other2`.
    const auto separates = [&](const auto& on, const auto& alone, const auto& other1, const auto& other2) {
      const Certified_sign s = orient(pv, on, alone);
      if (!strictly_signed(s)) return false;
      const Certified_sign t1 = orient(pv, on, other1), t2 = orient(pv, on, other2);
      return strictly_signed(t1) && t1 == t2 && t1 != s;
    };
    return separates(pa1, pa2, pb1, pb2) || separates(pa2, pa1, pb1, pb2) || separates(pb1, pb2, pa1, pa2) ||
           separates(pb2, pb1, pa1, pa2);
  }
  return false;
}

/// Faces sharing the edge (u, w), with third corners a and b, are certainly
/// not folded onto each other when some coordinate plane shows a and b
/// strictly on opposite sides of the edge (folded faces lie in one plane on
/// one side of it, and an axis projection keeps that, or flattens the
/// plane to a line).
template <class K>
bool opposite_across_edge(const K& k, const typename K::Point_3& u, const typename K::Point_3& w,
                          const typename K::Point_3& a, const typename K::Point_3& b) {
  const auto orient = k.orientation_2_object();
  for (int plane = 0; plane < 3; ++plane) {
    const auto pu = project_to_plane<K>(u, plane), pw = project_to_plane<K>(w, plane);
    const Certified_sign sa = orient(pu, pw, project_to_plane<K>(a, plane));
    if (!strictly_signed(sa)) continue;
    const Certified_sign sb = orient(pu, pw, project_to_plane<K>(b, plane));
    if (strictly_signed(sb)) return sb != sa;
  }
  return false;
}

/// Whether faces f and g (vertex indices, points through `point`) meet
/// other than in the vertices and edge they share (file comment).
/// \pre neither face is degenerate.
template <class K, class Points>
Maybe faces_meet_beyond_shared(const K& k, const Points& point, const Triangle& f, const Triangle& g) {
  int shared = 0, fi[3], gi[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (f[i] == g[j]) fi[shared] = i, gi[shared] = j, ++shared;
  switch (shared) {
    case 0:
      return triangles_meet(k, {&point[f[0]], &point[f[1]], &point[f[2]]}, {&point[g[0]], &point[g[1]], &point[g[2]]});
    case 1: {
      // The opposite corners of each face against the other's plane: when
      // those of one face lie strictly on one side, it meets the other's
      // plane in v only (decides most neighbours with two orientations).
      const int i = fi[0], j = gi[0];
      const auto& f0 = point[f[0]];
      const auto& f1 = point[f[1]];
      const auto& f2 = point[f[2]];
      const auto& g0 = point[g[0]];
      const auto& g1 = point[g[1]];
      const auto& g2 = point[g[2]];
      const auto& a1 = point[f[(i + 1) % 3]];
      const auto& a2 = point[f[(i + 2) % 3]];
      const auto& b1 = point[g[(j + 1) % 3]];
      const auto& b2 = point[g[(j + 2) % 3]];
      if (separated_around_vertex(k, point[f[i]], a1, a2, b1, b2)) return false;
      const auto against_f = orientation_against(k, f0, f1, f2);
      const Certified_sign sb1 = against_f(b1), sb2 = against_f(b2);
      if (strictly_signed(sb1) && sb1 == sb2) return false;
      const auto against_g = orientation_against(k, g0, g1, g2);
      const Certified_sign sa1 = against_g(a1), sa2 = against_g(a2);
      if (strictly_signed(sa1) && sa1 == sa2) return false;
      return maybe_or(segment_meets_triangle(k, a1, a2, g0, g1, g2, sa1, sa2),
                      segment_meets_triangle(k, b1, b2, f0, f1, f2, sb1, sb2));
    }
    case 2: {
      const Index u = f[fi[0]], w = f[fi[1]];
      const Index a = f[3 - fi[0] - fi[1]], b = g[3 - gi[0] - gi[1]];
      if (opposite_across_edge(k, point[u], point[w], point[a], point[b])) return false;
      const Certified_sign coplanar = k.orientation_3_object()(point[u], point[w], point[a], point[b]);
      if (certainly(coplanar, Certified_sign::positive) || certainly(coplanar, Certified_sign::negative)) return false;
      if (!is_certain(coplanar)) return std::nullopt;
      const Certified_sign same_side = k.coplanar_orientation_3_object()(point[u], point[w], point[a], point[b]);
      if (!is_certain(same_side)) return std::nullopt;
      return certainly(same_side, Certified_sign::positive);
    }
    default:
      return true;
  }
}

/// How the segment [p, q] crosses the triangle (a, b, c), for winding
/// numbers: +1 or -1 for a crossing through the open triangle (the sign of
/// orientation(a, b, c, q): +1 when q is on the side the triangle faces),
/// 0 when they do not meet at a point other than p or q off the triangle,
/// empty when the crossing is degenerate (through an edge or a vertex, or
/// the segment in the triangle's plane) or undecided.
/// \pre p and q do not lie on the triangle; it is not degenerate.
template <class K>
std::optional<int> segment_crossing(const K& k, const typename K::Point_3& p, const typename K::Point_3& q,
                                    const typename K::Point_3& a, const typename K::Point_3& b,
                                    const typename K::Point_3& c) {
  const auto orient = k.orientation_3_object();
  const Certified_sign sp = orient(a, b, c, p), sq = orient(a, b, c, q);
  if (!is_certain(sp) || !is_certain(sq)) return std::nullopt;
  if (certainly(sp, Certified_sign::zero) && certainly(sq, Certified_sign::zero)) return std::nullopt;  // in the plane
  // One end on the plane (off the triangle) or both on one side: no crossing.
  if (certainly(sp, Certified_sign::zero) || certainly(sq, Certified_sign::zero) || sp == sq) return 0;
  const Certified_sign s[3] = {orient(p, q, a, b), orient(p, q, b, c), orient(p, q, c, a)};
  bool positive = false, negative = false;
  for (Certified_sign x : s) {
    if (!is_certain(x)) return std::nullopt;
    positive = positive || certainly(x, Certified_sign::positive);
    negative = negative || certainly(x, Certified_sign::negative);
  }
  if (positive && negative) return 0;
  if (positive != negative && !certainly(s[0], Certified_sign::zero) && !certainly(s[1], Certified_sign::zero) &&
      !certainly(s[2], Certified_sign::zero))
    return certainly(sq, Certified_sign::positive) ? 1 : -1;
  return std::nullopt;  // through an edge or a vertex
}

}  // namespace relgeo::internal
