#pragma once
// The paths that many loads of one scenario share, built once per process: a campaign's cases
// override the speed, the start, the car, but rarely the path, whose spline and arc lengths
// are a fifth of a load (load_scenario_reusing_files, scenario.hpp).

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_plan.hpp"

namespace smoothsteer::runner::detail {

//! What make_path() made of a `path` section: the path, the plan (gear changes) and the
//! section's resolved mapping (summary.json's parameters).
struct BuiltPath {
  std::shared_ptr<const Path> path;
  std::shared_ptr<const PathPlan> plan;
  YAML::Node resolved;
};

//! Built paths by the content of their section (every key, value and tag: a quoted '5' is
//! another section than 5) and the folder it was read from. Only sections that were built
//! without an error are kept, so a hit is what make_path() would return; sections that read a
//! file (waypoints_csv) are never kept, the file might have changed.
class BuiltPaths {
 public:
  static constexpr std::size_t max_paths = 8;  //!< kept, the oldest dropped first

  //! The identity of a section read from `directory`; none if it must be built every time.
  static std::optional<std::string> key(const YAML::Node& section, const std::string& directory);
  //! The path built for `key` before (resolved: a copy), if any.
  std::optional<BuiltPath> find(const std::string& key) const;
  void keep(const std::string& key, const BuiltPath& built);

 private:
  mutable std::mutex mutex_;  // yaml-cpp changes a tree even when reading it
  std::deque<std::pair<std::string, BuiltPath>> paths_;  // oldest first
};

//! The process's paths (thread-safe).
BuiltPaths& process_paths();

}  // namespace smoothsteer::runner::detail
