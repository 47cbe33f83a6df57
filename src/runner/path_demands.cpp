#include "path_demands.hpp"

#include <cstddef>
#include <deque>
#include <mutex>
#include <utility>

namespace smoothsteer::runner::detail {

PathDemand shared_path_demand(const std::shared_ptr<const Path>& path) {
  // Remembered: a campaign's base path and the odd scenario of a sweep.
  constexpr std::size_t max_paths = 8;
  static std::mutex mutex;
  static std::deque<std::pair<std::weak_ptr<const Path>, PathDemand>> demands;
  const auto same = [&path](const std::weak_ptr<const Path>& kept) {
    // The owner, not the address: a dead path's memory may hold a new one.
    return !kept.owner_before(path) && !path.owner_before(kept) && !kept.expired();
  };
  {
    const std::lock_guard<std::mutex> lock(mutex);
    for (const auto& [kept, demand] : demands) {
      if (same(kept)) return demand;
    }
  }
  const PathDemand demand = path_demand(*path);
  const std::lock_guard<std::mutex> lock(mutex);
  std::erase_if(demands, [](const auto& entry) { return entry.first.expired(); });
  if (demands.size() >= max_paths) demands.pop_front();
  demands.emplace_back(path, demand);
  return demand;
}

}  // namespace smoothsteer::runner::detail
