#include "smoothsteer/controller/chain_stepper.hpp"

#include <algorithm>
#include <cmath>

namespace smoothsteer {

int ChainStepper::substep_count(double distance_m, double largest_substep_m, int max_substeps,
                                int order) noexcept {
  if (order <= 0 || !(distance_m > 0.0)) return 1;
  return std::clamp(static_cast<int>(std::ceil(distance_m / largest_substep_m)), 1, max_substeps);
}

void ChainStepper::begin_period(Vec2 position, double travel_heading, double distance_m,
                                double largest_substep_m, int max_substeps, int order) noexcept {
  steps_ = substep_count(distance_m, largest_substep_m, max_substeps, order);
  step_length_ = distance_m / steps_;
  position_ = position;
  heading_ = travel_heading;
}

void ChainStepper::advance(ChainAngles& angles, const double* wheelbases, int order,
                           double start_curvature, double end_curvature,
                           const ChainAngles& angle_bound, double disturbance_curvature) noexcept {
  const double front_before = angles[0];
  integrate_chain(angles, wheelbases, order, start_curvature, end_curvature, step_length_,
                  angle_bound);
  const double curvature =
      0.5 * (std::tan(front_before) + std::tan(angles[0])) / wheelbases[0] + disturbance_curvature;
  const double half_turn = 0.5 * curvature * step_length_;
  position_ = position_ + step_length_ * unit_from_heading(heading_ + half_turn);
  heading_ += 2.0 * half_turn;
}

}  // namespace smoothsteer
