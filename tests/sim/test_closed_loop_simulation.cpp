// Closed loop with the kinetic model: convergence at 50 and 20 Hz, reproducible noise,
// matched disturbance injection, and the metric definitions on exact traces.

#include <gtest/gtest.h>

#include <cmath>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/sim/metrics.hpp"
#include "support/property.hpp"
#include "support/sim_test_support.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::property_cases;
using testing::Random;
using testing::seed_message;

Path circle_sections() {
  return PathBuilder({0, 0}, 0.0).line(15).arc(30, pi / 2).arc(40, -pi).arc(50, pi / 2).build();
}

ActuatorParameters paper_actuator() {
  ActuatorParameters a;
  a.bandwidth_hz = 10.0;
  a.dead_time_s = 0.0;
  a.max_rate_radps = 3.0;
  return a;
}

SimulationResult run_circle_sections(double period, double noise, std::uint64_t seed,
                                     Pose2 start = {{0.0, -1.0}, 0.0}) {
  const VehicleParameters car;
  auto path = std::make_shared<const Path>(circle_sections());
  ControllerParameters parameters =
      ControllerParameters::paper_c1(car.wheelbase_m(), 0.5, 0.2, 0.3);
  LeadWheelController controller(parameters, path);
  DynamicSingleTrack model(car);
  SimulationParameters sim;
  sim.control_period_s = period;
  sim.duration_s = 40.0;
  sim.position_noise_std_m = noise;
  sim.heading_noise_std_rad = noise / 5.0;
  sim.noise_seed = seed;
  const SpeedProfile speed{2.8, 12.5, 0.5, 2.0};
  return simulate(*path, model, paper_actuator(), speed, sim, start, controller);
}

TEST(Simulation, CircleSectionsConvergeAt50HzAnd20Hz) {
  for (double period : {0.02, 0.05}) {
    const SimulationResult result = run_circle_sections(period, 0.0, 1);
    ASSERT_EQ(result.status, Status::ok);
    ASSERT_FALSE(result.non_finite);
    EXPECT_EQ(result.stop_reason, "path_end") << "period " << period;
    MetricsParameters mp;
    const Metrics m = compute_metrics(result.trace, mp);
    EXPECT_TRUE(m.reached) << "period " << period;
    EXPECT_LT(m.reaching_time_s, 5.0) << "period " << period;
    EXPECT_LT(m.max_abs_lead_error_after_reaching_m, 0.1) << "period " << period;
    EXPECT_EQ(m.non_finite_values, 0);
    // After the transient, the rear axle stays within the corner-cutting + side-slip offset.
    double late = 0.0;
    for (const TraceSample& s : result.trace) {
      if (s.time_s > 8.0) late = std::max(late, std::abs(s.lateral_error_m));
    }
    EXPECT_LT(late, 0.4) << "period " << period;
  }
}

TEST(Simulation, NoiseIsSeededAndReproducible) {
  const SimulationResult a = run_circle_sections(0.02, 0.02, 11);
  const SimulationResult b = run_circle_sections(0.02, 0.02, 11);
  const SimulationResult c = run_circle_sections(0.02, 0.02, 12);
  ASSERT_EQ(a.trace.size(), b.trace.size());
  for (std::size_t i = 0; i < a.trace.size(); ++i) {
    ASSERT_EQ(a.trace[i].steering_command_rad, b.trace[i].steering_command_rad) << i;
  }
  bool differs = false;
  for (std::size_t i = 0; i < std::min(a.trace.size(), c.trace.size()); ++i) {
    differs = differs || a.trace[i].steering_command_rad != c.trace[i].steering_command_rad;
  }
  EXPECT_TRUE(differs);
}

TEST(Simulation, RandomStartsNearThePathConvergeWithoutNaN) {
  for (int k = 0; k < property_cases(4); ++k) {
    const auto seed = case_seed(k);
    Random random(seed);
    const Pose2 start{{random.uniform(-3.0, 3.0), random.uniform(-2.0, 2.0)},
                      random.uniform(-0.5, 0.5)};
    const SimulationResult result = run_circle_sections(0.02, 0.01, seed, start);
    ASSERT_FALSE(result.non_finite) << seed_message(seed);
    const Metrics m = compute_metrics(result.trace, MetricsParameters{});
    EXPECT_EQ(m.non_finite_values, 0) << seed_message(seed);
    EXPECT_TRUE(m.reached) << seed_message(seed);
  }
}

TEST(Simulation, PlantSideDisturbanceBendsTheRearAxlePath) {
  // A controller that is not a LeadWheelController gets kappa_d on the plant: with zero
  // steering, the rear axle drives a circle of curvature kappa_d (kinematic model).
  const Path path = Path::straight_line({0, 0}, 0.0, 1000.0);
  KinematicVehicleModel model(VehicleParameters{});
  testing::ConstantSteering controller(0.0);
  SimulationParameters sim;
  sim.duration_s = 4.0;
  sim.stop_at_path_end = false;
  sim.matched_disturbance = 0.01;
  ActuatorParameters ideal;
  ideal.ideal = true;
  ideal.dead_time_s = 0.0;
  const SimulationResult result = simulate(path, model, ideal, SpeedProfile{5.0, 5.0, 0.0, 0.0},
                                           sim, {{0, 0}, 0.0}, controller);
  EXPECT_NEAR(result.final_state.heading_rad, 0.01 * 5.0 * 4.0, 1e-9);
}

TEST(Simulation, LeadWheelControllerRejectsCoveredMatchedDisturbance) {
  const VehicleParameters car;
  auto path = std::make_shared<const Path>(Path::straight_line({0, 0}, 0.0, 500.0));
  LeadWheelController controller(ControllerParameters::paper_c1(car.wheelbase_m(), 0.5, 0.2, 0.3),
                                 path);
  KinematicVehicleModel model(car);
  SimulationParameters sim;
  sim.duration_s = 30.0;
  sim.matched_disturbance = 0.04;  // < k_rob kbar_l = 0.06
  ActuatorParameters ideal;
  ideal.ideal = true;
  ideal.dead_time_s = 0.0;
  const SimulationResult result = simulate(*path, model, ideal, SpeedProfile{5.0, 5.0, 0.0, 0.0},
                                           sim, {{0, 1.0}, 0.0}, controller);
  const Metrics m = compute_metrics(result.trace, MetricsParameters{});
  EXPECT_TRUE(m.reached);
  EXPECT_LT(std::abs(result.trace.back().lead_lateral_error_m), 0.05);
}

TEST(Metrics, ReachingStdAndViolationsFollowTheirDefinitions) {
  std::vector<TraceSample> trace(6);
  const double lead[] = {1.0, 0.05, 0.2, 0.05, 0.02, -0.01};
  const double rate[] = {0.0, 0.5, -0.5, 0.5, -0.5, 0.0};
  for (std::size_t i = 0; i < trace.size(); ++i) {
    trace[i].time_s = 0.1 * static_cast<double>(i);
    trace[i].distance_m = static_cast<double>(i);
    trace[i].lead_lateral_error_m = lead[i];
    trace[i].lateral_error_m = -lead[i] * 2.0;
    trace[i].steering_command_rate_radps = rate[i];
    trace[i].steering_command_rad = i == 2 ? 2.0 : 0.0;
  }
  MetricsParameters p;
  p.reaching_threshold_m = 0.1;
  p.steering_rate_limit_radps = 0.4;
  const Metrics m = compute_metrics(trace, p);
  EXPECT_TRUE(m.reached);
  EXPECT_DOUBLE_EQ(m.reaching_time_s, 0.3);  // after index 2 (0.2 >= 0.1), stays below
  EXPECT_DOUBLE_EQ(m.reaching_distance_m, 3.0);
  EXPECT_DOUBLE_EQ(m.max_abs_lead_error_after_reaching_m, 0.05);
  EXPECT_DOUBLE_EQ(m.max_abs_rear_error_after_reaching_m, 0.1);
  EXPECT_DOUBLE_EQ(m.max_abs_rear_error_m, 2.0);
  EXPECT_NEAR(m.command_rate_std_radps, std::sqrt(4 * 0.25 / 6.0), 1e-12);
  EXPECT_DOUBLE_EQ(m.command_rate_max_radps, 0.5);
  EXPECT_EQ(m.rate_violations, 4);
  EXPECT_EQ(m.angle_violations, 1);
  EXPECT_EQ(m.bound_violations, 4);  // the angle violation shares step 2 with a rate violation

  trace.back().lead_lateral_error_m = 0.5;  // never settles
  const Metrics never = compute_metrics(trace, p);
  EXPECT_FALSE(never.reached);
  EXPECT_EQ(never.reaching_time_s, -1.0);
}

}  // namespace
}  // namespace smoothsteer
