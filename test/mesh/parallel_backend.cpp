// Compiled twice into relgeo_parallel_backend_tests: in the test itself
// (no RELGEO_HAS_TBB: serial_backend_run) and in
// relgeo_parallel_backend_tbb (linked with relgeo::tbb: tbb_backend_run).
#include "mesh/parallel_backend.h"

#include "mesh/solid_fixtures.h"

namespace relgeo_test {

#if defined(RELGEO_HAS_TBB) && RELGEO_HAS_TBB
Backend_run tbb_backend_run(int threads)
#else
Backend_run serial_backend_run(int threads)
#endif
{
  const Mesh_d a = cube_sphere(20), b = translated(a, 0.3, 0.2, 0.1);
  const relgeo::Face_bvh ta(a, {.threads = threads}), tb(b, {.threads = threads});
  const relgeo::Face_bvh both(disjoint_union(a, b), {.threads = threads});
  // A lambda of this function: its type, and so the search instantiated for
  // it, belongs to this translation unit alone.
  const auto keep = [](relgeo::Index f, relgeo::Index g, std::vector<relgeo::Face_pair>& out) {
    out.push_back({f, g});
  };
  return {.thread_count = &relgeo::internal::thread_count,
          .threads_used = relgeo::internal::thread_count(threads),
          .cross_pairs = ta.collect_overlapping_pairs<relgeo::Face_pair>(tb, keep, threads),
          .self_pairs = both.collect_overlapping_pairs<relgeo::Face_pair>(keep, threads)};
}

}  // namespace relgeo_test
