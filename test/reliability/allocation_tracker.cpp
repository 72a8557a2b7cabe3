// Global operator new/delete of the reliability tests: malloc and free, with
// the largest request recorded while an Allocation_watch is active.
#include "allocation_tracker.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<int> watching{0};
std::atomic<std::size_t> largest_request{0};

void* allocate(std::size_t n) {
  if (watching.load(std::memory_order_relaxed) > 0) {
    std::size_t seen = largest_request.load(std::memory_order_relaxed);
    while (n > seen && !largest_request.compare_exchange_weak(seen, n)) {
    }
  }
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return allocate(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace relgeo::test {
Allocation_watch::Allocation_watch() {
  largest_request = 0;
  ++watching;
}
Allocation_watch::~Allocation_watch() { --watching; }
std::size_t Allocation_watch::largest() const { return largest_request.load(); }
}  // namespace relgeo::test
