#pragma once
//! \file side_slip_observer.hpp
//! Side-slip estimation for cars without a slip sensor (paper Outlook: "side slip can be
//! estimated and thus compensated"). A Kalman filter on the linear single-track model
//! (Rajamani, Vehicle Dynamics and Control, eqs. 2.31 and 2.45, written per axle) with the state
//! x = (vy, r) and what a production car measures: yaw rate r (gyro), lateral acceleration a_y
//! (accelerometer at the CG), speed vx and the road-wheel steering angle delta:
//!   d vy / dt = -(Cf + Cr) / (m vx) vy - (vx + (Cf lf - Cr lr) / (m vx)) r + Cf / m delta
//!   d r / dt  = -(Cf lf - Cr lr) / (Iz vx) vy - (Cf lf^2 + Cr lr^2) / (Iz vx) r + Cf lf / Iz delta
//!   a_y = d vy / dt + vx r.
//! The transition is the exact matrix exponential of the 2 x 2 system over the period. What the
//! kinematic law needs is the rear axle's side slip beta_r = atan((vy - lr r) / vx): the angle
//! from the heading to the rear axle's course (docs/vehicle_dynamics.md).
//! Assumptions: linear tires (small slip angles, far from the friction limit), constant vx over
//! a period, a flat road, the accelerometer at the CG and free of roll. update() is noexcept,
//! allocation free and deterministic.
//! Near the friction limit the linear tire overstates the force a slip angle gives, so the filter
//! understates the slip. `ObserverTireModel::magic_formula` replaces the linear axle forces with
//! the vehicle file's lateral Magic Formula (Pacejka; the plant's own curve, scaled to the
//! believed cornering stiffness) and runs an extended Kalman filter on the same state and
//! measurements (docs/vehicle_dynamics.md, section 2).
//! A steering-angle sensor that reads off, or a rack that steers beside its reading, puts a
//! steering offset delta_o between the measured angle and the road wheels' (a bias the model
//! would otherwise turn into a wrong slip: 0.01 rad left 0.15 m beside the path). The filter
//! carries it as a third state, x = (vy, r, delta_o), a slow random walk the wheels steer
//! through (delta = delta_measured + delta_o). The gyro and the accelerometer make it
//! observable: in steady driving a_y fixes the axles' force sum and r their moment balance, so
//! the slip angles, and with them delta, follow. It learns only at speed and in the tires'
//! linear range (elsewhere the filter considers its uncertainty without changing it), stays
//! within +-max_steering_offset_rad, and persists across reset() like the car's rack does.

#include <optional>
#include <string>

#include "smoothsteer/status.hpp"
#include "smoothsteer/validation.hpp"
#include "smoothsteer/vehicle/sensor_fault_gate.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer {

//! The observer's tire model: the linear single-track model, or each axle's Magic Formula.
enum class ObserverTireModel { linear, magic_formula };

struct SideSlipObserverParameters {
  double mass_kg = 1093.3;                            //!< m [kg]
  double yaw_inertia_kgm2 = 1791.6;                   //!< Iz [kg m^2]
  double cg_to_front_axle_m = 1.156;                  //!< lf [m]
  double cg_to_rear_axle_m = 1.422;                   //!< lr [m]
  double front_cornering_stiffness_npr = 1.3e5;       //!< Cf of the front axle [N/rad]
  double rear_cornering_stiffness_npr = 1.05e5;       //!< Cr of the rear axle [N/rad]
  double yaw_rate_noise_std_radps = 0.002;            //!< std of the gyro's noise [rad/s]
  double lateral_acceleration_noise_std_mps2 = 0.05;  //!< std of the accelerometer's [m/s^2]
  //! Process noise: std of the unmodelled lateral force per unit mass [m/s^2] and of the
  //! unmodelled yaw acceleration [rad/s^2] (tire nonlinearity, parameter error).
  double lateral_process_std_mps2 = 0.5;
  //! The yaw's is what separates a steering offset from a lateral velocity: at 0.5 the moment
  //! balance counted so little that the offset took 3-5 s to learn (lane change at 10 m/s with
  //! a 0.01 rad sensor offset: 0.020 m against 0.008 m at 0.1; nominal figures unchanged).
  double yaw_process_std_radps2 = 0.1;
  ObserverTireModel tire_model = ObserverTireModel::linear;
  //! magic_formula only: the shape of each axle's curve (C, mu, E). Its B is not used: the curve
  //! is scaled so that its slope at zero is the cornering stiffness above, B = C_alpha / (C D),
  //! with D = mu Fz at the static axle load of mass_kg.
  TireParameters front_tire;
  TireParameters rear_tire;
  double gravity_mps2 = 9.81;  //!< g [m/s^2], for the static axle loads
  //! Below this speed the model is singular (1/vx); the estimate is kinematic: beta_r = 0 [m/s].
  double min_speed_mps = 2.0;
  //! The steering offset delta_o: its bound [rad] (0 switches the state off: delta_o = 0), its
  //! random walk's std [rad/sqrt(s)], and where it learns: at least this speed [m/s], at most
  //! this measured lateral acceleration [m/s^2] (the tires' linear range, where a wrong
  //! stiffness in the vehicle file costs least).
  double max_steering_offset_rad = 0.02;
  double steering_offset_process_std_radps = 2e-4;
  //! The largest values the two above accept (validation, scenario keys).
  static constexpr double max_steering_offset_bound_rad = 0.2;
  static constexpr double max_steering_offset_process_std_radps = 0.1;
  double offset_learning_min_speed_mps = 3.0;
  double offset_learning_max_lateral_acceleration_mps2 = 2.0;
  //! What rejects a bad gyro or accelerometer sample and when the estimate is not trusted
  //! (sensor_fault_gate.hpp).
  SideSlipFaultGate fault_gate;

  //! The vehicle file's parameters: Cf, Cr = B C D at the static axle loads, and its tires. The
  //! scales model a wrong belief (robustness study): both stiffnesses times
  //! `cornering_stiffness_scale`, mass and yaw inertia (and with them the believed axle loads,
  //! hence the peak forces of magic_formula) times `mass_scale`.
  static SideSlipObserverParameters from_vehicle(
      const VehicleParameters& vehicle, double cornering_stiffness_scale = 1.0,
      double mass_scale = 1.0, ObserverTireModel tire_model = ObserverTireModel::linear);

  //! The first rule broken (validation.hpp); is_valid(), validation_error(), validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  std::string validation_error() const;
  void validate() const;  //!< throws std::invalid_argument
};

//! One period's measurements. A non-finite yaw rate or lateral acceleration is a dropped
//! sample: the filter only predicts that channel (and counts it), the period does not fail.
struct SideSlipMeasurement {
  double speed_mps = 0.0;                  //!< vx [m/s]; |vx| < min_speed_mps: kinematic
  double yaw_rate_radps = 0.0;             //!< r [rad/s]; NaN: dropped
  double lateral_acceleration_mps2 = 0.0;  //!< a_y at the CG [m/s^2]; NaN: dropped
  double steering_angle_rad = 0.0;         //!< road-wheel angle delta (measured, not commanded)
};

class SideSlipObserver {
 public:
  //! Validates the parameters (throws std::invalid_argument naming the field).
  explicit SideSlipObserver(const SideSlipObserverParameters& parameters);

  //! Back to straight driving without slip and the initial uncertainty; clears health(). The
  //! steering offset and its uncertainty stay (forget_steering_offset() clears them).
  void reset() noexcept;
  //! The steering offset back to 0 at its initial uncertainty (a new car, a realigned rack).
  void forget_steering_offset() noexcept;
  //! One prediction over `period_s` (with the held steering angle of the measurement) and the
  //! corrections with r and a_y that pass the gates (sensor_fault_gate.hpp); restarts from the
  //! kinematic model when the estimate stays saturated or uncorrected. invalid_input for a
  //! non-finite speed or steering angle, or period_s outside (0, 1] s; nothing changes then.
  Status update(const SideSlipMeasurement& measurement, double period_s) noexcept;

  double lateral_velocity_mps() const noexcept { return lateral_velocity_; }  //!< vy [m/s]
  double yaw_rate_radps() const noexcept { return yaw_rate_; }                //!< r [rad/s]
  //! beta = atan(vy / vx) at the CG [rad].
  double side_slip_rad() const noexcept { return side_slip_; }
  //! beta_r = atan((vy - lr r) / vx): the rear axle's course minus the heading [rad], the input
  //! ControllerInput::rear_axle_side_slip_rad.
  double rear_axle_side_slip_rad() const noexcept { return rear_side_slip_; }
  //! delta_o: the road wheels' angle minus the measured one [rad], within the bound.
  double steering_offset_rad() const noexcept { return steering_offset_; }
  //! The standard deviation the filter gives delta_o [rad] (0.5 max_steering_offset_rad before
  //! it has learned anything).
  double steering_offset_std_rad() const noexcept;
  const SideSlipObserverParameters& parameters() const noexcept { return parameters_; }
  //! What the gates rejected, and whether the estimate is trusted.
  const SideSlipObserverHealth& health() const noexcept { return health_; }

 private:
  //! Straight driving and the initial covariance; health() and the gates' memory stay.
  void reset_estimate() noexcept;
  //! The kinematic model's state at speed v: beta_r = 0 (vy = lr r), the initial covariance.
  void restart_from_model(double v, double yaw_rate) noexcept;
  //! Saturation and outage bookkeeping after a step; restarts the filter when they last.
  void judge_estimate(bool corrected, double v, double restart_yaw_rate, double period_s,
                      std::uint32_t& faults) noexcept;

  SideSlipObserverParameters parameters_;
  SensorPlausibility plausibility_;
  SideSlipObserverHealth health_;
  double lateral_velocity_ = 0.0, yaw_rate_ = 0.0, steering_offset_ = 0.0;
  double covariance_[3][3]{};  //!< of (vy, r, delta_o)
  double side_slip_ = 0.0, rear_side_slip_ = 0.0;
  double speed_ = 0.0;
  double previous_steering_ = 0.0;  //!< delta of the last measurement, held over the period
  bool has_previous_ = false;
};

}  // namespace smoothsteer
