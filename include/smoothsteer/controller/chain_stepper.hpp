#pragma once
//! \file chain_stepper.hpp
//! Stage of LeadWheelController::compute_command(): one control period of the fictive chain in
//! sub-steps. The switching law is re-evaluated at every RK4 sub-step; the first one sees the
//! law's pose (measured, or predicted over the actuator delay), later ones the rear-axle pose
//! the chain's own kinematics predict (rear curvature tan(delta_1) / lambda_1). This keeps the
//! discrete sliding band of the lead wheel at O(kbar h^2) for the sub-step h instead of
//! O(kbar (v dt)^2).

#include "smoothsteer/controller/trailer_chain.hpp"
#include "smoothsteer/math/vec2.hpp"

namespace smoothsteer {

class ChainStepper {
 public:
  //! The number of sub-steps for `distance_m` of travel: none longer than largest_substep_m,
  //! between 1 and max_substeps; 1 for n = 0 or a car at rest.
  static int substep_count(double distance_m, double largest_substep_m, int max_substeps,
                           int order) noexcept;

  //! A new period from the rear axle's `position` and travel heading over `distance_m`.
  void begin_period(Vec2 position, double travel_heading, double distance_m,
                    double largest_substep_m, int max_substeps, int order) noexcept;
  int steps() const noexcept { return steps_; }
  //! The sub-step's rear arc length h [m].
  double step_length() const noexcept { return step_length_; }
  //! The rear axle's predicted position and travel heading at the start of the next sub-step.
  Vec2 position() const noexcept { return position_; }
  double heading() const noexcept { return heading_; }

  //! One sub-step: the chain integrated with kappa_n linear from start_curvature to
  //! end_curvature (integrate_chain), and the rear axle moved along an arc of the mean chain
  //! curvature over the sub-step plus the plant's estimated disturbance.
  void advance(ChainAngles& angles, const double* wheelbases, int order, double start_curvature,
               double end_curvature, const ChainAngles& angle_bound,
               double disturbance_curvature) noexcept;

 private:
  int steps_ = 1;
  double step_length_ = 0.0;
  Vec2 position_{};
  double heading_ = 0.0;
};

}  // namespace smoothsteer
