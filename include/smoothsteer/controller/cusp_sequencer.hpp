#pragma once
//! \file cusp_sequencer.hpp
//! Drives a PathPlan (pieces with gears, path_plan.hpp) with any SteeringController: hands the
//! active piece to the controller with set_path(), gives the signed speed of a profile that
//! brakes to a standstill at every cusp and at the end, and switches to the next piece once
//! the rear axle has stopped at the end of the active one. The controller handles the sign
//! change of v itself (LeadWheelController re-initialises its chain at the current steering
//! angle, which keeps the command continuous). Only the active piece is ever projected on.

#include <cstddef>

#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/path/path_plan.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct CuspSpeedOptions {
  double cruise_speed_mps = 1.5;    //!< |v| away from cusps [m/s]
  double deceleration_mps2 = 0.5;   //!< braking towards each cusp and the end [m/s^2]
  double stop_tolerance_m = 0.005;  //!< a piece is done this close to its end [m]
  //! Throws std::invalid_argument naming the field unless all are finite and > 0.
  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

class CuspSequencer {
 public:
  //! Validates the options and hands piece 0 to `controller` (which must outlive this). Throws
  //! std::invalid_argument if the controller does not support set_path().
  CuspSequencer(PathPlan plan, SteeringController& controller,
                const CuspSpeedOptions& options = {});

  //! Signed speed for the coming period, from the rear axle's position: +-min(cruise,
  //! sqrt(2 a d), d / dt) with d the distance left on the active piece (so the car stops at the
  //! end). At the end of a piece it returns 0 and switches the controller to the next piece.
  //! noexcept, allocation free.
  double speed_command(Vec2 rear_axle_position, double period_s) noexcept;

  std::size_t active_piece() const noexcept { return active_; }
  bool finished() const noexcept { return finished_; }
  const PathPlan& plan() const noexcept { return plan_; }

 private:
  PathPlan plan_;
  SteeringController& controller_;
  CuspSpeedOptions options_;
  ProjectionHint hint_;
  std::size_t active_ = 0;
  bool finished_ = false;
};

}  // namespace smoothsteer
