//! PathPlan: validation and assembly of pieces with gears.

#include "smoothsteer/path/path_plan.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "path_detail.hpp"
#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {
namespace {

[[noreturn]] void fail(const std::string& message) {
  throw std::invalid_argument(message);
}

}  // namespace

PathPlan PathPlan::from_pieces(std::vector<PathPiece> pieces) {
  constexpr const char* where = "PathPlan::from_pieces";
  if (pieces.empty()) fail(std::string(where) + ": pieces is empty; need at least 1 piece");
  if (pieces.size() > max_cusps + 1) {
    fail(std::string(where) + ": " + std::to_string(pieces.size()) + " pieces, " +
         std::to_string(pieces.size() - 1) +
         " gear changes; at most max_cusps = " + std::to_string(max_cusps));
  }
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const std::string name = "pieces[" + std::to_string(i) + "]";
    if (!pieces[i].path)
      fail(std::string(where) + ": " + name + ".path is null; a path is required");
    if (pieces[i].path->is_closed()) {
      fail(std::string(where) + ": " + name + ".path is closed; a piece must be open");
    }
    if (pieces[i].gear != Gear::forward && pieces[i].gear != Gear::reverse) {
      fail(std::string(where) + ": " + name + ".gear must be Gear::forward or Gear::reverse");
    }
    if (i == 0) continue;
    const Path& before = *pieces[i - 1].path;
    const Vec2 end = before.evaluate(before.length()).position;
    const double gap = norm(pieces[i].path->evaluate(0.0).position - end);
    if (!(gap <= joint_tolerance_m)) {
      fail(std::string(where) + ": " + name + ".path starts " + detail::format_number(gap) +
           " m from the end of pieces[" + std::to_string(i - 1) +
           "]; consecutive pieces must meet within 0.001 m");
    }
  }
  PathPlan plan;
  plan.pieces_ = std::move(pieces);
  return plan;
}

PathPlan PathPlan::from_waypoints(const std::vector<Vec2>& waypoints,
                                  const std::vector<int>& directions) {
  constexpr const char* where = "PathPlan::from_waypoints";
  if (directions.size() != waypoints.size()) {
    fail(std::string(where) + ": directions.size() = " + std::to_string(directions.size()) +
         " must equal waypoints.size() = " + std::to_string(waypoints.size()));
  }
  if (waypoints.size() < 2) {
    fail(std::string(where) + ": waypoints.size() = " + std::to_string(waypoints.size()) +
         " must be >= 2");
  }
  for (std::size_t i = 0; i + 1 < directions.size(); ++i) {
    if (directions[i] != 1 && directions[i] != -1) {
      fail(std::string(where) + ": directions[" + std::to_string(i) +
           "] = " + std::to_string(directions[i]) + " must be +1 (forward) or -1 (reverse)");
    }
  }
  std::vector<PathPiece> pieces;
  std::size_t first = 0;
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    const bool last = i + 1 == waypoints.size();
    if (!last && directions[i] == directions[i - 1]) continue;
    // waypoints[first..i] form one piece; waypoints[i] is a cusp unless it is the last one.
    const std::vector<Vec2> piece_points(waypoints.begin() + static_cast<std::ptrdiff_t>(first),
                                         waypoints.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    const Gear gear = directions[first] > 0 ? Gear::forward : Gear::reverse;
    try {
      pieces.push_back({std::make_shared<const Path>(Path::from_waypoints(piece_points)), gear});
    } catch (const std::invalid_argument& error) {
      fail(std::string(where) + ": piece from waypoints[" + std::to_string(first) +
           "] to waypoints[" + std::to_string(i) + "]: " + error.what());
    }
    first = i;
  }
  return from_pieces(std::move(pieces));
}

std::size_t PathPlan::cusp_count() const noexcept {
  std::size_t count = 0;
  for (std::size_t i = 1; i < pieces_.size(); ++i) {
    if (pieces_[i].gear != pieces_[i - 1].gear) ++count;
  }
  return count;
}

Vec2 PathPlan::final_position() const noexcept {
  const Path& last = *pieces_.back().path;
  return last.evaluate(last.length()).position;
}

double PathPlan::final_vehicle_heading_rad() const noexcept {
  const Path& last = *pieces_.back().path;
  const double travel = last.evaluate(last.length()).heading_rad;
  return wrap_angle(pieces_.back().gear == Gear::reverse ? travel + pi : travel);
}

}  // namespace smoothsteer
