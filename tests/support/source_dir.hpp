// The source tree that the tests read scenario, vehicle and data files from: the build sets
// SMOOTHSTEER_SOURCE_DIR for every test (tests/CMakeLists.txt); without it, the working directory.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

namespace smoothsteer::testing {

inline std::filesystem::path source_dir() {
  const char* env = std::getenv("SMOOTHSTEER_SOURCE_DIR");
  return env ? std::filesystem::path(env) : std::filesystem::current_path();
}

//! A file of the source tree, as a string for the loaders.
inline std::string source_file(const std::string& relative) {
  return (source_dir() / relative).string();
}

}  // namespace smoothsteer::testing
