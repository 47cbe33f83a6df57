// trace.csv writer (include/smoothsteer/io/trace_csv.hpp).

#include "smoothsteer/io/trace_csv.hpp"

#include <array>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <stdexcept>

namespace smoothsteer::io {
namespace {

constexpr int significant_digits = 9;
//! Longest row: 25 numbers of at most 16 characters ("-1.23456789e-308") plus separators.
constexpr std::size_t row_capacity = trace_column_count * 24 + 2;

std::string header() {
  std::string line;
  for (const char* name : trace_column_names()) {
    if (!line.empty()) line += ',';
    line += name;
  }
  line += '\n';
  return line;
}

//! Formats the row into `buffer`; returns its length.
std::size_t format_row(const TraceSample& sample, std::array<char, row_capacity>& buffer) {
  char* out = buffer.data();
  char* const end = buffer.data() + buffer.size();
  bool first = true;
  for (double value : trace_row(sample)) {
    if (!first) *out++ = ',';
    first = false;
    out = std::to_chars(out, end, value, std::chars_format::general, significant_digits).ptr;
  }
  *out++ = '\n';
  return static_cast<std::size_t>(out - buffer.data());
}

}  // namespace

TraceCsvWriter::TraceCsvWriter(std::string file) : file_(std::move(file)) {
  stream_ = std::fopen(file_.c_str(), "wb");
  if (!stream_) {
    throw std::runtime_error(file_ + ": cannot create the trace: " + std::strerror(errno));
  }
  const std::string line = header();
  std::fwrite(line.data(), 1, line.size(), stream_);
}

TraceCsvWriter::~TraceCsvWriter() {
  if (stream_) std::fclose(stream_);
}

void TraceCsvWriter::write(const TraceSample& sample) {
  std::array<char, row_capacity> buffer;
  std::fwrite(buffer.data(), 1, format_row(sample, buffer), stream_);
}

void TraceCsvWriter::close() {
  if (!stream_) return;
  const bool failed = std::ferror(stream_) != 0;
  const bool close_failed = std::fclose(stream_) != 0;
  stream_ = nullptr;
  if (failed || close_failed) {
    throw std::runtime_error(file_ + ": writing the trace failed (disk full?)");
  }
}

std::string trace_csv(const std::vector<TraceSample>& trace) {
  std::string text = header();
  std::array<char, row_capacity> buffer;
  for (const TraceSample& sample : trace) text.append(buffer.data(), format_row(sample, buffer));
  return text;
}

}  // namespace smoothsteer::io
