// relgeo/boolean/internal/labelling.h — which pieces of one operand lie
// inside, outside or on the other: one decision per patch (the pieces between
// intersection curves), spread to the patch.
//
// A patch that meets a curve is decided at one of its curve edges e = (u, w)
// by the other operand's two pieces around e, whose planes are the planes of
// their input faces (explicit: the fast predicates on implicit points). With
// b1 = (u, w, y1) and b2 = (w, u, y2) the other operand's pieces on e
// (outward oriented), and x the third point of the patch's piece on e, x lies
// locally inside the other solid iff it is below both planes of a convex edge
// (y2 below b1's plane), below one of them at a concave edge, below the
// common plane at a flat one. A patch that meets no curve is decided by a
// ray from one of its input vertices: the parity of the other operand's faces
// crossed, every crossing decided exactly (a ray through an edge or vertex is
// cast again in another direction).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

/// Where a piece lies relative to the other operand.
enum class Piece_label : std::uint8_t {
  unknown,
  outside,
  inside,
  on_same,      ///< on the other's boundary, same orientation (coplanar overlap)
  on_opposite,  ///< on the other's boundary, opposite orientation
};

/// Pieces of one operand: triangles of global point indices, each with the
/// input face it comes from.
struct Pieces {
  std::vector<Triangle> triangles;
  std::vector<Index> input_face;
};

/// Set of undirected edges (the intersection curves).
class Edge_set {
 public:
  void insert(Index u, Index w) { set_.push_back(key(u, w)); }
  void finish() {
    std::sort(set_.begin(), set_.end());
    set_.erase(std::unique(set_.begin(), set_.end()), set_.end());
  }
  bool contains(Index u, Index w) const { return std::binary_search(set_.begin(), set_.end(), key(u, w)); }
  std::size_t size() const { return set_.size(); }
  std::vector<Edge> edges() const {
    std::vector<Edge> out;
    for (std::uint64_t k : set_) out.push_back({static_cast<Index>(k >> 32), static_cast<Index>(k & 0xFFFFFFFFu)});
    return out;
  }

 private:
  static std::uint64_t key(Index u, Index w) {
    const Index a = std::min(u, w), b = std::max(u, w);
    return (std::uint64_t{a} << 32) | b;
  }
  std::vector<std::uint64_t> set_;
};

/// Patches of pieces: components across edges that are not curve edges,
/// through the pieces' half-edge topology. Returns the patch of each piece
/// and the number of patches.
inline std::pair<std::vector<Index>, Index> patches(const Mesh_topology& topology, const Edge_set& curves) {
  const std::size_t n = topology.number_of_faces();
  std::vector<Index> patch(n, invalid_index);
  Index count = 0;
  std::vector<Index> stack;
  for (Index s = 0; s < n; ++s) {
    if (patch[s] != invalid_index) continue;
    patch[s] = count;
    stack.push_back(s);
    while (!stack.empty()) {
      const Index t = stack.back();
      stack.pop_back();
      for (Index h = 3 * t; h < 3 * t + 3; ++h) {
        const Index o = topology.opposite(h);
        if (o == invalid_index || patch[o / 3] != invalid_index) continue;
        if (curves.contains(topology.source(h), topology.target(h))) continue;
        patch[o / 3] = count;
        stack.push_back(o / 3);
      }
    }
    ++count;
  }
  return {patch, count};
}

}  // namespace relgeo::internal
