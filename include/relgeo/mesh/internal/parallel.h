// relgeo/mesh/internal/parallel.h — the few parallel loops of the mesh area:
// on oneTBB in a translation unit compiled with RELGEO_HAS_TBB (a target that
// links relgeo::tbb), serial otherwise; each call's `threads` chooses at run
// time how many of its threads to use.
//
// Every parallel result of the mesh area is made thread-count independent by
// its caller (work split into a fixed list of items, results concatenated in
// item order), so these loops only have to run the items.
//
// One program, both backends. A program may mix translation units built with
// and without RELGEO_HAS_TBB (a library built serially, an application that
// links relgeo::tbb). So the two backends are distinct entities: each lives
// in its own inline namespace, chosen by the macro (internal::tbb_backend or
// internal::serial_backend), their names mangle differently, and the linker
// cannot keep one TU's thread_count beside the other's loops (which could run
// parallel_invoke outside the arena that bounds it to `threads`).
//
// What remains. A caller of these helpers (Face_bvh's build and pair
// searches, the self-intersection test, the Boolean's checks) instantiated in
// both kinds of TU still has two definitions, the same tokens naming
// different helpers; the linker keeps one of them whole, so that caller runs
// on one backend throughout the program — possibly the serial one in a TU
// built with TBB. Both definitions compute the same result (the independence
// above; test/mesh/parallel_backends_test.cpp runs both backends in one
// program), so only the speed can differ. Removing that too would put the
// backend into every caller's type, as CGAL's Concurrency_tag does: a
// template parameter on Face_bvh, the self-intersection test and the
// Boolean, for programs that relgeo::tbb (which defines the macro for every
// TU of a target) already makes rare.
#pragma once

#include <cstddef>
#include <utility>

#if defined(RELGEO_HAS_TBB) && RELGEO_HAS_TBB
#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#endif

namespace relgeo::internal {

#if defined(RELGEO_HAS_TBB) && RELGEO_HAS_TBB
inline namespace tbb_backend {

/// Threads a loop will use for `requested` (0: every hardware thread).
inline int thread_count(int requested) { return requested <= 0 ? tbb::info::default_concurrency() : requested; }

/// f(i) for i in [0, n), on up to `threads` threads (see thread_count), each
/// index once, in no particular order across threads.
template <class F>
void parallel_for_each_index(std::size_t n, int threads, F&& f) {
  threads = thread_count(threads);
  if (threads > 1 && n > 1) {
    tbb::task_arena arena(threads);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
      });
    });
    return;
  }
  for (std::size_t i = 0; i < n; ++i) f(i);
}

/// Runs `task` inside an arena of `threads` threads, so that nested
/// invoke_both calls use at most that many.
template <class F>
void in_thread_arena(int threads, F&& task) {
  threads = thread_count(threads);
  if (threads > 1) {
    tbb::task_arena arena(threads);
    arena.execute([&] { task(); });
    return;
  }
  task();
}

/// f() and g(), concurrently when `parallel` (inside in_thread_arena).
template <class F, class G>
void invoke_both(bool parallel, F&& f, G&& g) {
  if (parallel) {
    tbb::parallel_invoke(std::forward<F>(f), std::forward<G>(g));
    return;
  }
  f();
  g();
}

}  // namespace tbb_backend
#else
inline namespace serial_backend {

/// One thread, whatever is requested.
inline int thread_count(int /*requested*/) { return 1; }

/// f(i) for i in [0, n), in order.
template <class F>
void parallel_for_each_index(std::size_t n, int /*threads*/, F&& f) {
  for (std::size_t i = 0; i < n; ++i) f(i);
}

/// task().
template <class F>
void in_thread_arena(int /*threads*/, F&& task) {
  task();
}

/// f(), then g().
template <class F, class G>
void invoke_both(bool /*parallel*/, F&& f, G&& g) {
  f();
  g();
}

}  // namespace serial_backend
#endif

}  // namespace relgeo::internal
