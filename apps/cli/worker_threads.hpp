#pragma once
//! `-j/--jobs N` of the long commands (docs/cli.md): N worker threads, 0 for one per core.

#include <algorithm>
#include <thread>

namespace smoothsteer::cli {

//! The threads -j asks for: `jobs` (0: every core, at most 256), or `otherwise` when -j was not
//! given (jobs < 0), e.g. a sub-command's own --threads.
inline int worker_threads(int jobs, int otherwise) {
  if (jobs < 0) return otherwise;
  if (jobs > 0) return jobs;
  return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 256u));
}

}  // namespace smoothsteer::cli
