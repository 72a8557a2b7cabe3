// test/mesh/parallel_backend.h — the pair searches of the face BVH compiled
// twice into one program: parallel_backend.cpp without RELGEO_HAS_TBB
// (serial_backend_run) and with it (tbb_backend_run), see
// test/mesh/CMakeLists.txt and relgeo/mesh/internal/parallel.h.
#pragma once

#include <vector>

#include "relgeo/mesh/face_bvh.h"

namespace relgeo_test {

/// What one translation unit computed, and which backend it was compiled with.
struct Backend_run {
  /// relgeo::internal::thread_count as this TU names it (one function per
  /// backend: the two TUs must not share it).
  int (*thread_count)(int) = nullptr;
  /// thread_count(threads): how many threads the TU's loops may use.
  int threads_used = 0;
  /// Overlapping face pairs, through a callback of this TU (so the search is
  /// instantiated in this TU, on its backend): between two crossing spheres,
  /// and within their union.
  std::vector<relgeo::Face_pair> cross_pairs, self_pairs;
};

Backend_run serial_backend_run(int threads);
Backend_run tbb_backend_run(int threads);

}  // namespace relgeo_test
