#pragma once
// The path demand (largest curvature and curvature rate, tuning/path_demand.hpp) of a path that
// many controllers share. A scenario's controller is built twice (checked by the load, built
// again by the run), and a campaign's cases share one path (built_paths.hpp); sampling the path
// every 5 cm is a fifth of a load.

#include <memory>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/tuning/path_demand.hpp"

namespace smoothsteer::runner::detail {

//! path_demand(*path), computed once while the path lives (a path is immutable; the last few
//! paths are remembered, by identity, not by address). Thread-safe.
PathDemand shared_path_demand(const std::shared_ptr<const Path>& path);

}  // namespace smoothsteer::runner::detail
