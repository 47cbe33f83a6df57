#pragma once
//! \file controller_registration.hpp
//! Registers the comparison controllers (baselines/comparison_controllers.hpp) as io controller
//! types, so that scenario files can name them: `controller: {type: mpc, horizon_steps: 30}`.

namespace smoothsteer {

//! Registers every name of comparison_controller_names() as an io controller type. Keys of
//! every type: nominal_speed_mps (10), max_steering_rate_radps (the vehicle's),
//! max_steering_acceleration_radps2 (the vehicle's), k_rob (0.3), hosm_heading_bound_rad (0.6),
//! lead_wheelbase_m (1.0); plus each baseline's gains (docs/scenarios.md). The angle limit is
//! the vehicle's max_steering_angle_rad. A bad value
//! gets "<file>: key 'controller.<key>' ..."; a rule between fields "<file>: key 'controller':
//! <Parameters>: <field> = <value> <rule>". Idempotent.
void register_comparison_controllers();

}  // namespace smoothsteer
