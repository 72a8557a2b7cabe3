// benchmark/common/process_memory.h — reading this process's memory figures
// from /proc/self/status (Linux), for the peak-memory columns of the hull
// and Boolean benchmarks, and its page faults (getrusage).
#pragma once

#include <sys/resource.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace relgeo_bench {

/// A line "Key:   123 kB" of /proc/self/status, in bytes (0 if absent).
inline std::size_t proc_status_bytes(const char* key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  const std::size_t k = std::strlen(key);
  while (std::getline(f, line))
    if (line.compare(0, k, key) == 0 && line.size() > k && line[k] == ':')
      return static_cast<std::size_t>(std::strtoull(line.c_str() + k + 1, nullptr, 10)) * 1024;
  return 0;
}

/// Minor page faults of the process so far: pages mapped when first
/// touched (on a virtual machine each costs microseconds: doc/boolean.md,
/// "Page faults").
inline long minor_page_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

}  // namespace relgeo_bench
