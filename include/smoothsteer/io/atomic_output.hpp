#pragma once
//! \file atomic_output.hpp
//! The one place that publishes output files (never half an output set, never a rename over a
//! device node): a file or a whole directory is built under a temporary name next to its target and
//! renamed into place, so a reader sees the old outputs or the new ones, never a mix or half a
//! file. Targets that exist and are not what we write (a device, a symlink, a FIFO, a directory of
//! other files) are refused instead of being replaced.

#include <filesystem>
#include <string>

namespace smoothsteer::io {

//! Throws std::runtime_error naming `option` and `path` if `path` exists and is not a regular
//! file (symlinks included: the rename would replace the link, not its target).
void require_regular_file_or_absent(const std::string& path, const std::string& option);

//! Writes `content` to `path` through a temporary file in the same directory and a rename.
//! `option` names the command-line option or key in error messages (e.g. "--out").
void write_file_atomically(const std::string& path, const std::string& content,
                           const std::string& option = "output");

//! A run's output directory, built as `.NAME.partial.PID` next to NAME and published by
//! commit(): with an atomic exchange when NAME exists, else a rename. Destroying it before
//! commit() removes the partial directory. Partial directories left by killed processes
//! (their PID no longer runs) are removed when the next one is created.
class OutputDirectory {
 public:
  //! Throws std::runtime_error if `target` exists and is not a directory, or holds files that
  //! are not outputs of a run (trace.csv, summary.json, trace.png): it is never swapped away.
  OutputDirectory(std::string target, std::string option);
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;
  ~OutputDirectory();

  //! Where to write `name` before commit().
  std::filesystem::path file(const std::string& name) const { return partial_ / name; }
  //! Publishes every file at once.
  void commit();

  const std::string& target() const { return target_; }

 private:
  std::string target_;
  std::string option_;
  std::filesystem::path partial_;
  bool committed_ = false;
};

}  // namespace smoothsteer::io
