#pragma once
//! \file lead_wheel_controller.hpp
//! The n-smooth path-tracking controller: the Dubins-car sliding-mode law acts on the lead wheel
//! of a fictive trailer chain, whose front angle is the steering command (paper Sec. II).
//!
//! \code
//!   auto path = std::make_shared<const smoothsteer::Path>(smoothsteer::Path::circle({0, 0}, 30));
//!   smoothsteer::LeadWheelController controller(smoothsteer::ControllerParameters{}, path);
//!   smoothsteer::ControllerOutput out;
//!   controller.update({.rear_axle_position = {x, y}, .heading_rad = psi, .speed_mps = v,
//!                      .period_s = 0.02}, out);
//!   actuator.command(out.steering_angle_rad);
//! \endcode

#include <array>
#include <cmath>
#include <memory>

#include "smoothsteer/controller/actuator_inversion.hpp"
#include "smoothsteer/controller/chain_stepper.hpp"
#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/controller/delay_prediction.hpp"
#include "smoothsteer/controller/disturbance_estimator.hpp"
#include "smoothsteer/controller/dubins_switching_law.hpp"
#include "smoothsteer/controller/dynamics_inversion.hpp"
#include "smoothsteer/controller/feedforward.hpp"
#include "smoothsteer/controller/governor_stage.hpp"
#include "smoothsteer/controller/steering_certificate.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/controller/trailer_chain.hpp"
#include "smoothsteer/math/pose2.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer {

class LeadWheelController final : public SteeringController {
 public:
  //! Validates the parameters (std::invalid_argument on error) and requires a path.
  LeadWheelController(const ControllerParameters& parameters, std::shared_ptr<const Path> path);
  //! Without a path: update() returns not_configured until set_path() gives one.
  LeadWheelController(const ControllerParameters& parameters, PathLater);
  //! False until a path is set (only after the PathLater constructor).
  bool has_path() const noexcept { return path_ != nullptr; }

 protected:
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override;

 public:
  //! Re-initialises the chain in stationary cornering at the measured steering angle for
  //! forward driving; the direction is re-detected from v. An angle beyond the invariant set
  //! starts the chain at its bound, and the command moves from the measured angle to the
  //! chain's within the rate limit (the governor's R, else the certified rate |v|
  //! certificate().rate_per_meter), not at once. invalid_input, and nothing changes, for an
  //! angle valid_reset_angle() refuses with the car's angle limit, governor.max_steering_angle_rad
  //! (ScheduledController::reset refuses the same).
  //! The disturbance estimate persists across it (DisturbanceEstimator::reset()).
  Status reset(double measured_steering_angle_rad = 0.0) noexcept override;
  //! Clears the disturbance estimate (a new car, a wheel alignment, a test from scratch).
  void forget_disturbance_estimate() noexcept { disturbance_.forget(); }
  const char* name() const noexcept override { return "lead_wheel"; }
  //! The bounds the step's command is at (src/controller/active_limits.cpp): kbar_n, kbar_ff,
  //! the friction guard's curvature at |v|, kbar_sw and the front angle's invariant set.
  std::uint32_t active_limits(const ControllerOutput& output,
                              double speed_mps) const noexcept override;
  //! The governor's angle, rate and acceleration limits (SteeringGovernor).
  std::optional<SteeringLimits> car_steering_limits() const noexcept override;
  //! Replanning (SteeringController::set_path): swaps the path and re-seeds the three hints;
  //! the chain state, direction and delay history carry on, so delta_veh stays continuous
  //! (src/controller/lead_wheel_set_path.cpp).
  Status set_path(std::shared_ptr<const Path> path) noexcept override;

  //! Real-time parameter change (gain scheduling, docs/tuning.md): noexcept, no allocation.
  //! Keeps the commanded delta_veh continuous by re-mapping delta_1 to the new lambda_1
  //! (tan(delta_veh)/lambda_veh = tan(delta_1)/lambda_1); for n >= 2 it also re-solves delta_2 so
  //! that d delta_veh / ds is unchanged (the command stays C^1 across a retune), and it keeps
  //! delta_3..delta_n. No chain angle is clamped into the new invariant sets, since a jump of the
  //! state would be a kink in delta_veh: an angle left outside a shrunken set returns under the
  //! chain's own flow (integrate_chain). kappa_ff is clamped to the new kbar_ff. Returns
  //! invalid_input, leaving the controller unchanged, if the parameters are invalid (is_valid())
  //! or change the order n.
  Status retune(const ControllerParameters& parameters) noexcept;

  //! Evaluation hook: a matched disturbance kappa_d added to the lead-wheel curvature, i.e. the
  //! extended system receives kappa_n + kappa_d (paper Sec. III item 2: d psi_l / ds_l =
  //! kappa_l + kappa_d). The law stays convergent for |kappa_d| < k_rob kbar_sw, the switching
  //! part's authority (docs/feedforward.md, section 4).
  //! Returns false, and keeps the previous value, for a non-finite kappa_d or one beyond
  //! max_matched_disturbance_per_m: far beyond any robustness bound, it only breaks the arithmetic.
  bool set_matched_disturbance(double lead_curvature_disturbance) noexcept override {
    if (!(std::abs(lead_curvature_disturbance) <= max_matched_disturbance_per_m)) return false;
    matched_disturbance_ = lead_curvature_disturbance;
    return true;
  }
  //! Largest |kappa_d| set_matched_disturbance accepts [1/m]: a 1 m radius, as the scenario
  //! schema's simulation.matched_disturbance.
  static constexpr double max_matched_disturbance_per_m = 1.0;

  const ControllerParameters& parameters() const noexcept { return parameters_; }
  const ChainBounds& bounds() const noexcept { return bounds_; }
  //! Certified rate and acceleration of delta_veh under the feedforward split
  //! (steering_certificate.hpp); the box bound bounds().steering_rate_per_meter holds as well.
  const SteeringCertificate& certificate() const noexcept { return certificate_; }
  //! Current kappa_ff [1/m] (rate limited and saturated, docs/feedforward.md).
  double feedforward_curvature() const noexcept { return feedforward_curvature_; }
  //! The plant's curvature disturbance as estimated (0 unless disturbance_estimation is on).
  double disturbance_estimate() const noexcept { return disturbance_.estimate(); }
  const ChainAngles& chain_angles() const noexcept { return angles_; }
  //! +1 while driving forwards, -1 in reverse.
  double direction() const noexcept { return direction_; }
  //! Steering angle of the real vehicle for chain front angle delta_1 (paper_notes §3):
  //! tan(delta_veh) / lambda_veh = direction * tan(delta_1) / lambda_1.
  double vehicle_steering_angle(double front_angle) const noexcept;

 private:
  //! What the sub-steps of one period share.
  struct PeriodPlan {
    double speed_magnitude = 0.0;    //!< |v| [m/s]
    double guard = 0.0;              //!< the friction guard's largest lead curvature [1/m]
    double feedforward_bound = 0.0;  //!< kbar_ff, within the guard [1/m]
    double feedforward_step = 0.0;   //!< how far kappa_ff may move in a sub-step [1/m]
  };
  struct LeadWheelState {
    PathProjection projection;
    double relative_heading = 0.0;
    double lateral_error = 0.0;       //!< e of the lead wheel from its target curve
    double feedforward_target = 0.0;  //!< curvature that keeps the lead wheel on its target curve
    SwitchingResult law;              //!< the switching part kappa_sw
  };
  // The stages of compute_command() (src/controller/lead_wheel_step.cpp), in the order they run.
  //! A change of the direction of travel mirrors the chain (initialise_chain()).
  void follow_direction_of_travel(double speed_mps) noexcept;
  //! Stages 1-3: the single-track inversion, the disturbance estimate and the delay prediction;
  //! returns the rear axle's pose (position and course) the law acts on.
  Pose2 predict_law_pose(const ControllerInput& input) noexcept;
  //! Stage 2, the disturbance estimate, from the course turned since the last period.
  void estimate_disturbance(const ControllerInput& input) noexcept;
  //! The period's sub-steps (stepper) and governor, and what the split needs from them.
  PeriodPlan begin_period(const ControllerInput& input, const Pose2& law_pose,
                          ChainStepper& stepper) noexcept;
  //! One sub-step: law, governor, split (stage 4), chain; returns kappa_n. The first sub-step
  //! keeps its lead-wheel state in `first` for the diagnostics.
  double substep(const PeriodPlan& plan, bool first_substep, ChainStepper& stepper,
                 LeadWheelState& first) noexcept;
  //! delta_veh of the chain (or of n = 0's kappa_n) and its time derivatives.
  SteeringCommand chain_command(double speed_magnitude, double acceleration_mps2,
                                double lead_curvature) const noexcept;
  //! Stage 5, the actuator inversion, then the approach after a reset; writes the command.
  void send_command(SteeringCommand command, double speed_magnitude, double period_s,
                    ControllerOutput& output) noexcept;
  //! The real axles' errors and the step's internals; feeds the estimate the rear axle's path.
  void write_diagnostics(const ControllerInput& input, const LeadWheelState& first,
                         double lead_curvature, ControllerOutput& output) noexcept;

  //! refresh_target: recompute target_ at this projection (once per period, the first sub-step).
  //! The switching part has authority switching_bound and boundary layer boundary_layer;
  //! feedforward_rate is the rate kappa_ff moves at in this period (L_ff, or the governor's).
  LeadWheelState evaluate_lead_wheel(Vec2 rear_position, double rear_travel_heading,
                                     bool refresh_target, double switching_bound,
                                     double boundary_layer, double feedforward_rate) noexcept;
  //! The curve the lead wheel tracks near its closest point (feedforward.hpp); the planned kinks
  //! are rounded for kappa_ff moving at feedforward_rate (jump_plan.hpp).
  TargetCurve target_curve(const PathProjection& lead, double feedforward_rate) const noexcept;
  //! Sets the parameters and what derives from them (bounds, sum lambda_i^2, sub-step length).
  void apply_parameters(const ControllerParameters& parameters) noexcept;
  //! Heading of the direction of travel: psi, or psi + pi while reversing.
  double travel_heading(double heading) const noexcept;
  //! Stationary chain at this delta_veh (clamped into the invariant set only), kappa_ff := its
  //! lead curvature saturated at kbar_ff: the command continues through resets and cusps.
  void initialise_chain(double vehicle_steering_angle) noexcept;
  double front_angle_from_vehicle(double vehicle_steering_angle) const noexcept;
  double vehicle_steering_angle_of_chain() const noexcept;
  //! The Smith predictor's delay [s]; 0 while the delay compensation is off.
  double compensated_delay_s() const noexcept {
    return parameters_.delay_compensation.enabled ? parameters_.delay_compensation.actuator_delay_s
                                                  : 0.0;
  }
  //! How far back the pose's information lies behind the moment this command takes effect [s]:
  //! the Smith predictor's delay plus the pose's age. The prediction and the disturbance
  //! estimate's "command in effect" both reach back this far.
  double prediction_horizon_s(const ControllerInput& input) const noexcept {
    return compensated_delay_s() + input.pose_age_s;
  }
  //! The rate [rad/s] at which the command approaches the chain's after a reset beyond the set.
  double approach_rate_radps(double speed) const noexcept;
  //! While approaching: `steering` held within the approach rate of the last command.
  void approach_step(double speed, double period_s, double& steering, double& rate,
                     double& acceleration) noexcept;
  //! Largest lead curvature the friction guard allows at `speed` [1/m] (+inf: no guard).
  double friction_guard_curvature(double speed) const noexcept;

  ControllerParameters parameters_;
  std::shared_ptr<const Path> path_;
  ChainBounds bounds_;
  SteeringCertificate certificate_;
  double feedforward_curvature_ = 0.0;
  // The stages of compute_command() that keep state of their own, in the order they run:
  // the single-track inversion at the current speed, the disturbance estimate, the delay
  // prediction (whose command history the estimate reads too), the steering governor.
  DynamicsInversion dynamics_{};
  DisturbanceEstimator disturbance_{};
  DelayPrediction delay_{};
  GovernorStage governor_{};
  TargetCurve target_;  //!< target curve of the current period
  ChainAngles angles_{};
  double chain_length_squared_ = 0.0;  //!< sum lambda_i^2, for the cornering offset
  double chain_reach_ = 0.0;  //!< sum lambda_i: how far ahead of the rear axle the lead wheel is
  double largest_substep_m_ = 0.0;  //!< max_substep_fraction * min lambda_i [m]
  double direction_ = 1.0;
  double matched_disturbance_ = 0.0;
  double last_steering_angle_ = 0.0;
  //! After a reset beyond the invariant set: the last command while it approaches the chain's.
  double approach_angle_ = 0.0;
  bool approaching_ = false;
  ProjectionHint rear_hint_, front_hint_, lead_hint_;
};

}  // namespace smoothsteer
