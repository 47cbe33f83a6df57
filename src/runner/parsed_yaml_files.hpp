#pragma once
// The YAML files that many loads of one scenario share, parsed once per process: a campaign
// loads its base scenario (and the vehicle files it names) for each of thousands of cases with
// other overrides (load_scenario_reusing_files, scenario.hpp).

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <deque>
#include <mutex>
#include <string>

namespace smoothsteer::runner::detail {

//! Parsed YAML files by absolute path, each handed out as a copy that the caller may change
//! (overrides) without touching the next caller's. A file is read on every call and parsed
//! again only when its bytes differ from the ones parsed, so an edited file is never served
//! stale, however quickly it was rewritten. A copy (YAML::Clone) has no marks: an error found
//! on it can name no line, which is why load_scenario_reusing_files() repeats a failed load
//! from the files themselves.
class ParsedYamlFiles {
 public:
  //! Files kept, the oldest dropped first: a campaign needs its base and a vehicle file or two.
  static constexpr std::size_t max_files = 8;
  //! The kept texts together [bytes]; a larger file is parsed but not kept.
  static constexpr std::size_t max_bytes = 16u << 20;

  //! A copy of the file's tree; throws as io::load_yaml_file() does.
  YAML::Node copy(const std::string& file);
  //! Parses of a file so far (each a miss: first read or changed bytes), for tests.
  std::size_t parses() const;

 private:
  struct Parsed {
    std::string path;
    std::string text;
    YAML::Node tree;  //!< never handed out: yaml-cpp nodes are references
  };
  //! Keeps `parsed`, dropping the oldest files beyond the limits.
  void keep(Parsed parsed);

  mutable std::mutex mutex_;  // yaml-cpp changes a tree even when reading it
  std::deque<Parsed> files_;  // oldest first
  std::size_t parses_ = 0;
};

//! The process's files (thread-safe).
ParsedYamlFiles& process_yaml_files();

}  // namespace smoothsteer::runner::detail
