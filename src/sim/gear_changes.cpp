#include "smoothsteer/sim/gear_changes.hpp"

#include <charconv>
#include <stdexcept>
#include <string>

namespace smoothsteer {
namespace {

std::string text(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

double sign_of(double speed) {
  return speed > 0.0 ? 1.0 : (speed < 0.0 ? -1.0 : 0.0);
}

}  // namespace

std::vector<GearChange> gear_changes(const SpeedProfile& speed) {
  std::vector<GearChange> changes;
  if (!speed.knots || !speed.signed_speeds) return changes;
  const std::vector<SpeedKnot>& knots = *speed.knots;
  double moving = 0.0;  // the sign of the last knot in motion
  std::size_t first_rest = knots.size();
  for (std::size_t i = 0; i < knots.size(); ++i) {
    const double sign = sign_of(knots[i].speed_mps);
    if (sign == 0.0) {
      if (first_rest == knots.size()) first_rest = i;
      continue;
    }
    if (moving != 0.0 && sign != moving) {
      if (first_rest == knots.size()) {
        throw std::invalid_argument(
            "SpeedProfile: knots[" + std::to_string(i) +
            "].speed_mps = " + text(knots[i].speed_mps) +
            " changes the direction of travel without a knot at rest (0 m/s) before it");
      }
      changes.push_back({knots[first_rest].time_s, knots[i - 1].time_s});
    }
    moving = sign;
    first_rest = knots.size();
  }
  return changes;
}

void check_gear_changes(const PathPlan& plan, const SpeedProfile& speed, double control_period_s) {
  speed.validate();
  if (!speed.signed_speeds || !speed.knots) {
    throw std::invalid_argument(
        "SpeedProfile: signed_speeds = 0 must be 1 (a tabulated, signed profile) to drive a "
        "PathPlan");
  }
  for (std::size_t i = 1; i < plan.piece_count(); ++i) {
    if (plan.piece(i).gear == plan.piece(i - 1).gear) {
      throw std::invalid_argument("PathPlan: pieces[" + std::to_string(i) +
                                  "] has the gear of pieces[" + std::to_string(i - 1) +
                                  "]; a closed loop needs a gear change at every joint (join "
                                  "them into one path)");
    }
  }
  double first_sign = 0.0;
  for (const SpeedKnot& knot : *speed.knots) {
    if (knot.speed_mps != 0.0) {
      first_sign = sign_of(knot.speed_mps);
      break;
    }
  }
  if (first_sign != gear_sign(plan.piece(0).gear)) {
    throw std::invalid_argument("SpeedProfile: knots: the first speed in motion has sign " +
                                text(first_sign) + "; the first piece's gear needs " +
                                text(gear_sign(plan.piece(0).gear)));
  }
  const std::vector<GearChange> changes = gear_changes(speed);
  if (changes.size() != plan.cusp_count()) {
    throw std::invalid_argument("SpeedProfile: knots change the direction of travel " +
                                std::to_string(changes.size()) + " times; the plan has " +
                                std::to_string(plan.cusp_count()) + " cusps");
  }
  for (std::size_t i = 0; i < changes.size(); ++i) {
    const double rest = changes[i].resume_time_s - changes[i].stop_time_s;
    if (!(rest >= control_period_s * (1.0 - 1e-9))) {
      throw std::invalid_argument("SpeedProfile: the rest at gear change " + std::to_string(i) +
                                  " (t = " + text(changes[i].stop_time_s) + " s) lasts " +
                                  text(rest) + " s; at least one control period, " +
                                  text(control_period_s) + " s");
    }
  }
}

}  // namespace smoothsteer
