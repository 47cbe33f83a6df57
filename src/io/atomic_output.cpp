// Atomic publication of output files and directories (include/smoothsteer/io/atomic_output.hpp).

#include "smoothsteer/io/atomic_output.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace smoothsteer::io {
namespace {

namespace fs = std::filesystem;

//! Files a run writes; an existing output directory may hold only these.
constexpr std::array<const char*, 4> run_output_names{"trace.csv", "summary.json", "trace.png",
                                                      "path.csv"};

std::string unique_suffix() {
  static std::atomic<unsigned long> counter{0};
  return std::to_string(::getpid()) + "." + std::to_string(counter++);
}

//! The part of an output's name that its temporary siblings carry: a name may have NAME_MAX
//! = 255 bytes, and ".NAME.partial.PID.N.old" must fit in that too.
std::string name_stem(const std::string& name) {
  constexpr std::size_t longest = 180;
  return name.substr(0, longest);
}

fs::path directory_of(const fs::path& path) {
  return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

bool process_is_gone(const std::string& pid_text) {
  try {
    std::size_t used = 0;
    const long pid = std::stol(pid_text, &used);
    if (used != pid_text.size() || pid <= 0) return false;
    return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
  } catch (const std::exception&) {
    return false;
  }
}

//! Removes `.NAME.partial.PID.N` siblings whose process no longer runs (left by a kill).
void remove_stale_partials(const fs::path& parent, const std::string& name) {
  std::string prefix = ".";
  prefix.append(name_stem(name)).append(".partial.");
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(parent, error)) {
    const std::string entry_name = entry.path().filename().string();
    if (entry_name.rfind(prefix, 0) != 0) continue;
    const std::string rest = entry_name.substr(prefix.size());
    if (process_is_gone(rest.substr(0, rest.find('.')))) fs::remove_all(entry.path(), error);
  }
}

}  // namespace

void require_regular_file_or_absent(const std::string& path, const std::string& option) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(path, error);
  if (error || !fs::exists(status)) return;
  if (!fs::is_regular_file(status)) {
    throw std::runtime_error(option + " '" + path +
                             "': exists and is not a regular file; refusing to replace it");
  }
}

void write_file_atomically(const std::string& path, const std::string& content,
                           const std::string& option) {
  require_regular_file_or_absent(path, option);
  const fs::path target(path);
  std::string temporary_name = ".";  // built by append: GCC 12 warns on "." + a + b (-Wrestrict)
  temporary_name.append(name_stem(target.filename().string()))
      .append(".tmp.")
      .append(unique_suffix());
  const fs::path temporary = directory_of(target) / temporary_name;
  {
    std::ofstream file(temporary, std::ios::binary);
    if (!file) {
      throw std::runtime_error(option + " '" + path + "': cannot create '" + temporary.string() +
                               "': " + std::strerror(errno));
    }
    file << content;
    file.flush();
    if (!file) {
      file.close();
      std::remove(temporary.c_str());
      throw std::runtime_error(option + " '" + path + "': writing failed (disk full?)");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int saved = errno;
    std::remove(temporary.c_str());
    throw std::runtime_error(option + " '" + path +
                             "': cannot rename the temporary file: " + std::strerror(saved));
  }
}

OutputDirectory::OutputDirectory(std::string target, std::string option)
    : target_(std::move(target)), option_(std::move(option)) {
  fs::path path = fs::path(target_).lexically_normal();
  if (path.filename().empty()) path = path.parent_path();  // "out/" -> "out"
  const std::string name = path.filename().string();
  if (name.empty() || name == "." || name == "..") {
    throw std::runtime_error(option_ + " '" + target_ +
                             "': give a directory of its own (not '.', '..' or '/')");
  }
  std::error_code error;
  const fs::file_status status = fs::symlink_status(path, error);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) {
      throw std::runtime_error(option_ + " '" + target_ + "': exists and is not a directory");
    }
    for (const auto& entry : fs::directory_iterator(path)) {
      const std::string entry_name = entry.path().filename().string();
      bool ours = entry.is_regular_file();
      if (ours) {
        ours = false;
        for (const char* output : run_output_names) ours = ours || entry_name == output;
      }
      if (!ours) {
        throw std::runtime_error(
            option_ + " '" + target_ + "': holds '" + entry_name +
            "', which is not an output of a run; give a new directory or "
            "one that only holds trace.csv, summary.json, trace.png, path.csv");
      }
    }
  }
  const fs::path parent = directory_of(path);
  fs::create_directories(parent, error);
  if (error) {
    throw std::runtime_error(option_ + " '" + target_ + "': cannot create '" + parent.string() +
                             "': " + error.message());
  }
  remove_stale_partials(parent, name);
  std::string partial_name = ".";
  partial_name.append(name_stem(name)).append(".partial.").append(unique_suffix());
  partial_ = parent / partial_name;
  if (!fs::create_directory(partial_, error) || error) {
    throw std::runtime_error(option_ + " '" + target_ + "': cannot create '" + partial_.string() +
                             "': " + error.message());
  }
  target_ = path.string();
}

OutputDirectory::~OutputDirectory() {
  if (committed_) return;
  std::error_code error;
  fs::remove_all(partial_, error);
}

void OutputDirectory::commit() {
  // An existing target is swapped with the partial directory in one step (renameat2
  // RENAME_EXCHANGE, Linux >= 3.15); the old outputs then sit under the partial name.
  if (::renameat2(AT_FDCWD, partial_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
    std::error_code error;
    fs::remove_all(partial_, error);
    committed_ = true;
    return;
  }
  const int exchange_error = errno;
  if (exchange_error == ENOENT) {  // no target yet: a plain rename, which fails if one appeared
    if (::renameat2(AT_FDCWD, partial_.c_str(), AT_FDCWD, target_.c_str(), RENAME_NOREPLACE) == 0) {
      committed_ = true;
      return;
    }
  }
  if (exchange_error == EINVAL) {  // file system without RENAME_EXCHANGE: two renames
    const fs::path old = directory_of(partial_) / (partial_.filename().string() + ".old");
    if (std::rename(target_.c_str(), old.c_str()) == 0 &&
        std::rename(partial_.c_str(), target_.c_str()) == 0) {
      std::error_code error;
      fs::remove_all(old, error);
      committed_ = true;
      return;
    }
  }
  throw std::runtime_error(option_ + " '" + target_ +
                           "': cannot publish the outputs: " + std::strerror(errno));
}

}  // namespace smoothsteer::io
