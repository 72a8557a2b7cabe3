// relgeo/mesh/internal/parallel.h — the few parallel loops of the mesh area,
// on oneTBB when the including target defines RELGEO_HAS_TBB (and links
// TBB::tbb); serial otherwise.
//
// Every parallel result of the mesh area is made thread-count independent by
// its caller (work split into a fixed list of items, results concatenated in
// item order), so these loops only have to run the items.
#pragma once

#include <cstddef>
#include <utility>

#if defined(RELGEO_HAS_TBB) && RELGEO_HAS_TBB
#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#define RELGEO_MESH_PARALLEL 1
#else
#define RELGEO_MESH_PARALLEL 0
#endif

namespace relgeo::internal {

/// Threads a loop will use for `requested` (0: every hardware thread; 1 or
/// no TBB: one).
inline int thread_count(int requested) {
#if RELGEO_MESH_PARALLEL
  if (requested <= 0) return tbb::info::default_concurrency();
  return requested;
#else
  (void)requested;
  return 1;
#endif
}

/// f(i) for i in [0, n), on up to `threads` threads (see thread_count), each
/// index once, in no particular order across threads.
template <class F>
void parallel_for_each_index(std::size_t n, int threads, F&& f) {
  threads = thread_count(threads);
#if RELGEO_MESH_PARALLEL
  if (threads > 1 && n > 1) {
    tbb::task_arena arena(threads);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
      });
    });
    return;
  }
#endif
  for (std::size_t i = 0; i < n; ++i) f(i);
}

/// Runs `task` inside an arena of `threads` threads (when parallel), so
/// that nested parallel_invoke calls use at most that many.
template <class F>
void in_thread_arena(int threads, F&& task) {
  threads = thread_count(threads);
#if RELGEO_MESH_PARALLEL
  if (threads > 1) {
    tbb::task_arena arena(threads);
    arena.execute([&] { task(); });
    return;
  }
#endif
  task();
}

/// f() and g(), concurrently when `parallel` (inside in_thread_arena).
template <class F, class G>
void invoke_both(bool parallel, F&& f, G&& g) {
#if RELGEO_MESH_PARALLEL
  if (parallel) {
    tbb::parallel_invoke(std::forward<F>(f), std::forward<G>(g));
    return;
  }
#else
  (void)parallel;
#endif
  f();
  g();
}

}  // namespace relgeo::internal
