// benchmark/kernel/predicate_benchmark_epeck.cpp — CGAL::Epeck (lazy exact
// constructions, filtered predicates): its own functors used directly, and
// relgeo's Cgal_kernel adapter over it. A translation unit of its own: the
// lazy kernel is by far the slowest header set to compile.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "predicate_benchmark.h"
#include "relgeo/kernel/cgal_kernel.h"

namespace relgeo_bench {

std::vector<Subject> cgal_epeck_subjects() {
  using Epeck = CGAL::Epeck;
  return {
      relgeo_subject<relgeo::Cgal_kernel<Epeck>>(),
      make_subject<Cgal_direct_policy<Epeck>>("CGAL::Epeck"),
  };
}

}  // namespace relgeo_bench
