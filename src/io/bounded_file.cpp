// Bounded reading of user files (include/smoothsteer/io/bounded_file.hpp).

#include "smoothsteer/io/bounded_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace smoothsteer::io {
namespace {

//! Closes the descriptor on every way out.
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_bounded_file(const std::string& file, std::uintmax_t max_bytes,
                              const std::string& what) {
  const std::string where = file + ": " + what;
  // O_NONBLOCK: opening a FIFO without a writer would otherwise wait forever.
  Descriptor d{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (d.fd < 0) {
    const int saved = errno;
    if (saved == ENOENT) throw FileReadError(where + ": cannot open file (no such file)");
    if (saved == EISDIR) throw FileReadError(where + " is a directory, not a regular file");
    throw FileReadError(where + ": cannot open file: " + std::strerror(saved));
  }
  struct stat status {};
  if (::fstat(d.fd, &status) != 0) {
    throw FileReadError(where + ": cannot read file status: " + std::strerror(errno));
  }
  if (S_ISDIR(status.st_mode)) {
    throw FileReadError(where + " is a directory, not a regular file");
  }
  if (!S_ISREG(status.st_mode)) {
    throw FileReadError(where + " is not a regular file (a FIFO, device or socket); give a file");
  }
  const auto too_large = [&] {
    return FileReadError(where + " is larger than " + std::to_string(max_bytes) +
                         " bytes; refusing to read it");
  };
  if (static_cast<std::uintmax_t>(status.st_size) > max_bytes) throw too_large();
  std::string content;
  content.reserve(static_cast<std::size_t>(status.st_size));
  char buffer[1 << 16];
  while (true) {
    const ssize_t got = ::read(d.fd, buffer, sizeof buffer);
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      throw FileReadError(where + ": cannot read file: " + std::strerror(errno));
    }
    content.append(buffer, static_cast<std::size_t>(got));
    if (content.size() > max_bytes) throw too_large();  // it grew while being read
  }
  return content;
}

}  // namespace smoothsteer::io
