#pragma once
//! \file certified_route.hpp
//! The certified lead-wheel controller of a scenario, tuned in process by the route of
//! `smoothsteer tune` (docs/tuning.md "Feedforward route", docs/feedforward.md): the car's
//! limits (the scenario's vehicle), the path's curvature and curvature rate (path_demand), a
//! speed grid up to the scenario's top speed, compute_feedforward_schedule, and a
//! ScheduledController. The scenario's own controller section supplies every other field
//! (cornering target, actuator delay, ...): it must be a `scheduled_lead_wheel`.
//!
//! Its knobs are the tuning options the route exposes, each of which keeps the certificate
//! (the schedule is recomputed for every value): `feedforward_rate_share`, `k_rob_floor`,
//! `switching_floor_share`, `feedforward_rate_margin` (TuningOptions) and `boundary_layer`
//! (ControllerParameters; the certificate does not depend on it, docs/global_convergence.md).

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "smoothsteer/tuning/gain_schedule.hpp"

namespace smoothsteer {

//! Name of the certified controller in the comparison tables.
inline constexpr const char* certified_controller_name = "certified";

//! The scenario's car as the tuner sees it: wheelbase, steering angle, rate and acceleration
//! limits of the vehicle, and the friction limit mu g of its tires (as load_vehicle_limits).
VehicleLimits vehicle_limits_of(const runner::Scenario& scenario);

//! Grid speeds 0.5, 1.0, ... up to one step beyond the first multiple of 0.5 m/s at or above
//! the scenario's top speed (as the committed circle_sections schedule: 12.5 m/s -> 13).
std::vector<double> certified_speed_grid(const runner::Scenario& scenario);

//! The route's options for the scenario: the controller section's parameters as the template,
//! the committed schedule's feedforward headroom (its largest kbar_ff over the path's curvature
//! bound, to 1e-6), the path's demand, the speed profile's |dv/dt|; then each knob (key, value)
//! applied. Throws std::invalid_argument naming a key that is not a knob, or a scenario whose
//! controller is not a scheduled_lead_wheel.
TuningOptions certified_route_options(const runner::Scenario& scenario,
                                      const std::vector<std::pair<std::string, double>>& knobs);

//! The certified controller for the scenario with these knobs. Throws as above, and
//! InfeasibleLimits when the car cannot be certified on the grid with them.
std::unique_ptr<SteeringController> make_certified_controller(
    const runner::Scenario& scenario,
    const std::vector<std::pair<std::string, double>>& knobs = {});

}  // namespace smoothsteer
