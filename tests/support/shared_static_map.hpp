#pragma once
//! One StaticMap per test binary: building it takes ~0.35 s (docs/benchmarks.md).

#include "smoothsteer/tuning/static_map.hpp"

namespace smoothsteer::testing {

inline const StaticMap& shared_map() {
  static const StaticMap map{};
  return map;
}

}  // namespace smoothsteer::testing
