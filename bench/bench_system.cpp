// Cost of the car's SteeringSystem::update() (system/steering_system.hpp) against the bare
// controller's update() in the same run: the certified schedule (ScheduledController, n = 2,
// exact rear-axle target, planned jumps, governor, Smith predictor, single-track inversion) with
// the side-slip observer (Magic Formula or linear tires), and the same controller without it.
// Inputs come from a recorded closed loop of the kinetic single-track model on a double lane
// change at 15 m/s, so that only update() is timed. Figures: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/system/steering_system.hpp"
#include "smoothsteer/tuning/vehicle_steering_system.hpp"

namespace {

using namespace smoothsteer;

//! A double lane change of 3.5 m over 25 m, 40 m straight, back over 25 m (cosine ramps).
std::shared_ptr<const Path> lane_change_path() {
  static const auto path = [] {
    std::vector<Vec2> points;
    const auto ramp = [](double u) { return 0.5 * (1.0 - std::cos(std::numbers::pi * u)); };
    for (int k = -40; k <= 160; ++k) {
      const double x = k;
      double y = 0.0;
      if (x > 15.0 && x < 40.0) y = 3.5 * ramp((x - 15.0) / 25.0);
      if (x >= 40.0 && x <= 80.0) y = 3.5;
      if (x > 80.0 && x < 105.0) y = 3.5 * (1.0 - ramp((x - 80.0) / 25.0));
      points.push_back({x, y});
    }
    return std::make_shared<const Path>(Path::from_waypoints(points));
  }();
  return path;
}

VehicleDescription car() {
  VehicleDescription description;
  description.vehicle.max_steering_acceleration_radps2 = 8.0;
  return description;
}

SteeringSystemOptions options(ObserverTireModel tires) {
  SteeringSystemOptions o;
  o.observer_tire_model = tires;
  return o;
}

//! What the car's sensors reported in a closed loop of the system (no sensor noise).
const std::vector<SteeringSystemInput>& recorded_inputs() {
  static const std::vector<SteeringSystemInput> inputs = [] {
    SteeringSystem system =
        make_steering_system(car(), lane_change_path(), options(ObserverTireModel::magic_formula));
    const DynamicSingleTrack model(car().vehicle);
    SimulationParameters parameters;
    parameters.duration_s = 12.0;
    SpeedProfile speed;
    speed.initial_speed_mps = speed.final_speed_mps = 15.0;
    const SimulationResult result = simulate(*lane_change_path(), model, car().actuator, speed,
                                             parameters, {{-30.0, 0.0}, 0.0}, system);
    std::vector<SteeringSystemInput> recorded;
    for (const TraceSample& sample : result.trace) {
      VehicleState state;
      state.vx_mps = sample.speed_mps;
      state.vy_mps = sample.lateral_velocity_mps;
      state.yaw_rate_radps = sample.yaw_rate_radps;
      const VehicleState rates = model.derivative(state, sample.steering_actual_rad, 0.0);
      SteeringSystemInput input;
      input.rear_axle_position = sample.rear_axle.position;
      input.heading_rad = sample.rear_axle.heading_rad;
      input.speed_mps = sample.speed_mps;
      input.yaw_rate_radps = sample.yaw_rate_radps;
      input.lateral_acceleration_mps2 = rates.vy_mps + state.vx_mps * state.yaw_rate_radps;
      input.steering_angle_rad = sample.steering_actual_rad;
      input.rear_axle_side_slip_rad = sample.rear_side_slip_input_rad;
      recorded.push_back(input);
    }
    return recorded;
  }();
  return inputs;
}

//! The composed update(): observer, slip input, schedule, controller.
void run_system(benchmark::State& state, SteeringSystem system) {
  const auto& inputs = recorded_inputs();
  SteeringSystemOutput output;
  std::size_t k = 0;
  for (auto _ : state) {
    if (k == inputs.size()) {
      k = 0;
      system.reset(0.0);
    }
    benchmark::DoNotOptimize(system.update(inputs[k++], output));
    benchmark::DoNotOptimize(output);
  }
}

void BM_SystemUpdateMagicFormulaObserver(benchmark::State& state) {
  run_system(state, make_steering_system(car(), lane_change_path(),
                                         options(ObserverTireModel::magic_formula)));
}
BENCHMARK(BM_SystemUpdateMagicFormulaObserver);

void BM_SystemUpdateLinearObserver(benchmark::State& state) {
  run_system(state,
             make_steering_system(car(), lane_change_path(), options(ObserverTireModel::linear)));
}
BENCHMARK(BM_SystemUpdateLinearObserver);

//! The system with a slip sensor: the composition without the observer.
void BM_SystemUpdateSlipSensor(benchmark::State& state) {
  SteeringSystemOptions o = options(ObserverTireModel::linear);
  o.slip_input = SlipInput::sensor;
  run_system(state, make_steering_system(car(), lane_change_path(), o));
}
BENCHMARK(BM_SystemUpdateSlipSensor);

//! The bare controller's update(): the same ScheduledController, the recorded beta_r as input.
void BM_BareControllerUpdate(benchmark::State& state) {
  SteeringSystemOptions o = options(ObserverTireModel::linear);
  o.slip_input = SlipInput::kinematic;
  SteeringSystem system = make_steering_system(car(), lane_change_path(), o);
  // The system only owns it here; the controller is driven directly.
  SteeringController& controller = const_cast<SteeringController&>(system.controller());
  const auto& inputs = recorded_inputs();
  ControllerOutput output;
  std::size_t k = 0;
  for (auto _ : state) {
    if (k == inputs.size()) {
      k = 0;
      controller.reset(0.0);
    }
    const SteeringSystemInput& in = inputs[k++];
    ControllerInput input{in.rear_axle_position, in.heading_rad, in.speed_mps, in.acceleration_mps2,
                          in.period_s};
    input.rear_axle_side_slip_rad = *in.rear_axle_side_slip_rad;
    benchmark::DoNotOptimize(controller.update(input, output));
    benchmark::DoNotOptimize(output);
  }
}
BENCHMARK(BM_BareControllerUpdate);

}  // namespace

namespace {

//! The library's default lead-wheel controller (fixed parameters, lambda_l = 1 m: three chain
//! sub-steps per period at 15 m/s instead of the schedule's nine), with and without the
//! Magic-Formula observer: what the composition costs over a cheaper controller.
SteeringSystem default_controller_system(SlipInput slip) {
  SteeringSystemParameters parameters =
      SteeringSystemParameters::from_vehicle(car().vehicle, ObserverTireModel::magic_formula);
  parameters.slip_input = slip;
  ControllerParameters controller;
  controller.chain.vehicle_wheelbase_m = car().vehicle.wheelbase_m();
  return SteeringSystem(std::make_unique<LeadWheelController>(controller, lane_change_path()),
                        parameters);
}

void BM_DefaultControllerSystemUpdateMagicFormulaObserver(benchmark::State& state) {
  run_system(state, default_controller_system(SlipInput::observer));
}
BENCHMARK(BM_DefaultControllerSystemUpdateMagicFormulaObserver);

void BM_DefaultControllerSystemUpdateSlipSensor(benchmark::State& state) {
  run_system(state, default_controller_system(SlipInput::sensor));
}
BENCHMARK(BM_DefaultControllerSystemUpdateSlipSensor);

//! The steering offset compensation alone (steering_offset_compensation.hpp): the actuator's
//! predicted angle (two exact lag steps), the bias, the deadband and the two limiters, on a
//! slow sine command with a rack offset learned.
void BM_SteeringOffsetCompensationUpdate(benchmark::State& state) {
  SteeringOffsetCompensation compensation(SteeringOffsetCompensationParameters{
      .actuator = car().actuator,
      .limits = {.angle_rad = 0.5, .rate_radps = 0.4, .acceleration_radps2 = 8.0},
      .max_offset_rad = 0.02});
  compensation.reset(0.0);
  double t = 0.0, rate = 0.0, acceleration = 0.0;
  for (auto _ : state) {
    const double command = 0.05 * std::sin(t);
    benchmark::DoNotOptimize(
        compensation.update(command, command, 0.01, 1e-3, 0.02, rate, acceleration));
    t += 0.02;
  }
}
BENCHMARK(BM_SteeringOffsetCompensationUpdate);

//! The course error estimator alone (course_error_estimator.hpp): one pose step compared with
//! the course and the Kalman filter's prediction and correction, on a car turning at 0.1 rad/s.
void BM_CourseErrorEstimatorUpdate(benchmark::State& state) {
  CourseErrorEstimator estimator;
  const CourseErrorParameters parameters;
  double t = 0.0, heading = 0.0;
  Vec2 position{};
  for (auto _ : state) {
    const double slip = -0.004 * std::sin(0.5 * t);
    position = position + 0.2 * Vec2{std::cos(heading + slip), std::sin(heading + slip)};
    heading += 0.002;
    benchmark::DoNotOptimize(estimator.update(parameters, {.position = position,
                                                           .heading_rad = heading,
                                                           .rear_axle_side_slip_rad = slip,
                                                           .speed_mps = 10.0,
                                                           .lateral_acceleration_mps2 = 1.0}));
    t += 0.02;
  }
}
BENCHMARK(BM_CourseErrorEstimatorUpdate);

}  // namespace
