// relgeo/mesh/internal/diagonal_separation.h — whether two faces with double
// coordinates are certainly disjoint because their extents along one of the
// six diagonal directions x+y, y+z, z+x, x-y, y-z, z-x do not overlap.
//
// A face hierarchy pairs faces whose axis-aligned boxes overlap. Long faces
// lying across the axes (a gear's teeth, turned by a rotation) have boxes far
// larger than themselves: of the 92,123 box pairs of the benchmark's gear
// against its moved copy, 67% are apart along a diagonal (the elephant 57%,
// the fandisk 47%); with the box, the 18-DOP of collision detection. Each
// face's six extents are computed once (about as long as two filtered
// orientations); a pair is then twelve comparisons of floats, where the
// predicates it spares take several orientations.
//
// Certified in every floating-point environment. A sum or difference of two
// doubles is off by less than 2^-52 of itself in any rounding mode, and by
// less than 2^-1021 where flush-to-zero or denormals-are-zero drop a
// subnormal; converting to float is off by one float step at most (2^-23 of
// itself, 2^-126 flushed). Each end moves outward by 2^-20 of itself plus
// 2^-120 before the conversion, more than all of that. Ends beyond 2^126 in
// magnitude become infinite, and so do all ends of a face with a NaN or an
// infinite coordinate: never separated.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

/// A face's extents along the six diagonal directions, outward in floats.
struct Diagonal_extents {
  std::array<float, 6> lo, hi;
};

/// The extents of the triangle with corners (x, y, z) a, b, c.
inline Diagonal_extents diagonal_extents(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                         const std::array<double, 3>& c) {
  constexpr float infinity = std::numeric_limits<float>::infinity();
  const auto below = [](double x) {
    const double moved = x - (std::abs(x) * 0x1p-20 + 0x1p-120);
    return std::abs(moved) < 0x1p126 ? static_cast<float>(moved) : -infinity;
  };
  const auto above = [](double x) {
    const double moved = x + (std::abs(x) * 0x1p-20 + 0x1p-120);
    return std::abs(moved) < 0x1p126 ? static_cast<float>(moved) : infinity;
  };
  Diagonal_extents e;
  // A face with a NaN or infinite coordinate is separated from nothing:
  // the predicates say what is wrong with it.
  bool finite = true;
  for (const auto* corner : {&a, &b, &c})
    for (double x : *corner) finite = finite && std::abs(x) <= std::numeric_limits<double>::max();
  if (!finite) {
    e.lo.fill(-infinity), e.hi.fill(infinity);
    return e;
  }
  for (int k = 0; k < 6; ++k) {
    const int i = k % 3, j = (k + 1) % 3;
    const double sign = k < 3 ? 1.0 : -1.0;  // exact: one rounding per value
    const double u = a[i] + sign * a[j], v = b[i] + sign * b[j], w = c[i] + sign * c[j];
    e.lo[k] = below(std::min({u, v, w}));
    e.hi[k] = above(std::max({u, v, w}));
  }
  return e;
}

/// The extents of face t, whose points have double x, y, z.
template <class Points>
Diagonal_extents diagonal_extents(const Points& point, const Triangle& t) {
  const auto corner = [&](Index v) { return std::array<double, 3>{point[v].x, point[v].y, point[v].z}; };
  return diagonal_extents(corner(t[0]), corner(t[1]), corner(t[2]));
}

/// True only if the two faces are disjoint (false decides nothing).
inline bool diagonally_separated(const Diagonal_extents& a, const Diagonal_extents& b) {
  int apart = 0;  // no branch per axis: bitwise on the comparisons
  for (int k = 0; k < 6; ++k) apart |= static_cast<int>(a.hi[k] < b.lo[k]) | static_cast<int>(b.hi[k] < a.lo[k]);
  return apart != 0;
}

/// The extents of a mesh's faces, each computed when first asked for (one
/// thread: the pair searches that use it read faces in no useful order).
template <class Points>
class Lazy_diagonal_extents {
 public:
  Lazy_diagonal_extents(const Points& point, const std::vector<Triangle>& faces)
      : point_(point), faces_(faces), extents_(faces.size()), known_(faces.size(), 0) {}
  const Diagonal_extents& operator[](Index f) {
    if (!known_[f]) extents_[f] = diagonal_extents(point_, faces_[f]), known_[f] = 1;
    return extents_[f];
  }
  bool separated(Index f, Index g) { return diagonally_separated((*this)[f], (*this)[g]); }

 private:
  const Points& point_;
  const std::vector<Triangle>& faces_;
  std::vector<Diagonal_extents> extents_;
  std::vector<unsigned char> known_;
};

}  // namespace relgeo::internal
