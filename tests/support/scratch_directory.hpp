// A test's own folder under the system's temporary one, for the scenario, vehicle and CSV files
// it writes; removed with the object. The process id keeps parallel test processes apart.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace smoothsteer::testing {

class ScratchDirectory {
 public:
  explicit ScratchDirectory(const std::string& prefix)
      : directory_(std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid()))) {
    std::filesystem::create_directories(directory_);
  }
  ~ScratchDirectory() { std::filesystem::remove_all(directory_); }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  //! The path of `name` in the folder, as a string for the loaders.
  std::string file(const std::string& name) const { return (directory_ / name).string(); }
  //! Writes `text` to `name` (replacing it); returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(directory_ / name, std::ios::binary) << text;
    return file(name);
  }

 private:
  std::filesystem::path directory_;
};

}  // namespace smoothsteer::testing
