// relgeo/core/internal/stopwatch.h — the wall-clock timer of the phase
// timings in results and reports (steady clock, seconds as double).
#pragma once

#include <chrono>

namespace relgeo::internal {

class Stopwatch {
 public:
  using Clock = std::chrono::steady_clock;

  /// Seconds since the start: construction, or the last lap() or restart().
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  /// elapsed(), and the next phase starts now.
  double lap() {
    const Clock::time_point now = Clock::now();
    const double s = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return s;
  }
  void restart() { start_ = Clock::now(); }

 private:
  Clock::time_point start_ = Clock::now();
};

}  // namespace relgeo::internal
