// Steering actuator: third-order step response, exact dead time, bandwidth, saturation.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "smoothsteer/vehicle/steering_actuator.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::property_cases;
using testing::Random;
using testing::seed_message;

ActuatorParameters unsaturated(double bandwidth, double dead_time) {
  ActuatorParameters p;
  p.bandwidth_hz = bandwidth;
  p.dead_time_s = dead_time;
  p.max_angle_rad = 10.0;
  p.max_rate_radps = 1e6;
  return p;
}

std::vector<double> step_response(const ActuatorParameters& p, double step_s, int steps,
                                  double amplitude) {
  SteeringActuator actuator(p, step_s);
  actuator.reset(0.0);
  std::vector<double> out;
  for (int k = 0; k < steps; ++k) {
    actuator.step(amplitude);
    out.push_back(actuator.angle());
  }
  return out;
}

// The step response of (w/(s+w))^3 is 1 - e^{-wt}(1 + wt + (wt)^2/2): it starts like (wt)^3/6,
// so its log-log slope at small t is 3 (the order), and it matches the closed form.
TEST(SteeringActuator, StepResponseIsThirdOrder) {
  const double h = 1e-4;
  const ActuatorParameters p = unsaturated(3.0, 0.0);
  const double w = p.pole_radps();
  const std::vector<double> y = step_response(p, h, 20000, 1.0);
  for (int k : {10, 100, 1000, 5000, 19999}) {
    const double t = (k + 1) * h;
    const double exact = 1.0 - std::exp(-w * t) * (1.0 + w * t + 0.5 * w * t * w * t);
    EXPECT_NEAR(y[static_cast<std::size_t>(k)], exact, 1e-6) << "t = " << t;
  }
  const double t1 = 20 * h, t2 = 40 * h;
  const double slope = std::log(y[39] / y[19]) / std::log(t2 / t1);
  EXPECT_NEAR(slope, 3.0, 0.1);
}

TEST(SteeringActuator, BandwidthIsTheMinus3dBFrequency) {
  const double h = 1e-4;
  const ActuatorParameters p = unsaturated(2.0, 0.0);
  SteeringActuator actuator(p, h);
  actuator.reset(0.0);
  const double omega = 2.0 * std::numbers::pi * p.bandwidth_hz;
  double peak = 0.0;
  const int steps = static_cast<int>(6.0 / h);
  for (int k = 0; k < steps; ++k) {
    actuator.step(std::sin(omega * k * h));
    if (k * h > 3.0) peak = std::max(peak, std::abs(actuator.angle()));
  }
  EXPECT_NEAR(peak, 1.0 / std::sqrt(2.0), 2e-3);
}

TEST(SteeringActuator, DeadTimeIsExact) {
  for (int k = 0; k < property_cases(10); ++k) {
    const auto seed = case_seed(k);
    Random random(seed);
    const double h = 1e-3;
    const int delay_steps = random.integer(1, 200);
    const ActuatorParameters p = unsaturated(random.uniform(0.5, 10.0), delay_steps * h);
    ActuatorParameters undelayed = p;
    undelayed.dead_time_s = 0.0;
    SteeringActuator delayed_actuator(p, h), reference(undelayed, h);
    ASSERT_EQ(delayed_actuator.delay_steps(), delay_steps);
    delayed_actuator.reset(0.0);
    reference.reset(0.0);
    std::vector<double> commands(600), a, b;
    for (double& c : commands) c = random.uniform(-0.5, 0.5);
    for (std::size_t i = 0; i < commands.size(); ++i) {
      delayed_actuator.step(commands[i]);
      reference.step(commands[i]);
      a.push_back(delayed_actuator.angle());
      b.push_back(reference.angle());
    }
    for (int i = 0; i < delay_steps && i < 600; ++i) {
      EXPECT_EQ(a[static_cast<std::size_t>(i)], 0.0) << seed_message(seed);
    }
    for (std::size_t i = static_cast<std::size_t>(delay_steps); i < a.size(); ++i) {
      ASSERT_EQ(a[i], b[i - static_cast<std::size_t>(delay_steps)])
          << seed_message(seed) << " i " << i;
    }
  }
}

TEST(SteeringActuator, RateAndAngleSaturationHold) {
  for (int k = 0; k < property_cases(10); ++k) {
    const auto seed = case_seed(k);
    Random random(seed);
    ActuatorParameters p;
    p.bandwidth_hz = random.uniform(1.0, 10.0);
    p.max_angle_rad = random.uniform(0.2, 1.0);
    p.max_rate_radps = random.uniform(0.1, 2.0);
    const double h = 1e-3;
    SteeringActuator actuator(p, h);
    actuator.reset(0.0);
    double previous = 0.0;
    for (int i = 0; i < 5000; ++i) {
      const double command = (i / 700) % 2 == 0 ? 2.0 : -2.0;
      actuator.step(command);
      ASSERT_LE(std::abs(actuator.angle()), p.max_angle_rad + 1e-12) << seed_message(seed);
      ASSERT_LE(std::abs(actuator.angle() - previous) / h, p.max_rate_radps * (1.0 + 1e-9))
          << seed_message(seed);
      previous = actuator.angle();
    }
  }
}

TEST(SteeringActuator, ValidationNamesTheField) {
  ActuatorParameters p;
  p.dead_time_s = 0.0105;
  try {
    SteeringActuator actuator(p, 0.001);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("dead_time_s = 0.0105"), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("whole multiple"), std::string::npos);
  }
}

}  // namespace
}  // namespace smoothsteer
