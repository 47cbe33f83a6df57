#include "smoothsteer/evaluation/controller_registration.hpp"

#include <memory>
#include <stdexcept>
#include <string>

#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/runner/controller_registry.hpp"

namespace smoothsteer {

namespace {

//! The gains of one baseline as keys of its controller section; the keys are the parameter
//! fields, so a validate() message ("LqrParameters: weight_lateral = ...") names the key.
void read_baseline_gains(const std::string& name, io::ConfigSection& section,
                         ComparisonSetup& setup) {
  const io::Range positive = io::Range::positive(), non_negative = io::Range::non_negative();
  if (name == "stanley") {
    StanleyParameters& p = setup.stanley;
    p.gain_per_s = section.number("gain_per_s", p.gain_per_s, positive);
    p.softening_mps = section.number("softening_mps", p.softening_mps, positive);
  } else if (name == "pure_pursuit") {
    PurePursuitParameters& p = setup.pure_pursuit;
    p.min_lookahead_m = section.number("min_lookahead_m", p.min_lookahead_m, positive);
    p.lookahead_time_s = section.number("lookahead_time_s", p.lookahead_time_s, non_negative);
    p.max_lookahead_m = section.number("max_lookahead_m", p.max_lookahead_m, positive);
  } else if (name == "lqr") {
    LqrParameters& p = setup.lqr;
    p.weight_lateral = section.number("weight_lateral", p.weight_lateral, positive);
    p.weight_heading = section.number("weight_heading", p.weight_heading, non_negative);
    p.weight_steering = section.number("weight_steering", p.weight_steering, positive);
    p.curvature_feedforward = section.boolean("curvature_feedforward", p.curvature_feedforward);
  } else if (name == "newton_raphson") {
    NewtonRaphsonParameters& p = setup.newton_raphson;
    p.horizon_s = section.number("horizon_s", p.horizon_s, positive);
    p.gain_per_s = section.number("gain_per_s", p.gain_per_s, positive);
  } else if (name == "mpc" || name == "mpc_constrained") {
    MpcParameters& p = setup.mpc;
    p.steering_time_constant_s =
        section.number("steering_time_constant_s", p.steering_time_constant_s, positive);
    p.horizon_steps = section.integer("horizon_steps", p.horizon_steps, 2, 200);
    p.prediction_step_s = section.number("prediction_step_s", p.prediction_step_s, positive);
    const auto weight = [&](const char* key, double& value) {
      value = section.number(key, value, non_negative);
    };
    weight("weight_lateral_error", p.weight_lateral_error);
    weight("weight_heading_error", p.weight_heading_error);
    weight("weight_heading_error_squared_speed", p.weight_heading_error_squared_speed);
    p.weight_steering_input =
        section.number("weight_steering_input", p.weight_steering_input, positive);
    weight("weight_steering_input_squared_speed", p.weight_steering_input_squared_speed);
    weight("weight_steering_rate", p.weight_steering_rate);
    weight("weight_steering_acceleration", p.weight_steering_acceleration);
    weight("weight_terminal_lateral_error", p.weight_terminal_lateral_error);
    weight("weight_terminal_heading_error", p.weight_terminal_heading_error);
    weight("zero_feedforward_angle_rad", p.zero_feedforward_angle_rad);
  }
}

}  // namespace

void register_comparison_controllers() {
  for (const std::string& name : comparison_controller_names()) {
    runner::register_controller_type(
        name,
        [name](io::ConfigSection& section,
               const runner::ControllerContext& context) -> std::unique_ptr<SteeringController> {
          const VehicleParameters& vehicle = context.vehicle;
          const std::shared_ptr<const Path>& path = context.path;
          // Limits C1, C2 and the steering acceleration: the vehicle's, unless the section sets
          // the rate or acceleration limit (e.g. to the scenario actuator's max_rate_radps).
          SteeringLimits limits{
              vehicle.max_steering_angle_rad,
              section.number("max_steering_rate_radps", vehicle.max_steering_rate_radps,
                             io::Range::positive()),
              vehicle.max_steering_acceleration_radps2};
          if (section.has("max_steering_acceleration_radps2")) {
            limits.acceleration_radps2 =
                section.required_number("max_steering_acceleration_radps2", io::Range::positive());
          }
          ComparisonSetup setup;
          setup.path = path;
          setup.wheelbase_m = vehicle.wheelbase_m();
          setup.nominal_speed_mps =
              section.number("nominal_speed_mps", 10.0, io::Range::positive());
          setup.limits = limits;
          setup.k_rob = section.number("k_rob", setup.k_rob, {0.0, 1.0, false, true});
          setup.hosm_heading_bound_rad = section.number(
              "hosm_heading_bound_rad", setup.hosm_heading_bound_rad, io::Range::positive());
          setup.lead_wheelbase_m =
              section.number("lead_wheelbase_m", setup.lead_wheelbase_m, io::Range::positive());
          read_baseline_gains(name, section, setup);
          try {
            return make_comparison_controller(name, setup);
          } catch (const std::invalid_argument& error) {
            throw io::ConfigError(section.file() + ": key '" + section.full_key("") +
                                  "': " + error.what());
          }
        });
  }
}

}  // namespace smoothsteer
