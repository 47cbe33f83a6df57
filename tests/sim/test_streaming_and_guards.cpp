// A non-finite sample never leaves the simulation with status ok, counts the input controls
// are capped (so a hostile file cannot exhaust memory), streamed runs equal stored ones, and the
// metrics of the held command follow their definition (docs/metrics.md).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/sim/metrics.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "support/held_command.hpp"
#include "support/property.hpp"
#include "support/sim_test_support.hpp"

namespace smoothsteer {
namespace {

//! Reports ok but a NaN diagnostic from step `bad_step` on (as controllers did with |x| >= 1e155).
class NanAfter final : public SteeringController {
 public:
  explicit NanAfter(int bad_step) : bad_step_(bad_step) {}
  Status compute_command(const ControllerInput&, ControllerOutput& output) noexcept override {
    output = ControllerOutput{};
    output.steering_angle_rad = 0.01;
    if (step_++ >= bad_step_) {
      output.diagnostics.lead_lateral_error_m = -std::numeric_limits<double>::infinity();
    }
    return Status::ok;
  }
  Status reset(double) noexcept override {
    step_ = 0;
    return Status::ok;
  }
  const char* name() const noexcept override { return "nan_after"; }

 private:
  int bad_step_;
  int step_ = 0;
};

TEST(SimulationGuards, NonFiniteSampleStopsTheRunAndIsNeverEmitted) {
  const Path path = Path::straight_line({0, 0}, 0.0, 500.0);
  const VehicleParameters car;
  KinematicVehicleModel model(car);
  NanAfter controller(10);
  SimulationParameters sim;
  sim.duration_s = 5.0;
  const SimulationResult result =
      simulate(path, model, ActuatorParameters{}, SpeedProfile{5.0, 5.0, 0.0, 0.0}, sim,
               {{0, 0.5}, 0.0}, controller);
  // SteeringController::update() turns the non-finite output into numerical_error, so the run
  // stops as a controller error before the sample is emitted.
  EXPECT_EQ(result.stop_reason, "controller_error");
  EXPECT_EQ(result.trace.size(), 10u);
  const Metrics m = compute_metrics(result.trace, MetricsParameters{});
  EXPECT_EQ(m.non_finite_values, 0);
}

TEST(SimulationGuards, StepCountsAreCapped) {
  SimulationParameters sim;
  sim.substep_s = 1e-6;
  sim.control_period_s = 1e-5;
  sim.duration_s = 3600.0;
  const std::string error = sim.validation_error();
  EXPECT_NE(error.find("duration_s"), std::string::npos) << error;
  EXPECT_NE(error.find("control steps"), std::string::npos) << error;
  sim.control_period_s = 0.0200001;
  sim.substep_s = 0.001;
  sim.duration_s = 10.0;
  EXPECT_NE(sim.validation_error().find("0.0200001"), std::string::npos) << sim.validation_error();
}

TEST(StreamingSimulation, ObserverSeesTheSameSamplesAsTheStoredTrace) {
  const Path path = Path::circle({0, 0}, 30.0);
  const VehicleParameters car;
  DynamicSingleTrack model(car);
  testing::ConstantSteering controller(0.05);
  SimulationParameters sim;
  sim.duration_s = 4.0;
  const SpeedProfile speed{5.0, 8.0, 1.0, 0.5};
  const SimulationResult stored =
      simulate(path, model, ActuatorParameters{}, speed, sim, {{30, 0.5}, 1.6}, controller);
  std::vector<TraceSample> streamed;
  MetricsAccumulator accumulator{MetricsParameters{}};
  const SimulationResult result = simulate(path, model, ActuatorParameters{}, speed, sim,
                                           {{30, 0.5}, 1.6}, controller, [&](const TraceSample& s) {
                                             streamed.push_back(s);
                                             accumulator.add(s);
                                           });
  EXPECT_TRUE(result.trace.empty());
  ASSERT_EQ(streamed.size(), stored.trace.size());
  for (std::size_t i = 0; i < streamed.size(); ++i) {
    EXPECT_EQ(trace_values(streamed[i]), trace_values(stored.trace[i])) << "row " << i;
  }
  const auto batch = metric_values(compute_metrics(stored.trace, MetricsParameters{}));
  const auto online = metric_values(accumulator.result());
  EXPECT_EQ(batch, online);
}

TEST(Metrics, HeldCommandRateAndAccelerationFollowTheirDefinition) {
  // delta_cmd = 0, 0.01, 0.03, 0.03 at T = 0.02 s: held rates 0.5, 1.0, 0.0 rad/s,
  // accelerations 25, -50 rad/s^2.
  std::vector<TraceSample> trace(4);
  const double commands[] = {0.0, 0.01, 0.03, 0.03};
  for (std::size_t i = 0; i < trace.size(); ++i) {
    trace[i].time_s = 0.02 * static_cast<double>(i);
    trace[i].steering_command_rad = commands[i];
    trace[i].steering_actual_rate_radps = i == 2 ? 0.6 : 0.0;
    trace[i].steering_actual_acceleration_radps2 = i == 1 ? -40.0 : 0.0;
  }
  MetricsParameters p;
  p.steering_rate_limit_radps = 0.8;
  p.steering_acceleration_limit_radps2 = 30.0;
  const Metrics m = compute_metrics(trace, p);
  EXPECT_NEAR(m.held_rate_max_radps, 1.0, 1e-12);
  EXPECT_NEAR(m.held_rate_rms_radps, std::sqrt((0.25 + 1.0 + 0.0) / 3.0), 1e-12);
  EXPECT_EQ(m.held_rate_violations, 1);
  EXPECT_NEAR(m.held_acceleration_max_radps2, 50.0, 1e-9);
  EXPECT_NEAR(m.held_acceleration_rms_radps2, std::sqrt((625.0 + 2500.0) / 2.0), 1e-9);
  EXPECT_EQ(m.held_acceleration_violations, 1);
  EXPECT_NEAR(m.actual_rate_rms_radps, std::sqrt(0.36 / 4.0), 1e-12);
  EXPECT_EQ(m.actual_rate_violations, 0);
  EXPECT_NEAR(m.actual_acceleration_rms_radps2, 20.0, 1e-12);
  EXPECT_EQ(m.actual_acceleration_violations, 1);
}

TEST(Metrics, TheTestsHeldCommandCheckAgreesWithTheMetrics) {
  // tests/support/held_command.hpp on the sequence above: the same rates and accelerations, and
  // a violation named exactly where the metrics count one.
  const double commands[] = {0.0, 0.01, 0.03, 0.03};
  const double rates[] = {0.0, 0.5, 1.0, 0.0};
  const double accelerations[] = {0.0, 0.0, 25.0, -50.0};
  testing::HeldCommand held;
  const testing::HeldLimits limits{
      .angle_rad = 0.02, .rate_radps = 0.8, .acceleration_radps2 = 30.0};
  // Which limits each sample breaks: none, none, angle and rate, angle and acceleration.
  const char* broken[] = {"", "", "angle rate", "angle acceleration"};
  for (int k = 0; k < 4; ++k) {
    held.push(commands[k], 0.02);
    EXPECT_EQ(held.has_rate(), k >= 1);
    EXPECT_EQ(held.has_acceleration(), k >= 2);
    if (held.has_rate()) {
      EXPECT_NEAR(held.rate(), rates[k], 1e-12) << k;
    }
    if (held.has_acceleration()) {
      EXPECT_NEAR(held.acceleration(), accelerations[k], 1e-9) << k;
    }
    const std::string failure = held.violation(limits);
    std::string named;
    for (const char* what : {"angle", "rate", "acceleration"}) {
      std::string needle = "held ";
      needle.append(what).append(" ");
      if (failure.find(needle) == std::string::npos) continue;
      if (!named.empty()) named.append(" ");
      named.append(what);
    }
    EXPECT_EQ(named, broken[k]) << "sample " << k << ": " << failure;
  }
  EXPECT_NEAR(held.max_abs_rate(), 1.0, 1e-12);
  EXPECT_NEAR(held.max_abs_acceleration(), 50.0, 1e-9);
  held.restart(0.01);
  EXPECT_FALSE(held.has_rate());
  held.push(0.02, 0.02);
  EXPECT_TRUE(held.has_rate() && !held.has_acceleration());
  EXPECT_NEAR(held.rate(), 0.5, 1e-12);
}

TEST(Metrics, RmsRearErrorIsOverEveryRowWithTheStart) {
  std::vector<TraceSample> trace(4);
  const double errors[] = {1.0, -0.5, 0.0, 0.5};
  for (std::size_t i = 0; i < trace.size(); ++i) {
    trace[i].time_s = 0.02 * static_cast<double>(i);
    trace[i].lateral_error_m = errors[i];
  }
  const Metrics m = compute_metrics(trace, MetricsParameters{});
  EXPECT_NEAR(m.rms_rear_error_m, std::sqrt((1.0 + 0.25 + 0.0 + 0.25) / 4.0), 1e-12);
  EXPECT_NEAR(m.max_abs_rear_error_m, 1.0, 1e-12);
}

TEST(Metrics, ReachingRestartsAfterEveryExcursion) {
  // |e_lead|: 1, 0.05, 0.05, 0.5, 0.02, 0.01 -> reached at row 4 (the last excursion is row 3).
  const double errors[] = {1.0, 0.05, 0.05, 0.5, 0.02, 0.01};
  std::vector<TraceSample> trace(6);
  for (std::size_t i = 0; i < trace.size(); ++i) {
    trace[i].time_s = static_cast<double>(i);
    trace[i].distance_m = 10.0 * static_cast<double>(i);
    trace[i].lead_lateral_error_m = errors[i];
  }
  const Metrics m = compute_metrics(trace, MetricsParameters{});
  EXPECT_TRUE(m.reached);
  EXPECT_EQ(m.reaching_time_s, 4.0);
  EXPECT_EQ(m.reaching_distance_m, 40.0);
  EXPECT_EQ(m.max_abs_lead_error_after_reaching_m, 0.02);
  trace.back().lead_lateral_error_m = 0.2;
  const Metrics not_reached = compute_metrics(trace, MetricsParameters{});
  EXPECT_FALSE(not_reached.reached);
  EXPECT_EQ(not_reached.reaching_time_s, -1.0);
  EXPECT_EQ(not_reached.max_abs_lead_error_after_reaching_m, -1.0);
}

}  // namespace
}  // namespace smoothsteer
