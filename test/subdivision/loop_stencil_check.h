// test/subdivision/loop_stencil_check.h — the check that one level of Loop
// refinement is, point for point, the Loop stencils applied to the input
// (exactly: for exact kernels), shared by the mask suite and the fuzz
// regressions.
#pragma once

#include <gtest/gtest.h>

#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/subdivision.h"

namespace relgeo_test {

/// Expects each vertex of r (m refined once by s) to equal its vertex or edge
/// stencil under s's weights applied to m's vertices.
template <class K>
void expect_refinement_is_the_stencils(relgeo::Loop_subdivider<K>& s, const relgeo::Triangle_mesh<typename K::Point_3>& m,
                                       const relgeo::Triangle_mesh<typename K::Point_3>& r) {
  using namespace relgeo;
  const Mesh_topology t = Mesh_topology::build(m);
  const Loop_features f = classify_loop_features(t, m.tags);
  for (Index v = 0; v < m.vertices.size(); ++v)
    EXPECT_EQ(apply_stencil(vertex_point_stencil(t, f, s.weights(), v), m.vertices), r.vertices[v]) << "vertex " << v;
  for (Index e = 0; e < t.number_of_edges(); ++e)
    EXPECT_EQ(apply_stencil(edge_point_stencil(t, f, s.weights(), e), m.vertices), r.vertices[m.vertices.size() + e])
        << "edge " << e;
}

}  // namespace relgeo_test
