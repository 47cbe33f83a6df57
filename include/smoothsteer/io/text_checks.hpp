#pragma once
//! \file text_checks.hpp
//! The checks every reader of user text shares (scenario and vehicle YAML, waypoint CSV,
//! command-line values): one number syntax, one magnitude cap, UTF-8 validation.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace smoothsteer::io {

//! Largest magnitude accepted for any number read from a file or the command line. Inputs
//! beyond it (1e155 m away, radius 1e308) overflow squares and products inside the
//! arithmetic (a result would be inf or NaN); 1e9 m is still 25 times the circumference of the
//! earth.
inline constexpr double max_input_magnitude = 1e9;

//! Parses the whole of `text` as a decimal or exponent number ("0.3", "-1e-3", subnormals such
//! as "1e-308" included). Rejects empty text, trailing characters ("0.3garbage"), overflow
//! to infinity, and "inf"/"nan". Returns nullopt when rejected.
std::optional<double> parse_number(std::string_view text) noexcept;

//! Offset of the first byte of `text` that is not part of valid UTF-8 (overlong forms,
//! surrogates and code points above U+10FFFF are invalid), or nullopt if all of it is valid.
std::optional<std::size_t> invalid_utf8_offset(std::string_view text) noexcept;

//! Throws std::runtime_error "<what>: not valid UTF-8 at line L, byte B" if `text` is not UTF-8.
void require_utf8(std::string_view text, const std::string& what);

}  // namespace smoothsteer::io
