// The simulator drives the car's SteeringSystem: its result equals driving the same object by
// hand with the sensor values the simulator reports, bit for bit; the scenario route (a
// controller overload) and an explicitly built system give the same trace; and the system
// built from the vehicle file alone tracks the shipped lane change as its own controller block.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "smoothsteer/runner/scenario.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/system/steering_system.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

runner::Scenario lane_change() {
  return runner::load_scenario(testing::source_file("scenarios/lane_change_15.yaml"));
}

//! The options that reproduce lane_change_15's block from the car (its schedule was tuned with
//! headroom 1.2 over 0.5..20 m/s; its Smith delay is 48 ms).
SteeringSystemOptions lane_change_options() {
  SteeringSystemOptions options;
  options.max_speed_mps = 19.5;  // grid 0.5 .. 20 m/s
  options.feedforward_headroom = 1.2;
  // The delay and the catch-up follow the speed, as the file's derived_compensation.
  return options;
}

TEST(SteeringSystemSimulation, EqualsDrivingTheObjectByHand) {
  const runner::Scenario scenario = lane_change();
  const VehicleDescription car{scenario.vehicle, scenario.actuator};
  SimulationParameters parameters = scenario.simulation;
  // The trace holds the plant's true values: without sensor noise they are what the sensors said.
  parameters.side_slip.yaw_rate_noise_std_radps = 0.0;
  parameters.side_slip.lateral_acceleration_noise_std_mps2 = 0.0;
  parameters.position_noise_std_m = parameters.heading_noise_std_rad = 0.0;
  const std::unique_ptr<VehicleModel> model = runner::make_vehicle_model(scenario);
  for (const SlipInput slip : {SlipInput::observer, SlipInput::sensor}) {
    SteeringSystemOptions options = lane_change_options();
    options.slip_input = slip;
    SteeringSystem simulated = make_steering_system(car, scenario.path, options);
    const SimulationResult result = simulate(*scenario.path, *model, scenario.actuator,
                                             scenario.speed, parameters, scenario.start, simulated);
    ASSERT_EQ(result.status, Status::ok);
    ASSERT_GT(result.trace.size(), 500u);

    SteeringSystem by_hand = make_steering_system(car, scenario.path, options);
    by_hand.reset(0.0);
    SteeringSystemOutput output;
    for (std::size_t k = 0; k < result.trace.size(); ++k) {
      const TraceSample& sample = result.trace[k];
      VehicleState state;  // the body-frame velocities are all the lateral dynamics read
      state.heading_rad = sample.rear_axle.heading_rad;
      state.vx_mps = sample.speed_mps;
      state.vy_mps = sample.lateral_velocity_mps;
      state.yaw_rate_radps = sample.yaw_rate_radps;
      const VehicleState rates =
          model->derivative(state, sample.steering_actual_rad, sample.acceleration_mps2);
      SteeringSystemInput input;
      input.rear_axle_position = sample.rear_axle.position;
      input.heading_rad = sample.rear_axle.heading_rad;
      input.speed_mps = sample.speed_mps;
      input.acceleration_mps2 = sample.acceleration_mps2;
      input.yaw_rate_radps = sample.yaw_rate_radps;
      input.lateral_acceleration_mps2 = rates.vy_mps + state.vx_mps * state.yaw_rate_radps;
      input.steering_angle_rad = sample.steering_actual_rad;
      input.rear_axle_side_slip_rad = sample.rear_side_slip_rad;
      input.period_s = parameters.control_period_s;
      ASSERT_EQ(by_hand.update(input, output), Status::ok) << "step " << k;
      ASSERT_EQ(output.steering_angle_rad, sample.steering_command_rad) << "step " << k;
      ASSERT_EQ(output.side_slip.rear_axle_side_slip_rad, sample.rear_side_slip_input_rad)
          << "step " << k;
      ASSERT_EQ(output.tracking.lead_curvature, sample.lead_curvature) << "step " << k;
    }
  }
}

TEST(SteeringSystemSimulation, ScenarioRouteIsTheSystemRoute) {
  const runner::Scenario scenario = lane_change();
  const runner::RunResult run = runner::run_scenario(scenario);
  const std::unique_ptr<SteeringController> controller = runner::make_controller(scenario);
  SteeringSystem system(*controller,
                        steering_system_parameters(scenario.simulation.side_slip, scenario.vehicle,
                                                   scenario.actuator));
  const std::unique_ptr<VehicleModel> model = runner::make_vehicle_model(scenario);
  const SimulationResult result =
      simulate(*scenario.path, *model, scenario.actuator, scenario.speed, scenario.simulation,
               scenario.start, system);
  ASSERT_EQ(result.trace.size(), run.simulation.trace.size());
  for (std::size_t k = 0; k < result.trace.size(); ++k) {
    ASSERT_EQ(trace_values(result.trace[k]), trace_values(run.simulation.trace[k])) << "step " << k;
  }
}

TEST(SteeringSystemSimulation, FromTheVehicleFileTracksTheLaneChange) {
  const runner::Scenario scenario = lane_change();
  const VehicleDescription car{scenario.vehicle, scenario.actuator};
  SteeringSystem system = make_steering_system(car, scenario.path, lane_change_options());
  const std::unique_ptr<VehicleModel> model = runner::make_vehicle_model(scenario);
  const SimulationResult result =
      simulate(*scenario.path, *model, scenario.actuator, scenario.speed, scenario.simulation,
               scenario.start, system);
  const Metrics metrics = compute_metrics(result.trace, scenario.metrics);
  const Metrics own = runner::run_scenario(scenario).metrics;
  // The file's own block: 0.034 m. The system from the car alone (same schedule route, computed
  // in process instead of read from the committed CSV) gives the same to 1 mm.
  EXPECT_NEAR(metrics.max_abs_rear_error_m, own.max_abs_rear_error_m, 1e-3);
  EXPECT_EQ(metrics.held_rate_violations, 0);
  EXPECT_EQ(metrics.held_acceleration_violations, 0);
}

}  // namespace
}  // namespace smoothsteer
