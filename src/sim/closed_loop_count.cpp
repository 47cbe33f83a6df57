// Closed-loop counter (include/smoothsteer/sim/closed_loop_count.hpp).

#include "smoothsteer/sim/closed_loop_count.hpp"

#include <atomic>

namespace smoothsteer {
namespace {

std::atomic<long> closed_loops{0};

}  // namespace

long closed_loops_run() noexcept {
  return closed_loops.load(std::memory_order_relaxed);
}

namespace detail {
void count_closed_loop() noexcept {
  closed_loops.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace detail

}  // namespace smoothsteer
