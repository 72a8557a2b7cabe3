// tools/relgeo/commands/hull/dispatch.cpp — the planar hull algorithms under
// every kernel (CGAL Epeck included).
#include <chrono>
#include <csignal>
#include <iostream>
#include <vector>

#if defined(__unix__)
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#endif

#include "commands/hull/facade.h"
#include "kernels/cgal_kernels.h"
#include "kernels/dispatch.h"
#include "relgeo/error/hull_backward_error.h"
#include "relgeo/hull.h"
#include "relgeo/hull/cgal_convex_hull.h"

namespace relgeo::tool {

namespace {

using Clock = std::chrono::steady_clock;

/// Time limit of a run in a child process.
constexpr unsigned isolated_time_limit_s = 120;

}  // namespace

namespace {

#if defined(__unix__)
// ---- running CGAL's hull without exact predicates in a child process -----------
// CGAL::convex_hull_2 requires exact predicates; under Simple_cartesian<double>
// it can read outside its stack (segfault seen in ch__ref_graham_andrew_scan on
// the experiment's large-range input). The tool runs it in a forked child and
// reports a crash as a failed run instead of dying.

bool write_all(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t w = ::write(fd, p, size);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w, size -= static_cast<std::size_t>(w);
  }
  return true;
}

bool read_all(int fd, void* data, std::size_t size) {
  char* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t r = ::read(fd, p, size);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    p += r, size -= static_cast<std::size_t>(r);
  }
  return true;
}

struct Wire_header {
  int status;
  std::size_t failure_size, index_count, predicate_calls, uncertain_answers, timed_runs;
  double time_s;
};

/// Runs `run()` (returning a Hull_run) in a forked child, with a time limit.
template <class Run>
Hull_run run_isolated(Run run, unsigned time_limit_s) {
  int fds[2];
  if (::pipe(fds) != 0) return run();  // no isolation available: run here
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]), ::close(fds[1]);
    return run();
  }
  if (pid == 0) {  // child: compute, send, _exit (no atexit handlers, no stream flushing)
    ::close(fds[0]);
    ::alarm(time_limit_s);
    int code = 0;
    try {
      const Hull_run r = run();
      const Wire_header h{static_cast<int>(r.status), r.failure.size(), r.indices.size(),
                          r.predicate_calls,        r.uncertain_answers, r.timed_runs, r.time_s};
      const bool ok = write_all(fds[1], &h, sizeof h) &&
                      write_all(fds[1], r.failure.data(), r.failure.size()) &&
                      write_all(fds[1], r.indices.data(), r.indices.size() * sizeof(std::size_t));
      code = ok ? 0 : 3;
    } catch (...) {
      code = 4;
    }
    ::_exit(code);
  }
  ::close(fds[1]);
  Hull_run r;
  Wire_header h{};
  bool ok = read_all(fds[0], &h, sizeof h);
  if (ok) {
    r.status = static_cast<Hull_status>(h.status);
    r.failure.resize(h.failure_size);
    r.indices.resize(h.index_count);
    ok = read_all(fds[0], r.failure.data(), h.failure_size) &&
         read_all(fds[0], r.indices.data(), h.index_count * sizeof(std::size_t));
    r.predicate_calls = h.predicate_calls;
    r.uncertain_answers = h.uncertain_answers;
    r.timed_runs = h.timed_runs;
    r.time_s = h.time_s;
  }
  ::close(fds[0]);
  int wstatus = 0;
  while (::waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(wstatus) || !ok || !WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0) {
    Hull_run failed;
    failed.status = Hull_status::failed;
    if (WIFSIGNALED(wstatus)) {
      const int sig = WTERMSIG(wstatus);
      failed.failure = sig == SIGALRM ? "timeout (" + std::to_string(time_limit_s) + " s)"
                                      : std::string("crash (") + (sig == SIGSEGV ? "SIGSEGV"
                                                                  : sig == SIGABRT ? "SIGABRT"
                                                                  : sig == SIGBUS  ? "SIGBUS"
                                                                                   : "signal " + std::to_string(sig)) + ")";
    } else {
      failed.failure = "crash (no result)";
    }
    return failed;
  }
  return r;
}
#endif

}  // namespace

Hull_run run_hull(std::string_view algorithm, std::string_view kernel,
                  std::span<const Point_2<double>> input, double min_seconds, const relgeo::Hull_options& options) {
  validate_hull_combination(algorithm, kernel);
  return with_kernel(kernel, [&]<class K>(const K& k) {
    using P = typename K::Point_2;
    const auto construct = k.construct_point_2_object();
    std::vector<P> points;
    points.reserve(input.size());
    for (const auto& p : input) points.push_back(construct(p.x, p.y));
    const std::span<const P> span(points);

    auto compute = [&]() -> Hull_result<P> {
      if (algorithm == "graham-incremental") return graham_incremental<K>(span, k);
      if (algorithm == "graham-fortune") return graham_fortune<K>(span, k, options);
      if (algorithm == "monotone-chain") return monotone_chain<K>(span, k, options);
      if constexpr (is_cgal_kernel_v<K>)
        return cgal_convex_hull<typename K::Cgal>(span, Cgal_hull_algorithm::convex_hull_2, k);
      // validate_hull_combination lets `cgal` through only for cgal-* kernels.
      throw Usage_error("algorithm '" + std::string(algorithm) + "' cannot run under kernel '" +
                        std::string(kernel) + "'");
    };

    auto timed = [&] {
      Hull_run run;
      const auto start = Clock::now();
      double best = -1;
      for (;;) {
        const auto t0 = Clock::now();
        Hull_result<P> r = compute();
        const auto t1 = Clock::now();
        ++run.timed_runs;
        const double t = std::chrono::duration<double>(t1 - t0).count();
        if (best < 0 || t < best) best = t;
        if (run.timed_runs == 1) {
          run.status = r.status;
          run.failure = r.failure;
          run.indices = std::move(r.indices);
          run.predicate_calls = r.predicate_calls;
          run.uncertain_answers = r.uncertain_answers;
        }
        if (std::chrono::duration<double>(t1 - start).count() >= min_seconds) break;
      }
      run.time_s = best;
      return run;
    };

    Hull_run run;
#if defined(__unix__)
    if (algorithm == "cgal" && !K::has_exact_predicates)
      run = run_isolated(timed, isolated_time_limit_s);
    else
      run = timed();
#else
    run = timed();
#endif
    run.predicate_calls_counted = algorithm != "cgal";
    if (algorithm == "graham-fortune") run.backward_error_bound = graham_fortune_backward_error_bound<K>(input);
    return run;
  });
}

}  // namespace relgeo::tool
