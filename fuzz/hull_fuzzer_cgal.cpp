// The hull contract (hull_harness.h) under CGAL's kernels through
// Cgal_kernel: Simple_cartesian<double>, Epick, Epeck.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include "hull_harness.h"
#include "relgeo/kernel/cgal_kernel.h"

namespace relgeo::fuzz {

void check_hull_cgal(int kernel, std::span<const Point_2<double>> input, Hull_algorithm a, const Hull_options& o) {
  switch (kernel) {
    case 0: check_hull<Cgal_kernel<CGAL::Simple_cartesian<double>>>(input, a, o); break;
    case 1: check_hull<Cgal_kernel<CGAL::Epick>>(input, a, o); break;
    default: check_hull<Cgal_kernel<CGAL::Epeck>>(input, a, o);
  }
}

}  // namespace relgeo::fuzz
