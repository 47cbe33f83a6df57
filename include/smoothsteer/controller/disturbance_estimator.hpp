#pragma once
//! \file disturbance_estimator.hpp
//! Stage of LeadWheelController::compute_command(): the estimate of the curvature the plant adds
//! at the rear axle (ControllerParameters::disturbance_estimation, docs/feedforward.md
//! "disturbances on the vehicle"): the measured course curvature minus the commanded one,
//! low-passed over the estimation length once the path has let the car settle.

#include "smoothsteer/controller/delay_prediction.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/math/vec2.hpp"

namespace smoothsteer {

class DisturbanceEstimator {
 public:
  //! What one update needs from the controller's other stages.
  struct Context {
    bool enabled = false;
    double length_m = 0.0;           //!< low-pass length [m]
    double direction = 1.0;          //!< +1 forwards: the estimate learns only then
    double delay_s = 0.0;            //!< the delay compensation's delay [s]
    double slip_lag_m = 0.0;         //!< the single-track inversion's slip lag [m]
    double dynamics_gain = 1.0;      //!< g of the single-track inversion
    double wheelbase_m = 1.0;        //!< lambda_veh
    double feedforward_bound = 0.0;  //!< kbar_ff: the estimate stays within it
  };

  //! Forgets the estimate and the previous pose (LeadWheelController::reset()).
  void reset() noexcept {
    has_previous_pose_ = false;
    estimate_ = 0.0;
    steady_path_m_ = 0.0;
  }
  //! One control period, before the law: learns from the course turned since the last one.
  void update(const ControllerInput& input, const Context& context,
              const DelayPrediction& commands) noexcept;
  //! The path's curvature at the rear axle in this period, after the law's projection.
  void set_rear_path_curvature(double curvature) noexcept { rear_path_curvature_ = curvature; }
  double estimate() const noexcept { return estimate_; }

  //! The estimate learns once the path's curvature has stayed steady (lateral jerk
  //! v^3 |d kappa / ds| below 0.1 m/s^3, a fifth of the road-design comfort limit) for the
  //! settling distance max(5 m, 0.5 s v) and then as much again: the slip and actuator lags the
  //! model leaves have died out by then.
  static constexpr double steady_lateral_jerk_mps3 = 0.1;
  static constexpr double min_settling_m = 5.0;
  static constexpr double settling_time_s = 0.5;

 private:
  double estimate_ = 0.0;           //!< kappa_d estimate [1/m]
  Vec2 previous_position_{};        //!< rear axle at the last update()
  double previous_course_ = 0.0;    //!< psi + beta_r at the last update()
  bool has_previous_pose_ = false;  //!< previous_position_ and previous_course_ are set
  //! The path's curvature at the rear axle at the last two update()s, and how far the car has
  //! driven since it last moved faster than steady_lateral_jerk_mps3 allows [m].
  double rear_path_curvature_ = 0.0;
  double previous_rear_path_curvature_ = 0.0;
  double steady_path_m_ = 0.0;
};

}  // namespace smoothsteer
