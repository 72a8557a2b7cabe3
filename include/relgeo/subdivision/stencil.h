// relgeo/subdivision/stencil.h — a mask as an explicit list of weighted
// vertices, and its application to a point list.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "relgeo/kernel/point.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// An affine (weights sum to 1) or vector (weights sum to 0) mask.
template <class FT>
struct Stencil {
  std::vector<Index> vertices;
  std::vector<FT> weights;
  void add(Index v, FT w) {
    vertices.push_back(v);
    weights.push_back(std::move(w));
  }
  void clear() {
    vertices.clear();
    weights.clear();
  }
};

/// sum w_i p_i, coordinate-wise in FT, as relgeo::Point_3<FT> (for a vector
/// stencil: the vector's coordinates).
template <class FT, class P>
Point_3<FT> apply_stencil(const Stencil<FT>& s, const std::vector<P>& points) {
  using A = internal::Point_access<P>;
  Point_3<FT> r{FT(0), FT(0), FT(0)};
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    const P& p = points[s.vertices[i]];
    r.x = FT(r.x + FT(s.weights[i] * A::x(p)));
    r.y = FT(r.y + FT(s.weights[i] * A::y(p)));
    r.z = FT(r.z + FT(s.weights[i] * A::z(p)));
  }
  return r;
}

}  // namespace relgeo
