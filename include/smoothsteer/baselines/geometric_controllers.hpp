#pragma once
//! \file geometric_controllers.hpp
//! The two classic geometric path trackers, as comparison baselines.
//! Neither respects C1/C2 by construction: wrap them in SaturatedController.
//!
//! Stanley (Thrun et al., "Stanley: the robot that won the DARPA Grand Challenge", J. Field
//! Robotics 23(9), 2006, eq. 9): with e_f the front axle's signed lateral error (left positive)
//! and psi_f the heading relative to the path at the front axle's closest point,
//!   delta = -psi_f - atan(k e_f / (v_soft + v)).
//!
//! Pure pursuit (Coulter, "Implementation of the pure pursuit path tracking algorithm",
//! CMU-RI-TR-92-01, 1992): the rear axle chases the path point a look-ahead distance
//! L_d = clamp(L_min + k_v v, L_min, L_max) ahead (along the path from its closest point);
//! with alpha the bearing of that point in the vehicle frame and l its distance,
//!   delta = atan(2 lambda sin(alpha) / l).
//! Both are for forward driving; at v <= 0 they hold their last command.

#include <memory>

#include "smoothsteer/baselines/path_tracking_baseline.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct StanleyParameters {
  double wheelbase_m = 2.7;    //!< lambda_veh: where the front axle is [m]
  double gain_per_s = 2.0;     //!< k [1/s]
  double softening_mps = 1.0;  //!< v_soft: keeps the gain finite at low speed [m/s]
  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

class StanleyController final : public PathTrackingBaseline<StanleyParameters> {
 public:
  StanleyController(const StanleyParameters& parameters, std::shared_ptr<const Path> path);
  const char* name() const noexcept override { return "stanley"; }

 protected:
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override;
};

struct PurePursuitParameters {
  double wheelbase_m = 2.7;       //!< lambda_veh [m]
  double min_lookahead_m = 3.0;   //!< L_min [m]
  double lookahead_time_s = 0.6;  //!< k_v: look-ahead grows by k_v |v| [s]
  double max_lookahead_m = 30.0;  //!< L_max [m]
  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

class PurePursuitController final : public PathTrackingBaseline<PurePursuitParameters> {
 public:
  PurePursuitController(const PurePursuitParameters& parameters, std::shared_ptr<const Path> path);
  const char* name() const noexcept override { return "pure_pursuit"; }
  //! L_d at speed v [m].
  double lookahead_m(double speed_mps) const noexcept;

 protected:
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override;
};

}  // namespace smoothsteer
