// SteeringOffsetCompensation (system/steering_offset_compensation.hpp): the held command makes up
// for a misaligned rack, not for an angle sensor that reads off, and keeps the car's limits
// whatever the offset estimate does. Against the simulator's actuator (steering_actuator.hpp,
// RK4 at 1 ms), with the observer's offset given as a learning curve.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/system/steering_offset_compensation.hpp"
#include "smoothsteer/system/steering_system.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::property_cases;
using testing::Random;
using testing::seed_message;

constexpr double kSubstep = 0.001;

ActuatorParameters random_actuator(Random& random) {
  ActuatorParameters actuator;
  actuator.bandwidth_hz = random.uniform(2.0, 20.0);
  actuator.dead_time_s = kSubstep * random.integer(0, 60);
  actuator.max_angle_rad = 1.0;
  actuator.max_rate_radps = 10.0;  // not reached: the prediction has no saturation
  return actuator;
}

//! A smooth random command: two sines, with the rate and acceleration within `share` of the
//! limits and the angle within `share` of its bound; `from_rest`: it starts at rest (a (1 - cos)
//! each), as a controller's command does after reset().
struct RandomCommand {
  double amplitude[2], frequency[2], phase[2];
  bool from_rest = false;
  RandomCommand(Random& random, const SteeringLimits& limits, double share, bool rest = false)
      : from_rest(rest) {
    for (int i = 0; i < 2; ++i) {
      frequency[i] = random.uniform(0.1, 1.0);
      const double w = 2.0 * pi * frequency[i];
      amplitude[i] =
          0.5 * share *
          std::min({limits.angle_rad, limits.rate_radps / w, limits.acceleration_radps2 / (w * w)});
      phase[i] = random.uniform(0.0, 2.0 * pi);
    }
  }
  double operator()(double t) const {
    if (from_rest) {
      return 0.5 * (amplitude[0] * (1.0 - std::cos(2.0 * pi * frequency[0] * t)) +
                    amplitude[1] * (1.0 - std::cos(2.0 * pi * frequency[1] * t)));
    }
    return amplitude[0] * std::sin(2.0 * pi * frequency[0] * t + phase[0]) +
           amplitude[1] * std::sin(2.0 * pi * frequency[1] * t + phase[1]);
  }
};

//! Holds `command` over `period_s` on the simulated actuator; returns its angle at the end.
double hold(SteeringActuator& actuator, double command, double period_s) {
  const long substeps = std::lround(period_s / kSubstep);
  for (long i = 0; i < substeps; ++i) actuator.step(command);
  return actuator.angle();
}

TEST(ActuatorAnglePrediction, FollowsTheSimulatedActuatorAtTheControlPeriod) {
  // Dead times that are not a whole number of periods take the fractional split.
  for (int index = 0; index < property_cases(20); ++index) {
    const auto seed = case_seed(index);
    Random random(seed);
    const ActuatorParameters parameters = random_actuator(random);
    const double period = random.coin() ? 0.01 : 0.02;
    const SteeringLimits limits{.angle_rad = 0.5, .rate_radps = 0.4, .acceleration_radps2 = 4.0};
    const RandomCommand command(random, limits, 0.9);
    SCOPED_TRACE(seed_message(seed) + " bandwidth " + std::to_string(parameters.bandwidth_hz) +
                 " Hz, dead time " + std::to_string(parameters.dead_time_s) + " s, period " +
                 std::to_string(period));
    SteeringActuator actuator(parameters, kSubstep);
    ActuatorAnglePrediction prediction(parameters);
    actuator.reset(command(0.0));
    prediction.reset(command(0.0));
    double largest = 0.0;
    for (int k = 0; k < 500; ++k) {
      const double held = command(k * period);
      const double simulated = hold(actuator, held, period);
      largest = std::max(largest, std::abs(prediction.advance(held, period) - simulated));
    }
    // The simulator's RK4 at 1 ms errs by up to 3.5e-7 rad at 20 Hz (p h = 0.25); a dead time
    // off by one period would err by the command's rate times 0.01 s, 1e-3 rad and more.
    EXPECT_LE(largest, 1e-6);
  }
}

struct Case {
  double rack_rad = 0.0;    //!< the wheels steer the actuator's angle plus this
  double sensor_rad = 0.0;  //!< the measured angle reads the actuator's plus this
};

Case random_case(Random& random) {
  Case c;
  const double offset = (random.coin() ? 1.0 : -1.0) * random.uniform(0.003, 0.02);
  switch (random.integer(0, 2)) {
    case 0:
      c.rack_rad = offset;
      break;
    case 1:
      c.sensor_rad = offset;
      break;
    default:
      c.rack_rad = offset;
      c.sensor_rad = (random.coin() ? 1.0 : -1.0) * random.uniform(0.003, 0.02);
  }
  return c;
}

TEST(SteeringOffsetCompensation, MakesUpForTheRackNotTheSensorWithinTheLimits) {
  for (int index = 0; index < property_cases(20); ++index) {
    const auto seed = case_seed(index);
    Random random(seed + 31);
    const ActuatorParameters actuator_parameters = random_actuator(random);
    const Case c = random_case(random);
    const double period = random.coin() ? 0.01 : 0.02;
    const SteeringLimits limits{.angle_rad = random.uniform(0.3, 0.6),
                                .rate_radps = random.uniform(0.3, 0.8),
                                .acceleration_radps2 = random.uniform(1.0, 8.0)};
    // The controller's command near the limits: the car's limiter must take up the offset's
    // share where the sum would leave them.
    const RandomCommand command(random, limits, random.uniform(0.5, 1.0));
    const double learning_s = random.uniform(0.1, 0.6);  // the observer's learning time
    SCOPED_TRACE(seed_message(seed) + " rack " + std::to_string(c.rack_rad) + " sensor " +
                 std::to_string(c.sensor_rad) + " period " + std::to_string(period));
    SteeringOffsetCompensation compensation(SteeringOffsetCompensationParameters{
        .actuator = actuator_parameters, .limits = limits, .max_offset_rad = 0.02});
    SteeringActuator actuator(actuator_parameters, kSubstep);
    actuator.reset(0.0);
    compensation.reset(c.sensor_rad);
    double previous = 0.0, previous_rate = 0.0;
    const double tolerance = 1e-9;
    for (int k = 0; k < 400; ++k) {
      const double t = k * period;
      const double measured = actuator.angle() + c.sensor_rad;
      // The observer's delta_o, wheels minus measured, learned over `learning_s`, and its std.
      const double observer_offset =
          (c.rack_rad - c.sensor_rad) * (1.0 - std::exp(-t / learning_s));
      const double observer_std = 0.01 * std::exp(-t / learning_s) + 2e-4;
      double rate = 0.0, acceleration = 0.0;
      const double held = compensation.update(command(t), measured, observer_offset, observer_std,
                                              period, rate, acceleration);
      ASSERT_LE(std::abs(held), limits.angle_rad * (1.0 + tolerance)) << "k " << k;
      if (k > 0) {
        const double differenced = (held - previous) / period;
        ASSERT_NEAR(differenced, rate, 1e-9) << "k " << k;
        ASSERT_LE(std::abs(differenced), limits.rate_radps * (1.0 + tolerance)) << "k " << k;
        ASSERT_LE(std::abs(differenced - previous_rate) / period,
                  limits.acceleration_radps2 * (1.0 + tolerance))
            << "k " << k;
      }
      previous = held;
      previous_rate = rate;
      hold(actuator, held, period);
    }
    // Settled: the rack's offset made up for (less the deadband), the sensor's not.
    const double deadband = SteeringOffsetCompensationParameters{}.deadband_rad;
    EXPECT_NEAR(compensation.applied_offset_rad(), c.rack_rad, deadband + 1e-4);
    EXPECT_NEAR(compensation.sensor_bias_rad(), c.sensor_rad, 1e-4);
  }
}

TEST(SteeringOffsetCompensation, PassesACommandUnchangedWithoutAnOffset) {
  for (int index = 0; index < property_cases(20); ++index) {
    const auto seed = case_seed(index);
    Random random(seed + 57);
    const ActuatorParameters actuator_parameters = random_actuator(random);
    const double period = random.coin() ? 0.01 : 0.02;
    const SteeringLimits limits{.angle_rad = 0.5, .rate_radps = 0.4, .acceleration_radps2 = 4.0};
    const RandomCommand command(random, limits, 0.8, true);
    const double noise = random.uniform(0.0, 4e-4);  // the observer's offset, within the deadband
    SCOPED_TRACE(seed_message(seed));
    SteeringOffsetCompensation compensation(SteeringOffsetCompensationParameters{
        .actuator = actuator_parameters, .limits = limits, .max_offset_rad = 0.02});
    SteeringActuator actuator(actuator_parameters, kSubstep);
    actuator.reset(command(0.0));
    compensation.reset(command(0.0));
    for (int k = 0; k < 300; ++k) {
      const double t = k * period;
      double rate = 0.0, acceleration = 0.0;
      const double held =
          compensation.update(command(t), actuator.angle(), noise * std::sin(3.0 * t), 1e-4, period,
                              rate, acceleration);
      ASSERT_EQ(held, command(t)) << "k " << k;
      hold(actuator, held, period);
    }
    EXPECT_EQ(compensation.applied_offset_rad(), 0.0);
    EXPECT_EQ(compensation.limiter_statistics().limited, 0);
  }
}

TEST(SteeringOffsetCompensation, HoldsWhileTheCommandTurnsFast) {
  const SteeringLimits limits{.angle_rad = 0.5, .rate_radps = 0.4, .acceleration_radps2 = 4.0};
  SteeringOffsetCompensation compensation(SteeringOffsetCompensationParameters{
      .actuator = ActuatorParameters{}, .limits = limits, .max_offset_rad = 0.02});
  compensation.reset(0.0);
  double rate = 0.0, acceleration = 0.0, command = 0.0;
  compensation.update(command, std::nullopt, 0.0, 1e-4, 0.02, rate, acceleration);
  // An engagement: the command turns at 0.3 rad/s while the observer's offset swings to 0.01.
  for (int k = 0; k < 50; ++k) {
    command += 0.3 * 0.02;
    compensation.update(command, std::nullopt, 0.01, 1e-4, 0.02, rate, acceleration);
  }
  EXPECT_EQ(compensation.applied_offset_rad(), 0.0);
  for (int k = 0; k < 50; ++k) {  // steady again: taken
    compensation.update(command, std::nullopt, 0.01, 1e-4, 0.02, rate, acceleration);
  }
  EXPECT_NEAR(compensation.applied_offset_rad(), 0.0095, 1e-12);
}

TEST(SteeringOffsetCompensation, ForgetsAndKeepsAcrossReset) {
  const SteeringLimits limits{.angle_rad = 0.5, .rate_radps = 0.4, .acceleration_radps2 = 4.0};
  SteeringOffsetCompensation compensation(SteeringOffsetCompensationParameters{
      .actuator = ActuatorParameters{}, .limits = limits, .max_offset_rad = 0.02});
  compensation.reset(0.0);
  double rate = 0.0, acceleration = 0.0, held = 0.0;
  for (int k = 0; k < 200; ++k) {
    held = compensation.update(0.0, std::nullopt, 0.01, 1e-4, 0.02, rate, acceleration);
  }
  EXPECT_NEAR(compensation.applied_offset_rad(), 0.0095, 1e-12);
  EXPECT_NEAR(held, -0.0095, 1e-12);
  compensation.reset(0.1);  // a new engagement: the offset stays, the chain starts at the wheels
  EXPECT_NEAR(compensation.applied_offset_rad(), 0.0095, 1e-12);
  EXPECT_NEAR(compensation.wheels_from_measured(0.1), 0.1095, 1e-12);
  compensation.forget();
  EXPECT_EQ(compensation.applied_offset_rad(), 0.0);
  EXPECT_EQ(compensation.sensor_bias_rad(), 0.0);
}

// The actuator model the system is given is checked like the rest of its parameters: a
// bandwidth or a dead time no actuator has is named by its field, not taken into the prediction.
TEST(SteeringOffsetCompensation, TheActuatorModelIsValidatedByField) {
  SteeringSystemParameters parameters;
  parameters.actuator = ActuatorParameters{};
  EXPECT_EQ(parameters.validation_error(), "");
  for (const double bandwidth : {-1.0, 0.0, std::numeric_limits<double>::quiet_NaN(),
                                 std::numeric_limits<double>::infinity()}) {
    parameters.actuator->bandwidth_hz = bandwidth;
    EXPECT_NE(parameters.validation_error().find("actuator.bandwidth_hz"), std::string::npos)
        << bandwidth << ": " << parameters.validation_error();
  }
  parameters.actuator = ActuatorParameters{};
  for (const double dead_time : {-0.01, 10.5, std::numeric_limits<double>::quiet_NaN()}) {
    parameters.actuator->dead_time_s = dead_time;
    EXPECT_NE(parameters.validation_error().find("actuator.dead_time_s"), std::string::npos)
        << dead_time << ": " << parameters.validation_error();
  }
  parameters.actuator = ActuatorParameters{};
  parameters.actuator->ideal = true;  // an ideal actuator has no low-pass to check
  parameters.actuator->bandwidth_hz = 0.0;
  EXPECT_EQ(parameters.validation_error(), "");
}

}  // namespace
}  // namespace smoothsteer
