// relgeo's hulls against CGAL's on the same input: with exact predicates they
// must coincide (indices and order).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include "hull_inputs.h"
#include "relgeo/hull.h"
#include "relgeo/hull/cgal_convex_hull.h"
#include "relgeo/kernel.h"

namespace relgeo::test {
namespace {

TEST(HullCgalPeer, ExactPredicateHullsEqualCgalsHulls) {
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    const auto input = seed % 5 == 0 ? uniform_points(seed, 300) : near_degenerate_points(seed, static_cast<int>(seed % 4));
    const auto epick = to_kernel<Cgal_kernel<CGAL::Epick>>(input);
    const auto cgal = cgal_convex_hull<CGAL::Epick>(epick, Cgal_hull_algorithm::convex_hull_2).indices;
    EXPECT_EQ(cgal_convex_hull<CGAL::Epick>(epick, Cgal_hull_algorithm::graham_andrew).indices, cgal) << seed;
    EXPECT_EQ(graham_fortune<Filtered_exact_kernel>(input).indices, cgal) << seed;
    EXPECT_EQ(monotone_chain<Filtered_exact_kernel>(input).indices, cgal) << seed;
    EXPECT_EQ(graham_incremental<Filtered_exact_kernel>(input).indices, cgal) << seed;
    EXPECT_EQ(graham_fortune<Cgal_kernel<CGAL::Epick>>(epick).indices, cgal) << seed;
    if (seed % 20 == 0) {
      const auto epeck = to_kernel<Cgal_kernel<CGAL::Epeck>>(input);
      EXPECT_EQ(cgal_convex_hull<CGAL::Epeck>(epeck).indices, cgal) << seed;
      EXPECT_EQ(graham_fortune<Exact_kernel>(to_kernel<Exact_kernel>(input)).indices, cgal) << seed;
    }
  }
}

}  // namespace
}  // namespace relgeo::test
