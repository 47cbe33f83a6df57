//! CuspSequencer: piece switching and the speed profile that stops at every cusp.

#include "smoothsteer/controller/cusp_sequencer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace smoothsteer {
std::optional<Violation> CuspSpeedOptions::first_violation() const noexcept {
  RuleChecker check("CuspSpeedOptions");
  check.require_positive({{"cruise_speed_mps", cruise_speed_mps},
                          {"deceleration_mps2", deceleration_mps2},
                          {"stop_tolerance_m", stop_tolerance_m}});
  return check.first();
}

CuspSequencer::CuspSequencer(PathPlan plan, SteeringController& controller,
                             const CuspSpeedOptions& options)
    : plan_(std::move(plan)), controller_(controller), options_(options) {
  options_.validate();
  if (controller_.set_path(plan_.piece(0).path) != Status::ok) {
    throw std::invalid_argument(std::string("CuspSequencer: controller '") + controller_.name() +
                                "' does not support set_path(); it cannot drive a PathPlan");
  }
}

double CuspSequencer::speed_command(Vec2 rear_axle_position, double period_s) noexcept {
  if (finished_ || !(period_s > 0.0)) return 0.0;
  const PathPiece& piece = plan_.piece(active_);
  const double travelled = piece.path->project(rear_axle_position, hint_).arc_length_m;
  const double left = piece.path->length() - travelled;
  if (left <= options_.stop_tolerance_m) {
    // Standstill at the cusp (or the end): switch pieces. The new piece starts where this one
    // ended, so the controller's re-seeded hints land at its start.
    if (active_ + 1 == plan_.piece_count()) {
      finished_ = true;
    } else {
      ++active_;
      hint_.reset();
      controller_.set_path(plan_.piece(active_).path);
    }
    return 0.0;
  }
  const double speed =
      std::min({options_.cruise_speed_mps, std::sqrt(2.0 * options_.deceleration_mps2 * left),
                left / period_s});
  return gear_sign(piece.gear) * speed;
}

}  // namespace smoothsteer
