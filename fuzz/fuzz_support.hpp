#pragma once
//! Shared by the libFuzzer targets: inputs are written to a per-process scratch directory (the
//! loaders read files), rejected inputs are expected (every loader throws on bad input), and
//! anything else - a crash, a sanitizer report, an exception that is not std::exception, or
//! running out of memory - ends the process so that libFuzzer reports it.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>

namespace smoothsteer::fuzz {

inline const std::filesystem::path& scratch_directory() {
  static const std::filesystem::path directory = [] {
    const std::filesystem::path d =
        std::filesystem::temp_directory_path() / ("smoothsteer_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(scratch_directory(), ignored);
    });
    return d;
  }();
  return directory;
}

inline std::string write_scratch(const std::string& name, const std::uint8_t* data,
                                 std::size_t size) {
  const std::filesystem::path file = scratch_directory() / name;
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file.string();
}

inline void write_scratch(const std::string& name, const std::string& text) {
  write_scratch(name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

//! Runs `body`; a rejected input (std::exception with a message) is fine, a bad_alloc is a bug:
//! every count the input controls is capped.
template <typename Body>
void expect_accept_or_reject(Body&& body) {
  try {
    body();
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "fuzz: std::bad_alloc escaped: an input-controlled count is not capped\n");
    std::abort();
  } catch (const std::exception& error) {
    if (error.what()[0] == '\0') {
      std::fprintf(stderr, "fuzz: an error without a message\n");
      std::abort();
    }
  }
}

}  // namespace smoothsteer::fuzz
