// benchmark/kernel/predicate_benchmark_cgal.cpp — CGAL::Simple_cartesian<double>
// and CGAL::Epick: their own functors used directly, and relgeo's
// Cgal_kernel adapter over them.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include "predicate_benchmark.h"
#include "relgeo/kernel/cgal_kernel.h"

namespace relgeo_bench {

std::vector<Subject> cgal_subjects() {
  using Sc = CGAL::Simple_cartesian<double>;
  using Epick = CGAL::Epick;
  return {
      relgeo_subject<relgeo::Cgal_kernel<Sc>>(),
      make_subject<Cgal_direct_policy<Sc>>("CGAL::Simple_cartesian<double>"),
      relgeo_subject<relgeo::Cgal_kernel<Epick>>(),
      make_subject<Cgal_direct_policy<Epick>>("CGAL::Epick"),
  };
}

}  // namespace relgeo_bench
