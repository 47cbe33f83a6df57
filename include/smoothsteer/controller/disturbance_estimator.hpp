#pragma once
//! \file disturbance_estimator.hpp
//! Stage of LeadWheelController::compute_command(): the estimate of the curvature the plant adds
//! at the rear axle (ControllerParameters::disturbance_estimation, docs/feedforward.md
//! "disturbances on the vehicle"): the measured course curvature minus the commanded one,
//! averaged once the path has let the car settle. The average is a running mean over what it has
//! learned so far, whose memory grows to the estimation length: fast while it knows little (the
//! first metres count fully), then averaging the sensors' noise over the whole length. The
//! estimate persists across reset() (a new engagement, a restart at a measured angle): a rack
//! offset, a tire's pull or a road's usual crossfall stay; forget() clears it.

#include "smoothsteer/controller/delay_prediction.hpp"
#include "smoothsteer/controller/dynamics_inversion.hpp"
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
    DynamicsInversion dynamics;      //!< the single-track inversion at this speed (its slip lag)
    double wheelbase_m = 1.0;        //!< lambda_veh
    double feedforward_bound = 0.0;  //!< kbar_ff: the estimate stays within it
  };

  //! A new engagement (LeadWheelController::reset()): forgets the previous pose and the path's
  //! settling, keeps the estimate and what it has learned.
  void reset() noexcept {
    has_previous_pose_ = false;
    steady_path_m_ = 0.0;
    engaged_ = false;
  }
  //! Forgets the estimate too: back to 0 and to the shortest memory.
  void forget() noexcept {
    reset();
    estimate_ = 0.0;
    learned_m_ = 0.0;
  }
  //! One control period, before the law: learns from the course turned since the last one.
  void update(const ControllerInput& input, const Context& context,
              const DelayPrediction& commands) noexcept;
  //! The path's curvature and the rear axle's lateral error in this period, after the law's
  //! projection (the error for the engagement gate).
  void set_rear_path(double curvature, double lateral_error_m) noexcept {
    rear_path_curvature_ = curvature;
    rear_lateral_error_m_ = lateral_error_m;
  }
  double estimate() const noexcept { return estimate_; }
  //! The distance the running mean has learned over [m], at most the estimation length.
  double learned_m() const noexcept { return learned_m_; }

  //! The running mean's shortest memory [m]: the first learned metres are averaged over at least
  //! this, so that one period's noise cannot set the estimate.
  static constexpr double min_memory_m = 2.0;

  //! The estimate learns once the path's curvature has stayed steady (lateral jerk
  //! v^3 |d kappa / ds| below 0.1 m/s^3, a fifth of the road-design comfort limit) for the
  //! settling distance max(5 m, 0.5 s v) and then as much again: the slip and actuator lags the
  //! model leaves have died out by then.
  static constexpr double steady_lateral_jerk_mps3 = 0.1;
  //! After reset() the estimate learns only once the rear axle has come this close to the path:
  //! an engagement from off the path is a transient, not a disturbance (circle_sections starts
  //! 1 m off; learning from 0.5 m on put 2.2e-3 1/m into the estimate at its start).
  static constexpr double engaged_lateral_error_m = 0.1;
  //! While the command turns faster than this, the tires' slip lags it by more than the model's
  //! delay covers, and the settling starts again: an engagement turns at 0.1-0.4 rad/s. 0.05
  //! rad/s also paused the law's recovery from disturbances_15's drift (4 cm left at 10 s).
  static constexpr double settled_steering_rate_radps = 0.1;
  //! Where the model is not to be trusted the estimate does not learn: below this speed (the
  //! tires' slip model and the course's differences lose their meaning at parking speed) and
  //! above this lateral acceleration of the path (about 0.4 g, where a passenger car's tires
  //! leave their linear range and the difference is the tires' saturation, not a disturbance;
  //! 3 m/s^2 froze a value learned at the start of circle_sections' arcs: 0.10 -> 0.12 m). No
  //! gate on the lateral error: a disturbance larger than the feedback's share pushes the car
  //! beyond any such gate, which then would never let the estimate learn it (2.4 m on
  //! disturbances_15 with a 0.5 m gate).
  static constexpr double min_learning_speed_mps = 3.0;
  static constexpr double max_learning_lateral_acceleration_mps2 = 4.0;
  static constexpr double min_settling_m = 5.0;
  static constexpr double settling_time_s = 0.5;

 private:
  double estimate_ = 0.0;           //!< kappa_d estimate [1/m]
  double learned_m_ = 0.0;          //!< the running mean's memory so far [m]
  Vec2 previous_position_{};        //!< rear axle at the last update()
  double previous_course_ = 0.0;    //!< psi + beta_r at the last update()
  bool has_previous_pose_ = false;  //!< previous_position_ and previous_course_ are set
  //! The path's curvature at the rear axle at the last two update()s, and how far the car has
  //! driven since it last moved faster than steady_lateral_jerk_mps3 allows [m].
  double rear_path_curvature_ = 0.0;
  double rear_lateral_error_m_ = 0.0;
  bool engaged_ = false;  //!< |e| has been within engaged_lateral_error_m since reset()
  double previous_rear_path_curvature_ = 0.0;
  double steady_path_m_ = 0.0;
};

}  // namespace smoothsteer
