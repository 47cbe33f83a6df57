#pragma once
//! \file actuator_inversion.hpp
//! Last stage of LeadWheelController::compute_command(): the steering-actuator inversion
//! (ControllerParameters::actuator_inversion, docs/vehicle_dynamics.md). The command leads the
//! chain's delta_veh by a1 delta' + a2 delta'' (a_k = C(m, k) T^k), which the actuator's
//! (1 + T s)^m then reproduces; only the chain's derivatives up to n - 1 are used, so that the
//! command keeps a certified rate bound.

#include "smoothsteer/controller/controller_parameters.hpp"

namespace smoothsteer {

struct SteeringCommand {
  double steering_rad = 0.0;
  double rate_radps = 0.0;
  double acceleration_radps2 = 0.0;
  int derivatives = 0;  //!< how many of the derivatives exist
};

//! `command` with the actuator's lags inverted for a chain of order n; unchanged while the
//! inversion is off or n < 2.
inline void invert_actuator(const ActuatorInversion& actuator, int n,
                            SteeringCommand& command) noexcept {
  if (!actuator.enabled || n < 2) return;
  const double lag = actuator.time_constant_s;
  const double count = actuator.lag_count;
  const double a1 = count * lag;                              // a1 = m T
  const double a2 = 0.5 * count * (count - 1.0) * lag * lag;  // a2 = C(m, 2) T^2
  if (n == 2) {  // derivatives up to n - 1 = 1: the command's rate delta' + a1 delta''
    command.steering_rad += a1 * command.rate_radps;
    command.rate_radps += a1 * command.acceleration_radps2;
    command.acceleration_radps2 = 0.0;
    command.derivatives = 1;
  } else {
    command.steering_rad += a1 * command.rate_radps + a2 * command.acceleration_radps2;
    command.rate_radps = command.acceleration_radps2 = 0.0;
    command.derivatives = 0;
  }
}

}  // namespace smoothsteer
