// test/reliability/allocation_tracker.h — the largest single allocation made
// while an Allocation_watch lives (allocation_tracker.cpp replaces the global
// operator new of the test binary that links it). Used to check that readers
// do not size buffers from a count in a file before they read the data.
#pragma once

#include <cstddef>

namespace relgeo::test {

class Allocation_watch {
 public:
  Allocation_watch();
  ~Allocation_watch();
  Allocation_watch(const Allocation_watch&) = delete;
  Allocation_watch& operator=(const Allocation_watch&) = delete;
  /// Bytes of the largest allocation since construction.
  std::size_t largest() const;
};

}  // namespace relgeo::test
