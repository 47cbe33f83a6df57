// Waypoint CSV reader (include/smoothsteer/io/waypoint_csv.hpp).

#include "smoothsteer/io/waypoint_csv.hpp"

#include <cmath>
#include <optional>
#include <sstream>

#include "smoothsteer/io/bounded_file.hpp"
#include "smoothsteer/io/config_section.hpp"
#include "smoothsteer/io/text_checks.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer::io {
namespace {

std::string trim(const std::string& text) {
  const std::size_t begin = text.find_first_not_of(" \t");
  if (begin == std::string::npos) return "";
  const std::size_t end = text.find_last_not_of(" \t");
  return text.substr(begin, end - begin + 1);
}

}  // namespace

std::vector<Vec2> parse_waypoint_csv(const std::string& text, const std::string& file) {
  try {
    require_utf8(text, file);
  } catch (const std::runtime_error& error) {
    throw ConfigError(error.what());
  }
  std::vector<Vec2> points;
  std::vector<int> lines;  //!< the line of each waypoint, to name a bad one
  std::istringstream in(text);
  std::string line;
  int number = 0;
  bool first = true;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trim(line).empty() || trim(line)[0] == '#') continue;
    const std::size_t comma = line.find(',');
    if (first && line.find_first_of("xXyY") != std::string::npos) {
      first = false;
      continue;  // header line "x,y"
    }
    first = false;
    const auto fail = [&](const std::string& rule) {
      throw ConfigError(file + ": line " + std::to_string(number) + ": " + rule + ", got '" +
                        line.substr(0, 80) + "'");
    };
    if (comma == std::string::npos || line.find(',', comma + 1) != std::string::npos) {
      fail("expected two finite numbers 'x,y'");
    }
    const auto x = parse_number(trim(line.substr(0, comma)));
    const auto y = parse_number(trim(line.substr(comma + 1)));
    if (!x || !y) fail("expected two finite numbers 'x,y'");
    if (std::abs(*x) > max_input_magnitude || std::abs(*y) > max_input_magnitude) {
      fail("coordinates must have magnitude <= 1e9 m");
    }
    if (points.size() == max_waypoints) {
      fail("more than " + std::to_string(max_waypoints) + " waypoints");
    }
    points.push_back({*x, *y});
    lines.push_back(number);
  }
  if (points.size() < 2) throw ConfigError(file + ": needs at least 2 waypoints");
  if (const std::optional<std::size_t> turn = Path::find_reversal(points)) {
    throw ConfigError(file + ": line " + std::to_string(lines[*turn]) +
                      ": the path turns back on itself at this waypoint (more than 120 degrees "
                      "from the previous chord to the next, alone or with the turns within 1 mm "
                      "after it); a path that changes direction needs "
                      "one path per direction (docs/cusps.md)");
  }
  return points;
}

std::vector<Vec2> read_waypoint_csv(const std::string& file) {
  try {
    return parse_waypoint_csv(read_bounded_file(file, max_waypoint_file_bytes, "waypoint file"),
                              file);
  } catch (const FileReadError& error) {
    throw ConfigError(error.what());
  }
}

}  // namespace smoothsteer::io
