// relgeo/intersection/internal/cut_overlap.h — whether two triangles whose
// planes cross meet, from two orientations more than their corners' signs
// against each other's plane (Guigue and Devillers, "Fast and robust
// triangle-triangle overlap test using orientation predicates", J. Graphics
// Tools 8, 2003).
//
// Each triangle cuts the other's plane along a segment of the planes' common
// line; after the normalisation below, two orientations of input corners
// compare the segments' ends along that line, which decides their overlap
// without building a point. Used by intersect_triangles (which builds the
// points only for pairs that meet), do_intersect_triangles and the face pair
// test of the self-intersection search (mesh/internal/face_pair_predicates.h).
// Checked against CGAL's Epeck on 10^6 pairs of random, near-degenerate,
// touching and coplanar triangles (TriangleIntersectionCgal) and on triangles
// with integer corners in {0..3}^3, where corners on the other's plane abound.
#pragma once

#include <algorithm>
#include <array>
#include <optional>
#include <utility>

#include "relgeo/core/certified_sign.h"

namespace relgeo::internal {

/// Every sign certainly zero: a triangle in the other's plane (with its
/// other signs decided, the two are coplanar).
inline bool all_zero(const std::array<Certified_sign, 3>& s) {
  return certainly(s[0], Certified_sign::zero) && certainly(s[1], Certified_sign::zero) &&
         certainly(s[2], Certified_sign::zero);
}

// Vertex i alone: strictly on the positive side with the others on the
// plane or below, or on the plane with both others strictly below. (With
// two vertices on the plane, the alone vertex must be the third: its two
// edges then cut the plane at those two vertices. Taking a vertex on the
// plane, one of its edges would lie in the plane and the cut interval
// would shrink to a point; found by fuzz/triangle_intersection.)
inline bool alone_at(const std::array<Certified_sign, 3>& s, int i) {
  const Certified_sign p = s[(i + 1) % 3], q = s[(i + 2) % 3];
  if (certainly(s[i], Certified_sign::zero))
    return certainly(p, Certified_sign::negative) && certainly(q, Certified_sign::negative);
  const auto le0 = [](Certified_sign x) { return !certainly(x, Certified_sign::positive); };
  return certainly(s[i], Certified_sign::positive) && le0(p) && le0(q);
}

// t's vertices rotated so that t[0] is alone (>= 0, the others <= 0),
// flipping the other plane (swapping o[1], o[2], which negates t's signs and
// swaps the other's signs) when no vertex is alone.
template <class Triangle>
void normalise(Triangle& t, std::array<Certified_sign, 3>& st, Triangle& o, std::array<Certified_sign, 3>& so) {
  for (int flip = 0; flip < 2; ++flip) {
    for (int i = 0; i < 3; ++i)
      if (alone_at(st, i)) {
        std::rotate(t.begin(), t.begin() + i, t.end());
        std::rotate(st.begin(), st.begin() + i, st.end());
        return;
      }
    std::swap(o[1], o[2]);
    std::swap(so[1], so[2]);
    for (auto& x : st) x = -x;
  }
}

/// Whether closed triangles a and b meet: `sa` are the signs of a's corners
/// against b's plane (orient3(b0, b1, b2, a_i)), `sb` those of b's against
/// a's, all decided, neither triangle strictly on one side, not coplanar.
/// Empty when an orientation is undecided. `orient3(p, q, r, s)` is the
/// kernel's orientation of the corners (any type the triangles hold: points,
/// or pointers to them with an orientation that reads through them).
template <class Orientation_3, class Triangle>
std::optional<bool> cuts_overlap(const Orientation_3& orient3, Triangle a, std::array<Certified_sign, 3> sa, Triangle b,
                                 std::array<Certified_sign, 3> sb) {
  // Normalise: a[0] alone on the nonnegative side of b's plane, a[1], a[2]
  // on the nonpositive side (flipping b's plane by swapping b[1], b[2] if
  // needed); then the same for b against a's plane (swapping a[1], a[2]).
  normalise(a, sa, b, sb);
  normalise(b, sb, a, sa);
  // The cuts [i, j] of a (on edges a0a1, a0a2) and [k, l] of b (on b0b1,
  // b0b2) lie on the common line; these orientations compare i with k and
  // j with l along it, which decides their overlap.
  const Certified_sign c1 = orient3(a[0], a[1], b[0], b[1]);
  const Certified_sign c2 = orient3(a[0], a[2], b[2], b[0]);
  if (!is_certain(c1) || !is_certain(c2)) return std::nullopt;
  return !certainly(c1, Certified_sign::positive) && !certainly(c2, Certified_sign::positive);
}

}  // namespace relgeo::internal
