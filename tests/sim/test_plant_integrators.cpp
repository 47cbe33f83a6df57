// The adaptive plant integrators (exact actuator lags + Fehlberg 7(8) / Dormand-Prince 5(4))
// against RK4 at a ten times finer sub-step: the same trajectory to well below a millimetre
// under a smooth held steering command with a speed ramp and dead times, with far fewer model
// evaluations than RK4 at the default sub-step. (In closed loop the sliding-mode law amplifies
// any difference through its switching; docs/benchmarks.md reports the shipped scenarios.)

#include <gtest/gtest.h>

#include <cmath>

#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/sim/metrics.hpp"
#include "support/sim_test_support.hpp"

namespace smoothsteer {
namespace {

//! Held command 0.08 sin(0.7 t) + 0.03 sin(2.1 t) [rad]: open loop, smooth, below every limit.
class SmoothSteering final : public SteeringController {
 public:
  Status compute_command(const ControllerInput&, ControllerOutput& output) noexcept override {
    output = ControllerOutput{};
    output.steering_angle_rad = 0.08 * std::sin(0.7 * t_) + 0.03 * std::sin(2.1 * t_);
    t_ += 0.02;
    return Status::ok;
  }
  Status reset(double) noexcept override {
    t_ = 0.0;
    return Status::ok;
  }
  const char* name() const noexcept override { return "smooth"; }

 private:
  double t_ = 0.0;
};

SimulationResult run(PlantIntegrator integrator, double dead_time_s, double substep_s) {
  const VehicleParameters car;
  const Path path = Path::straight_line({0, 0}, 0.0, 500.0);
  SmoothSteering controller;
  DynamicSingleTrack model(car);
  ActuatorParameters actuator;
  actuator.dead_time_s = dead_time_s;
  actuator.max_rate_radps = 3.0;
  SimulationParameters sim;
  sim.duration_s = 15.0;
  sim.substep_s = substep_s;
  sim.integrator = integrator;
  // The ramp starts and ends inside control periods (1.01 s, 9.01 s).
  return simulate(path, model, actuator, SpeedProfile{8.0, 12.0, 0.5, 1.01}, sim,
                  {{0.0, -0.5}, 0.05}, controller);
}

TEST(PlantIntegrators, AdaptiveMatchesFineRk4WithFewerEvaluations) {
  SimulationParameters adaptive;
  adaptive.integrator = PlantIntegrator::rkf78;
  if (!adaptive.is_valid()) GTEST_SKIP() << adaptive.validation_error();
  for (double dead_time : {0.0, 0.01, 0.03}) {
    const SimulationResult fine = run(PlantIntegrator::fixed_rk4, dead_time, 0.0001);
    const SimulationResult reference = run(PlantIntegrator::fixed_rk4, dead_time, 0.001);
    for (PlantIntegrator integrator : {PlantIntegrator::rkf78, PlantIntegrator::dopri5}) {
      SCOPED_TRACE("dead time " + std::to_string(dead_time) + " s, integrator " +
                   std::to_string(static_cast<int>(integrator)));
      const SimulationResult result = run(integrator, dead_time, 0.001);
      ASSERT_EQ(result.trace.size(), fine.trace.size());
      double worst_position = 0.0, worst_angle = 0.0, worst_speed = 0.0;
      for (std::size_t i = 0; i < result.trace.size(); ++i) {
        const TraceSample& a = result.trace[i];
        const TraceSample& b = fine.trace[i];
        worst_position =
            std::max(worst_position, norm(a.rear_axle.position - b.rear_axle.position));
        worst_angle =
            std::max({worst_angle, std::abs(a.rear_axle.heading_rad - b.rear_axle.heading_rad),
                      std::abs(a.steering_actual_rad - b.steering_actual_rad)});
        worst_speed = std::max(worst_speed, std::abs(a.speed_mps - b.speed_mps));
      }
      EXPECT_LT(worst_position, 1e-4);
      EXPECT_LT(worst_angle, 1e-5);
      EXPECT_LT(worst_speed, 1e-6);
      const std::uint64_t fewer = integrator == PlantIntegrator::rkf78 ? 4 : 2;
      EXPECT_LT(fewer * result.model_evaluations, reference.model_evaluations)
          << result.model_evaluations << " vs " << reference.model_evaluations;
    }
  }
}

}  // namespace
}  // namespace smoothsteer
