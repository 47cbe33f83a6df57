#pragma once
//! \file course_error_estimator.hpp
//! Stage of SteeringSystem::update(): what the side-slip estimate gets wrong about the course.
//! The law steers the rear axle's course psi + beta_r, with beta_r from the observer's model of
//! the car (side_slip_observer.hpp), and the feedforward inverts the same model's slip gradients
//! (docs/vehicle_dynamics.md, section 3). A loaded car, worn or stiffer tires or a wrong vehicle
//! file scale both: in the linear range beta_r = -m l_f a_y / (L C_r) and K = m l / (L C), so 30 %
//! more mass slips 1.3 times as much, 25 % stiffer tires 0.8 times. The gyro and the
//! accelerometer cannot tell: a car near neutral steer reads the same yaw rate and lateral
//! acceleration at either scale (only the difference l_r / C_f - l_f / C_r shows). The pose can:
//! between two poses the rear axle moves along its true course. The estimator compares each pose
//! step with the step along psi + beta_r (beta_r of the pose's own time, pose_age_s back) and
//! runs a Kalman filter on
//!   w = (a beta_r + c) ds + the pose's noise,
//! w the step's lateral part across the course, ds its length, a the slip's relative error and c
//! a course bias [rad] (a crosswind, a heading sensor's bias), each a slow random walk. It sums
//! the residual, so each pose's noise enters once instead of differentiated. The law then gets
//! (1 + a) beta_r + c, and the feedforward the slip gradients (1 + a) K
//! (ControllerInput::slip_gradient_scale).
//! update() is noexcept, allocation free, O(1) and deterministic.

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "smoothsteer/controller/disturbance_estimator.hpp"
#include "smoothsteer/math/vec2.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct CourseErrorParameters {
  //! The pose's noise: position [m] and heading [rad] (white, per pose). The defaults are a
  //! good localization's; a noisier pose only slows the learning when it is told.
  double position_noise_std_m = 0.01;
  double heading_noise_std_rad = 0.002;
  //! Prior standard deviation and random walk [1/sqrt(s)] of the slip's relative error a.
  double initial_slip_error_std = 0.15;
  double slip_error_process_std = 0.02;
  //! Prior standard deviation [rad] and random walk [rad/sqrt(s)] of the course bias c.
  double initial_course_bias_std_rad = 0.002;
  double course_bias_process_std_radps = 0.001;
  //! Bounds: |a| <= max_slip_error (the slip gradients stay within
  //! ControllerInput::min/max_slip_gradient_scale), |c| <= max_course_bias_rad.
  double max_slip_error = 0.5;
  double max_course_bias_rad = 0.02;
  //! Learns only driving forwards at this speed or more [m/s], and up to this lateral
  //! acceleration [m/s^2]: the disturbance estimate's bounds (disturbance_estimator.hpp), where
  //! the tires' slip model holds; beyond about 0.4 g a passenger car's tires leave their linear
  //! range, where the slip is not a scale of the model's and the load transfer of a real car
  //! (the double-track plant) adds its own.
  double min_speed_mps = DisturbanceEstimator::min_learning_speed_mps;
  double max_lateral_acceleration_mps2 =
      DisturbanceEstimator::max_learning_lateral_acceleration_mps2;
  //! A pose step whose summed residual is beyond this many standard deviations is a jump of the
  //! localization: the residual starts again there, a and c stay.
  double max_innovation_sigmas = 6.0;

  //! The first rule broken (validation.hpp); is_valid(), validation_error(), validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  std::string validation_error() const;
  void validate() const;  //!< throws std::invalid_argument
};

class CourseErrorEstimator {
 public:
  //! One period's signals.
  struct Input {
    Vec2 position;                         //!< the rear axle's position as delivered [m]
    double heading_rad = 0.0;              //!< psi as delivered [rad]
    bool new_pose = true;                  //!< whether the pose changed since the last period
    double rear_axle_side_slip_rad = 0.0;  //!< the observer's beta_r now [rad]
    double speed_mps = 0.0;                //!< signed v [m/s]
    //! v r [m/s^2], the yaw rate's (NaN: unknown, taken as within the bound)
    double lateral_acceleration_mps2 = 0.0;
    double period_s = 0.02;   //!< [s]
    double pose_age_s = 0.0;  //!< how old the pose is [s]
  };
  //! One control period. Returns the course correction the law adds to beta_r now [rad]:
  //! a beta_r + c.
  double update(const CourseErrorParameters& parameters, const Input& input) noexcept;
  //! A new engagement: the residual starts again; a and c stay (they are the car's and the
  //! road's, as the observer's steering offset is).
  void restart() noexcept {
    has_pose_ = false;
    span_length_ = span_slip_ = span_time_ = 0.0;
    count_ = 0;
    learnable_ = true;
  }
  //! Forgets a and c too (a new car, new tires, another load).
  void reset() noexcept { *this = CourseErrorEstimator{}; }
  //! a: how much more the car's tires slip than the model says (the law's beta_r and the
  //! feedforward's slip gradients are taken times 1 + a).
  double slip_error() const noexcept { return slip_error_; }
  //! c: the course bias [rad].
  double course_bias_rad() const noexcept { return course_bias_; }

  //! The slip history the pose's age reads back [periods]: 0.62 s at 50 Hz. An older pose
  //! takes the oldest slip.
  static constexpr std::size_t history = 32;

 private:
  void initialize(const CourseErrorParameters& parameters) noexcept;
  void restart_residual(double position_variance) noexcept;

  bool initialized_ = false;
  double slip_error_ = 0.0, course_bias_ = 0.0;
  double covariance_[3][3]{};  //!< of (residual, a, c)
  double residual_ = 0.0;      //!< summed lateral steps minus their prediction [m]
  bool has_pose_ = false;
  bool learnable_ = true;  //!< no period since the last pose beyond the lateral acceleration
  Vec2 last_position_{};
  double last_course_ = 0.0;             //!< psi + beta_r of the last pose [rad]
  double span_length_ = 0.0;             //!< |v| dt summed since the last pose [m]
  double span_slip_ = 0.0;               //!< beta_r |v| dt summed since the last pose [m rad]
  double span_time_ = 0.0;               //!< since the last pose [s]
  std::array<double, history> slips_{};  //!< beta_r of the last periods, newest at head_
  std::size_t head_ = 0, count_ = 0;
};

}  // namespace smoothsteer
