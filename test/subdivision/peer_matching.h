// test/subdivision/peer_matching.h — compare relgeo's refinement with a peer
// (CGAL, OpenMesh) level by level, whatever order the peer numbers its new
// vertices in: old vertices keep their index in every implementation; a new
// vertex is identified by its two neighbours of the previous level (the
// endpoints of the edge it splits).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <vector>

#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo_test {

/// What the comparison needs to know about the peer's mesh after a step.
struct Peer_view {
  std::size_t number_of_vertices;
  std::function<std::vector<std::size_t>(std::size_t)> neighbours;  // of a peer vertex
  std::vector<std::array<std::size_t, 3>> faces;                     // peer vertex indices
};

/// Maps peer vertex indices to relgeo's after one step from a level where the
/// map was `map` (peer -> relgeo) and relgeo's topology was `t`. Records a
/// test failure (and returns an empty map) when the structure differs.
inline std::vector<relgeo::Index> match_step(const std::vector<relgeo::Index>& map,
                                             const relgeo::Mesh_topology& t, const Peer_view& peer) {
  using relgeo::Index;
  const std::size_t old_n = map.size();
  std::vector<Index> next(peer.number_of_vertices, relgeo::invalid_index);
  for (std::size_t x = 0; x < peer.number_of_vertices; ++x) {
    if (x < old_n) {
      next[x] = map[x];
      continue;
    }
    std::vector<std::size_t> olds;
    for (std::size_t y : peer.neighbours(x))
      if (y < old_n) olds.push_back(y);
    if (olds.size() != 2) {
      ADD_FAILURE() << "peer vertex " << x << " has " << olds.size() << " old neighbours";
      return {};
    }
    const Index e = t.find_edge(map[olds[0]], map[olds[1]]);
    if (e == relgeo::invalid_index) {
      ADD_FAILURE() << "peer vertex " << x << " splits no relgeo edge";
      return {};
    }
    next[x] = static_cast<Index>(old_n + e);
  }
  return next;
}

/// The faces of both meshes are the same oriented triangles (under the map).
inline void expect_same_faces(const std::vector<relgeo::Index>& map, const Peer_view& peer,
                              const std::vector<relgeo::Triangle>& ours) {
  const auto normal = [](std::array<relgeo::Index, 3> f) {
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    return f;
  };
  std::set<std::array<relgeo::Index, 3>> a, b;
  for (const auto& f : ours) a.insert(normal({f[0], f[1], f[2]}));
  for (const auto& f : peer.faces) b.insert(normal({map[f[0]], map[f[1]], map[f[2]]}));
  EXPECT_EQ(a.size(), ours.size());
  EXPECT_TRUE(a == b) << "connectivity differs";
}

}  // namespace relgeo_test
