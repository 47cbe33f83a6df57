#pragma once
//! A counting global operator new for the allocation-free tests: it observes every allocation of
//! the test binary. Include it in exactly ONE source file per test executable (it defines the
//! replacement operators), then compare allocation_count before and after the measured calls.
//! Allocations through malloc (e.g. in C libraries) are not seen. largest_allocation_bytes holds
//! the largest single request since it was last set to 0 (the hostile-input tests check that a
//! rejected input is refused before any large allocation).

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> allocation_count{0};
std::atomic<std::size_t> largest_allocation_bytes{0};
}  // namespace

void* operator new(std::size_t size) {
  allocation_count.fetch_add(1, std::memory_order_relaxed);
  std::size_t largest = largest_allocation_bytes.load(std::memory_order_relaxed);
  while (size > largest && !largest_allocation_bytes.compare_exchange_weak(
                               largest, size, std::memory_order_relaxed)) {
  }
  if (void* pointer = std::malloc(size == 0 ? 1 : size)) return pointer;
  throw std::bad_alloc();
}
// These replace the global operator delete for the malloc-based operator new above. GCC's
// -Wmismatched-new-delete cannot see that the two are a matching pair (it fires in the
// sanitizer build), so it is silenced for these two definitions only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* pointer) noexcept {
  std::free(pointer);
}
void operator delete(void* pointer, std::size_t) noexcept {
  std::free(pointer);
}
#pragma GCC diagnostic pop
