// Shared checks of user text (include/smoothsteer/io/text_checks.hpp).

#include "smoothsteer/io/text_checks.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace smoothsteer::io {

std::optional<double> parse_number(std::string_view text) noexcept {
  if (text.empty() || text.size() > 64) return std::nullopt;
  // Only digits, sign, point and exponent: strtod would also take "inf", "nan", hex floats
  // and leading blanks.
  for (char ch : text) {
    const bool allowed =
        (ch >= '0' && ch <= '9') || ch == '+' || ch == '-' || ch == '.' || ch == 'e' || ch == 'E';
    if (!allowed) return std::nullopt;
  }
  const std::string copy(text);
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size()) return std::nullopt;
  // ERANGE also flags underflow; a subnormal or zero result is a valid number, overflow is not.
  if (errno == ERANGE && !(std::abs(value) <= 1.0)) return std::nullopt;
  if (!std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<std::size_t> invalid_utf8_offset(std::string_view text) noexcept {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  std::size_t i = 0;
  while (i < text.size()) {
    const unsigned char lead = byte(i);
    if (lead < 0x80) {
      ++i;
      continue;
    }
    std::size_t length = 0;
    unsigned code = 0;
    if ((lead & 0xE0) == 0xC0) {
      length = 2;
      code = lead & 0x1Fu;
    } else if ((lead & 0xF0) == 0xE0) {
      length = 3;
      code = lead & 0x0Fu;
    } else if ((lead & 0xF8) == 0xF0) {
      length = 4;
      code = lead & 0x07u;
    } else {
      return i;
    }
    if (i + length > text.size()) return i;
    for (std::size_t k = 1; k < length; ++k) {
      if ((byte(i + k) & 0xC0) != 0x80) return i;
      code = (code << 6) | (byte(i + k) & 0x3Fu);
    }
    const unsigned smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < smallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) {
      return i;
    }
    i += length;
  }
  return std::nullopt;
}

void require_utf8(std::string_view text, const std::string& what) {
  const auto offset = invalid_utf8_offset(text);
  if (!offset) return;
  std::size_t line = 1;
  for (std::size_t i = 0; i < *offset; ++i) line += text[i] == '\n' ? 1 : 0;
  throw std::runtime_error(what + ": not valid UTF-8 at line " + std::to_string(line) + ", byte " +
                           std::to_string(*offset + 1));
}

}  // namespace smoothsteer::io
