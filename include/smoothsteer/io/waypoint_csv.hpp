#pragma once
//! \file waypoint_csv.hpp
//! Waypoint CSV files (`path: {type: waypoints_csv, file: ...}`, docs/scenarios.md): one
//! "x,y" pair per line in metres, an optional header line naming x and y, `#` comments and
//! blank lines. Errors are ConfigError naming the file, the line and the rule.

#include <string>
#include <vector>

#include "smoothsteer/math/vec2.hpp"

namespace smoothsteer::io {

//! Most waypoints one file may give (the path builder fits one cubic per pair).
inline constexpr std::size_t max_waypoints = 1'000'000;

//! Parses the text of a waypoint CSV; `file` names it in messages.
std::vector<Vec2> parse_waypoint_csv(const std::string& text, const std::string& file);
//! Reads and parses a waypoint CSV file (must be a regular file, UTF-8).
std::vector<Vec2> read_waypoint_csv(const std::string& file);

}  // namespace smoothsteer::io
