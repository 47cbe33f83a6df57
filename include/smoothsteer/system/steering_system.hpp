#pragma once
//! \file steering_system.hpp
//! One real-time object per car: the steering controller and what it needs from the car's
//! sensors, wired once. update() takes what a car's buses and localization give (rear-axle pose,
//! speed, longitudinal acceleration, yaw rate, lateral acceleration, and the measured road-wheel
//! angle where there is one), estimates the rear axle's side slip beta_r with SideSlipObserver
//! (the law steers the course psi + beta_r, docs/vehicle_dynamics.md), corrects it by what the
//! pose's steps say about the course (course_error_estimator.hpp), runs the controller, and
//! returns the command, its derivatives and diagnostics: the observer's estimate and which limit
//! is active. The delay compensation (Smith predictor), the feedforward's single-track inversion
//! and the friction guard are the controller's own (ControllerParameters). The simulator drives
//! this same object (sim/simulation.hpp), so a car and the simulation share one wiring.
//!
//! \code
//!   // set-up (tuning/vehicle_steering_system.hpp): the car's description and the path
//!   smoothsteer::SteeringSystem system = smoothsteer::make_steering_system(car, path);
//!   // every period
//!   smoothsteer::SteeringSystemInput in;
//!   in.rear_axle_position = {x, y};
//!   in.heading_rad = psi;
//!   in.speed_mps = v;
//!   in.yaw_rate_radps = r;
//!   in.lateral_acceleration_mps2 = ay;
//!   in.steering_angle_rad = delta_measured;  // optional
//!   smoothsteer::SteeringSystemOutput out;
//!   if (system.update(in, out) == smoothsteer::Status::ok)
//!   actuator.command(out.steering_angle_rad);
//! \endcode
//! update() is noexcept, allocation free and deterministic; set_path() has the controller's
//! contract (SteeringController::set_path). Set-up (construction) throws std::invalid_argument.

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "smoothsteer/controller/active_limits.hpp"
#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/math/vec2.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/waypoint_conditioner.hpp"
#include "smoothsteer/status.hpp"
#include "smoothsteer/system/course_error_estimator.hpp"
#include "smoothsteer/system/driving_domain.hpp"
#include "smoothsteer/system/pose_latency_estimator.hpp"
#include "smoothsteer/system/steering_offset_compensation.hpp"
#include "smoothsteer/validation.hpp"
#include "smoothsteer/vehicle/side_slip_observer.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer {

//! Where the rear axle's side slip beta_r that the law steers comes from.
enum class SlipInput {
  kinematic,  //!< beta_r = 0: the kinematic assumption (course = heading)
  sensor,     //!< SteeringSystemInput::rear_axle_side_slip_rad (a slip sensor; 0 when absent)
  observer,   //!< SideSlipObserver on yaw rate, lateral acceleration, speed and steering angle
};

struct SteeringSystemParameters {
  SlipInput slip_input = SlipInput::observer;
  //! The observer's model and sensor noise (used for SlipInput::observer only).
  SideSlipObserverParameters observer{};

  //! The paths the controller was certified for, when it was built for the car alone
  //! (make_steering_system(car, options)): set_path() measures each path's demand and update()
  //! sets limit_path_beyond_domain where it exceeds the domain at |v|. Absent: no such check.
  std::optional<DrivingDomain> domain;
  //! Above this |v| [m/s] the controller's limits are not certified (a gain schedule's last
  //! entry holds): update() sets limit_beyond_certified_speed. +inf: certified at every speed.
  double certified_max_speed_mps = std::numeric_limits<double>::infinity();
  //! Whether update() estimates the pose's age where the input does not give it
  //! (SteeringSystemInput::pose_age_s = 0; pose_latency_estimator.hpp): the lag of the pose's
  //! heading behind the gyro, plus the time since the pose last changed.
  bool estimate_pose_age = true;
  //! What the side-slip estimate gets wrong about the course (the slip's scale: load, tires, a
  //! wrong vehicle file; a course bias: crosswind), learned from the pose's steps
  //! (course_error_estimator.hpp). The law gets the corrected beta_r and the feedforward the
  //! scaled slip gradients. std::nullopt: beta_r as estimated, the vehicle file's gradients.
  std::optional<CourseErrorParameters> course_error = CourseErrorParameters{};
  //! The steering actuator's model (dead time and low-pass, steering_actuator.hpp) the command
  //! is held through. With it, the observer (its max_steering_offset_rad > 0) and a lead-wheel
  //! controller whose governor holds finite angle and rate limits, the held command makes up for
  //! the steering offset the observer learns, told apart from an angle sensor's bias by the
  //! actuator's predicted angle (steering_offset_compensation.hpp). Absent: no compensation.
  std::optional<ActuatorParameters> actuator;
  //! Whether the held command makes up for the steering offset (given the above).
  bool compensate_steering_offset = true;

  //! The vehicle file's observer (SideSlipObserverParameters::from_vehicle) with `tire_model`.
  static SteeringSystemParameters from_vehicle(
      const VehicleParameters& vehicle, ObserverTireModel tire_model = ObserverTireModel::linear);

  //! The first rule broken (validation.hpp); is_valid(), validation_error(), validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  std::string validation_error() const;
  void validate() const;  //!< throws std::invalid_argument
};

//! What a car's buses and localization give, once per control period.
struct SteeringSystemInput {
  Vec2 rear_axle_position;         //!< rear-axle reference point, world frame [m]
  double heading_rad = 0.0;        //!< psi [rad]
  double speed_mps = 0.0;          //!< signed longitudinal speed v [m/s]
  double acceleration_mps2 = 0.0;  //!< dv/dt [m/s^2]
  //! r, gyro [rad/s]. NaN (or any non-finite value): a dropped sample, which the observer
  //! skips and counts (SideSlipDiagnostics::sensors); the period does not fail.
  double yaw_rate_radps = 0.0;
  //! a_y at the CG, accelerometer [m/s^2]. NaN: a dropped sample, as the yaw rate's.
  double lateral_acceleration_mps2 = 0.0;
  double period_s = 0.02;  //!< control period dt [s]
  //! Measured road-wheel angle delta [rad], |delta| <= pi (else invalid_input); absent: the
  //! observer assumes the last command.
  std::optional<double> steering_angle_rad;
  //! A slip sensor's beta_r [rad] (SlipInput::sensor); absent: 0.
  std::optional<double> rear_axle_side_slip_rad;
  //! How old the pose (position and heading) is [s]: ControllerInput::pose_age_s. The other
  //! signals are taken as current. 0: not given; the system estimates it
  //! (SteeringSystemParameters::estimate_pose_age).
  double pose_age_s = 0.0;
};

//! The rear axle's side slip as the system sees it.
struct SideSlipDiagnostics {
  double rear_axle_side_slip_rad = 0.0;  //!< beta_r given to the law [rad]
  double side_slip_rad = 0.0;            //!< observer's beta at the CG [rad] (0 without one)
  double lateral_velocity_mps = 0.0;     //!< observer's vy [m/s]
  double yaw_rate_radps = 0.0;           //!< observer's filtered r [rad/s]
  //! observer's steering offset: the road wheels' angle minus the measured one [rad]
  double steering_offset_rad = 0.0;
  //! the filter's standard deviation of it [rad]
  double steering_offset_std_rad = 0.0;
  //! What the course error estimator learned (course_error_estimator.hpp; 0 without it): the
  //! slip's relative error a (the law's beta_r and the feedforward's slip gradients are taken
  //! times 1 + a) and the course bias c [rad], added to beta_r.
  double slip_error = 0.0;
  double course_bias_rad = 0.0;
  //! The observer's update() status (ok without an observer). Not ok: beta_r = 0 this period.
  Status observer_status = Status::ok;
  //! False when the observer's estimate is saturated, or no sample has corrected it for a while
  //! (sensor_fault_gate.hpp): the law then gets beta_r = 0, the kinematic assumption.
  bool estimate_trusted = true;
  //! What the observer's gates dropped and rejected (counts since reset) and this period's
  //! SensorFault bits; all zero without an observer.
  SideSlipObserverHealth sensors;
};

struct SteeringSystemOutput {
  double steering_angle_rad = 0.0;            //!< delta_veh command [rad]
  double steering_rate_radps = 0.0;           //!< valid if derivatives_available >= 1
  double steering_acceleration_radps2 = 0.0;  //!< valid if derivatives_available >= 2
  int derivatives_available = 0;
  //! The pose's age the controller carried the pose over [s]: the input's, or the estimate.
  double pose_age_s = 0.0;
  //! The steering offset the held command makes up for: the road wheels steer the command plus
  //! this [rad] (0 without compensation; steering_offset_compensation.hpp).
  double applied_steering_offset_rad = 0.0;
  //! The measured angle's bias against the actuator's predicted angle [rad] (0 without).
  double steering_angle_sensor_bias_rad = 0.0;
  TrackingDiagnostics tracking;     //!< the controller's diagnostics
  SideSlipDiagnostics side_slip;    //!< the observer's estimate
  std::uint32_t active_limits = 0;  //!< ActiveLimit bits
};

class SteeringSystem {
 public:
  //! Owns `controller` (any SteeringController). Throws std::invalid_argument for a null
  //! controller or invalid parameters, naming the field.
  SteeringSystem(std::unique_ptr<SteeringController> controller,
                 const SteeringSystemParameters& parameters);
  //! Borrows `controller`, which must outlive the system (the simulator's use).
  SteeringSystem(SteeringController& controller, const SteeringSystemParameters& parameters);
  //! The lead-wheel controller with `controller` on `path`, and the vehicle's observer. Throws
  //! std::invalid_argument naming the field when the parameters are invalid, the path is null,
  //! or controller.vehicle_wheelbase_m is not the vehicle's lf + lr.
  SteeringSystem(const VehicleParameters& vehicle, const ControllerParameters& controller,
                 std::shared_ptr<const Path> path, SlipInput slip_input = SlipInput::observer);

  SteeringSystem(SteeringSystem&&) noexcept = default;
  SteeringSystem& operator=(SteeringSystem&&) noexcept = default;

  //! One control period. Status as SteeringController::update; on an error nothing changes:
  //! not the output, not the observer, not the controller (every input is checked before a
  //! stage takes it). Besides the controller's ControllerInputRange, invalid_input for a
  //! measured steering angle that is not finite or beyond pi, and for a slip sensor's value
  //! beyond ControllerInput::max_side_slip_rad (SlipInput::sensor). A gyro or accelerometer
  //! sample that is dropped (NaN) or fails the observer's gates is skipped, not an error; an
  //! estimate the observer does not trust gives beta_r = 0 (side_slip.estimate_trusted).
  Status update(const SteeringSystemInput& input, SteeringSystemOutput& output) noexcept;
  //! Restarts the controller at the measured steering angle and the observer from straight
  //! driving. The controller's status (SteeringController::reset): invalid_input for NaN, inf,
  //! |angle| >= pi / 2 or beyond the car's angle limit, and then nothing changes.
  //! The observer's steering offset, which reset() keeps (the car's rack stays as it is), stays.
  Status reset(double measured_steering_angle_rad = 0.0) noexcept;
  //! The observer's steering offset and the compensation's back to 0 (a new car, a realigned
  //! rack or sensor).
  void forget_steering_offset() noexcept;
  //! The course error estimator's slip error and course bias back to 0 (a new car, new tires,
  //! another load); reset() keeps them.
  void forget_course_error() noexcept;
  //! Replanning: SteeringController::set_path's contract.
  //! With a domain (SteeringSystemParameters::domain) it also measures the path's demand
  //! (curvature_demand(): O(curvature samples), no allocation).
  Status set_path(std::shared_ptr<const Path> path) noexcept;
  //! A planner's window of waypoints, as a driving stack sends one every 0.1 s: fitted by the
  //! system's WaypointConditioner at the jitter pooled over the windows so far, with the
  //! earlier windows' waypoints behind it (clean windows interpolated; docs/controller.md,
  //! "Paths as they come"), then set_path(). Set-up time, not
  //! the control step: allocates, and throws std::invalid_argument for waypoints
  //! Path::from_waypoints refuses (the path is then not replaced).
  Status set_waypoints(const std::vector<Vec2>& waypoints);
  //! The jitter pooled over the windows set_waypoints() was given; reset() keeps it (it is the
  //! planner's).
  const WaypointConditioner& waypoint_conditioner() const noexcept { return conditioner_; }
  //! Forgets the pooled jitter and the earlier windows (another planner).
  void forget_waypoint_jitter() noexcept { conditioner_.reset(); }
  //! Evaluation hook: SteeringController::set_matched_disturbance.
  bool set_matched_disturbance(double lead_curvature_disturbance) noexcept {
    return controller_->set_matched_disturbance(lead_curvature_disturbance);
  }

  const SteeringController& controller() const noexcept { return *controller_; }
  //! The steering offset compensation (nullptr without one: see
  //! SteeringSystemParameters::actuator).
  const SteeringOffsetCompensation* steering_offset_compensation() const noexcept {
    return compensation_ ? &*compensation_ : nullptr;
  }
  //! The observer (nullptr unless SlipInput::observer).
  const SideSlipObserver* observer() const noexcept { return observer_ ? &*observer_ : nullptr; }
  const SteeringSystemParameters& parameters() const noexcept { return parameters_; }
  //! What the last update() gave the controller (its beta_r included), e.g. for error reports.
  const ControllerInput& controller_input() const noexcept { return controller_input_; }

 private:
  void set_up(const SteeringSystemParameters& parameters);
  //! Everything update() refuses, checked before any stage runs (controller_input_ is set).
  bool valid_input(const SteeringSystemInput& input) const noexcept;
  double rear_axle_side_slip(const SteeringSystemInput& input, SideSlipDiagnostics& slip) noexcept;

  std::unique_ptr<SteeringController> owned_;
  SteeringController* controller_ = nullptr;
  SteeringSystemParameters parameters_;
  std::optional<SideSlipObserver> observer_;
  //! The observer's next state, committed when the controller accepts the period.
  std::optional<SideSlipObserver> pending_observer_;
  std::optional<SteeringOffsetCompensation> compensation_;
  ControllerInput controller_input_;
  ControllerOutput controller_output_;  //!< the previous output, as update() expects
  PathCurvatureDemand path_demand_;     //!< of the last path set_path() accepted (with a domain)
  double last_command_rad_ = 0.0;
  PoseLatencyEstimator pose_latency_;  //!< its lag persists across reset()
  CourseErrorEstimator course_error_;  //!< its slip error and course bias persist across reset()
  WaypointConditioner conditioner_;    //!< set_waypoints()' pooled jitter
  Vec2 last_position_{};               //!< the pose of the last update, to see a new one
  double last_heading_rad_ = 0.0;
};

}  // namespace smoothsteer
