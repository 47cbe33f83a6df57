#pragma once
//! \file bounded_file.hpp
//! The one way the readers of user files (scenario and vehicle YAML, waypoint and schedule CSV)
//! open a file: only a regular file, never more than a stated number of bytes. A FIFO would
//! block the reader forever and /dev/zero would fill the memory.

#include <cstdint>
#include <stdexcept>
#include <string>

namespace smoothsteer::io {

//! Largest scenario or vehicle YAML file read [bytes]; the shipped ones are a few kB.
inline constexpr std::uintmax_t max_yaml_file_bytes = 16u << 20;
//! Largest waypoint CSV read [bytes]: max_waypoints rows of two long numbers.
inline constexpr std::uintmax_t max_waypoint_file_bytes = 64u << 20;
//! Largest gain-schedule CSV read [bytes]: 10 000 speeds of 12 columns take about 2 MB.
inline constexpr std::uintmax_t max_schedule_file_bytes = 16u << 20;

//! The file could not be read, is not a regular file, or is larger than allowed.
class FileReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! Reads the whole of `file`, a `what` ("scenario file", "schedule file", ...). Throws
//! FileReadError "<file>: <what> ..." if it does not exist, is a directory, a FIFO, a device or
//! anything else that is not a regular file, or holds more than `max_bytes` bytes. The file is
//! opened without blocking and checked on the opened descriptor, and never more than
//! `max_bytes` + 1 bytes are read, so a file that changes under the reader cannot defeat it.
std::string read_bounded_file(const std::string& file, std::uintmax_t max_bytes,
                              const std::string& what);

}  // namespace smoothsteer::io
