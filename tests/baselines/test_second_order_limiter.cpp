// The second-order limiter of the comparison controllers (SteeringSaturator,
// src/controller/second_order_limiter.cpp): on random raw commands, limits and periods its held
// output keeps the angle, rate and acceleration limits differenced at the actual periods; a
// command that keeps them passes unchanged; a step target is reached time-optimally without
// overshoot; the statistics count every clamp.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "smoothsteer/baselines/steering_limits.hpp"
#include "support/held_command.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double eps = std::numeric_limits<double>::epsilon();

SteeringLimits random_limits(testing::Random& random) {
  SteeringLimits limits;
  limits.angle_rad = random.uniform(0.05, 1.5);
  limits.rate_radps = std::exp(random.uniform(std::log(0.05), std::log(5.0)));
  limits.acceleration_radps2 = std::exp(random.uniform(std::log(0.5), std::log(200.0)));
  return limits;
}

std::string describe(const SteeringLimits& limits) {
  std::ostringstream text;
  text.precision(17);
  text << "D=" << limits.angle_rad << " R=" << limits.rate_radps
       << " A=" << limits.acceleration_radps2;
  return text.str();
}

//! Periods: constant, or drawn per sample from [h, ratio h].
std::vector<double> random_periods(testing::Random& random, int count, double& ratio) {
  const double period = std::exp(random.uniform(std::log(1e-3), std::log(0.1)));
  ratio = random.coin() ? 1.0 : random.uniform(1.0, 5.0);
  std::vector<double> periods(static_cast<std::size_t>(count));
  for (double& h : periods) h = period * (ratio > 1.0 ? random.uniform(1.0, ratio) : 1.0);
  return periods;
}

//! Raw commands in segments: noise, steps, ramps, sinusoids, NaN bursts, huge values.
std::vector<double> hostile_commands(testing::Random& random, int count, double bound,
                                     double rate) {
  std::vector<double> raw;
  while (static_cast<int>(raw.size()) < count) {
    const int length = random.integer(1, 200);
    const int kind = random.integer(0, 5);
    const double level = random.uniform(-1.5 * bound, 1.5 * bound);
    const double slope = random.uniform(-3.0, 3.0) * rate * 0.01;
    const double frequency = random.uniform(0.01, 1.0);
    for (int i = 0; i < length; ++i) {
      switch (kind) {
        case 0:
          raw.push_back(random.uniform(-2.0 * bound, 2.0 * bound));
          break;
        case 1:
          raw.push_back(level);
          break;
        case 2:
          raw.push_back(level + slope * i);
          break;
        case 3:
          raw.push_back(level * std::sin(frequency * i));
          break;
        case 4:
          raw.push_back(std::nan(""));
          break;
        default: {
          const double huge[] = {1e300, -1e300, inf, -inf, 1e9 * bound};
          raw.push_back(huge[random.integer(0, 4)]);
        }
      }
    }
  }
  raw.resize(static_cast<std::size_t>(count));
  return raw;
}

//! Checks the held sequence sample by sample against the limits (HeldCommand), with the
//! round-off of differencing at these periods, and the limiter's invariant set: "" when it
//! keeps them.
struct HeldChecker {
  SteeringLimits limits;
  testing::HeldCommand held;
  double previous_period = 0.0;

  HeldChecker(const SteeringLimits& l, double command, double rate)
      : limits(l), held(command, rate) {}

  std::string check(double next, double period) {
    const double bound = limits.angle_rad;
    // Round-off of differencing commands of size <= bound at these periods.
    const double rate_roundoff = 16.0 * eps * bound / period;
    const double shortest = previous_period > 0.0 ? std::min(period, previous_period) : period;
    const double acceleration_roundoff = 2.0 * 16.0 * eps * bound / (period * shortest);
    held.push(next, period);
    previous_period = period;
    std::ostringstream failure;
    failure.precision(17);
    failure << held.violation(
        testing::HeldLimits{.rate_radps = limits.rate_radps,
                            .acceleration_radps2 = limits.acceleration_radps2},
        testing::HeldTolerance{1e-9, rate_roundoff, acceleration_roundoff});
    // The angle exactly, and the invariant set: the stop at the acceleration limit stays inside
    // the angle bound.
    if (!(std::abs(next) <= bound)) failure << "angle " << next << " beyond " << bound;
    const double stop =
        next + held.rate() * std::abs(held.rate()) / (2.0 * limits.acceleration_radps2);
    if (!(std::abs(stop) <= bound * (1.0 + 1e-9) + rate_roundoff * period)) {
      failure << "stopping point " << stop << " beyond " << bound;
    }
    return failure.str();
  }
};

TEST(SecondOrderLimiter, HeldCommandKeepsEveryLimitOnHostileInput) {
  const int cases = testing::property_cases(40);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed + 11);
    const SteeringLimits limits = random_limits(random);
    constexpr int steps = 3000;
    double ratio = 1.0;
    const std::vector<double> periods = random_periods(random, steps, ratio);
    const std::vector<double> raw =
        hostile_commands(random, steps, limits.angle_rad, limits.rate_radps);
    SteeringSaturator saturator(limits);
    const double start = random.uniform(-limits.angle_rad, limits.angle_rad);
    const double start_rate = random.uniform(-2.0, 2.0) * limits.rate_radps;
    saturator.reset(start, start_rate);
    HeldChecker held{limits, saturator.previous(), saturator.previous_rate()};
    for (int k = 0; k < steps; ++k) {
      double rate = 0.0;
      const double h = periods[static_cast<std::size_t>(k)];
      const double u = saturator.apply(raw[static_cast<std::size_t>(k)], h, rate);
      const std::string failure = held.check(u, h);
      ASSERT_TRUE(failure.empty())
          << failure << " at sample " << k << " raw " << raw[static_cast<std::size_t>(k)] << " h "
          << h << "; " << describe(limits) << " period ratio " << ratio << " start " << start
          << " start rate " << start_rate << "; " << testing::seed_message(seed);
      ASSERT_DOUBLE_EQ(rate, held.held.rate()) << "reported rate at sample " << k;
    }
    EXPECT_EQ(saturator.statistics().updates, steps);
  }
}

TEST(SecondOrderLimiter, CommandThatKeepsTheLimitsPassesUnchanged) {
  const int cases = testing::property_cases(40);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed + 12);
    const SteeringLimits limits = random_limits(random);
    constexpr int steps = 2000;
    double ratio = 1.0;
    const std::vector<double> periods = random_periods(random, steps, ratio);
    // u(t) = sum a_i sin(w_i t + phi_i) with sum a_i <= D / 2, rate sum a_i w_i <= R and
    // V^2 / (2A) <= 0.4 D (stop inside the bound), sum a_i w_i^2 <= A 2 / (1 + ratio): the
    // difference quotients are means of u' over each period, so their difference over the
    // period is at most max|u''| (h_k + h_{k-1}) / (2 h_k).
    const double amplitude = 0.5 * limits.angle_rad * random.uniform(0.1, 1.0);
    const double rate_room =
        std::min(limits.rate_radps, std::sqrt(0.8 * limits.acceleration_radps2 * limits.angle_rad));
    const double largest_w =
        std::min(rate_room / amplitude,
                 std::sqrt(2.0 * limits.acceleration_radps2 / ((1.0 + ratio) * amplitude)));
    struct Wave {
      double a, w, phi;
    };
    std::vector<Wave> waves;
    double left = amplitude;
    for (int i = 0; i < 3; ++i) {
      const double a = i == 2 ? left : left * random.uniform(0.0, 1.0);
      left -= a;
      waves.push_back({a, largest_w * random.uniform(0.1, 0.999), random.uniform(0.0, 6.3)});
    }
    const auto u = [&](double t) {
      double value = 0.0;
      for (const Wave& wave : waves) value += wave.a * std::sin(wave.w * t + wave.phi);
      return value;
    };
    SteeringSaturator saturator(limits);
    double t = 0.0;
    saturator.reset(u(t), (u(t) - u(t - periods[0])) / periods[0]);
    for (int k = 0; k < steps; ++k) {
      t += periods[static_cast<std::size_t>(k)];
      double rate = 0.0;
      const double raw = u(t);
      const double held = saturator.apply(raw, periods[static_cast<std::size_t>(k)], rate);
      ASSERT_EQ(held, raw) << "sample " << k << "; " << describe(limits) << " period ratio "
                           << ratio << " amplitude " << amplitude << " w " << largest_w << "; "
                           << testing::seed_message(seed);
    }
    EXPECT_EQ(saturator.statistics().limited, 0) << testing::seed_message(seed);
    EXPECT_EQ(saturator.statistics().acceleration_limited, 0);
  }
}

TEST(SecondOrderLimiter, CommandAtExactlyTheLimitsPassesUnchanged) {
  // The car's limits at 100 Hz: from rest at -0.3 rad the rate grows by A h per period to R,
  // cruises, and brakes back to rest, each command the previous plus h r in floating point,
  // so the differences sit at the limits up to round-off. Then the same mirrored.
  const SteeringLimits limits{1.066, 0.4, 8.0};
  const double h = 0.01;
  SteeringSaturator saturator(limits);
  saturator.reset(-0.3);
  double command = -0.3;
  double rate = 0.0;
  std::vector<double> rates;
  for (int k = 1; k <= 5; ++k) rates.push_back(k * 0.08);
  for (int k = 0; k < 100; ++k) rates.push_back(0.4);
  for (int k = 4; k >= 0; --k) rates.push_back(k * 0.08);
  for (double sign : {1.0, -1.0}) {
    for (double r : rates) {
      command += h * sign * r;
      double applied = 0.0;
      ASSERT_EQ(saturator.apply(command, h, applied), command) << "rate " << sign * r;
      rate = applied;
    }
  }
  EXPECT_EQ(rate, 0.0);
  EXPECT_EQ(saturator.statistics().limited, 0);
}

//! Least time from rest to rest over `distance` at rate R and acceleration A.
double rest_to_rest_time(double distance, double rate, double acceleration) {
  if (distance >= rate * rate / acceleration) return distance / rate + rate / acceleration;
  return 2.0 * std::sqrt(distance / acceleration);
}

TEST(SecondOrderLimiter, StepTargetIsReachedWithoutOvershoot) {
  const int cases = testing::property_cases(40);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed + 13);
    const SteeringLimits limits = random_limits(random);
    const double h = std::exp(random.uniform(std::log(1e-3), std::log(0.05)));
    const double bound = limits.angle_rad;
    const double start = random.uniform(-0.9 * bound, 0.9 * bound);
    // Inside the bound (0.9 D), or beyond it (clamped to the bound).
    const double raw = random.coin() ? random.uniform(-0.9 * bound, 0.9 * bound)
                                     : std::copysign(random.uniform(bound, 3.0 * bound),
                                                     random.uniform(-1.0, 1.0));
    const double target = std::clamp(raw, -bound, bound);
    const double direction = target >= start ? 1.0 : -1.0;
    const double distance = std::abs(target - start);
    // The discrete profile ends on a period boundary; at the bound the approach brakes by
    // r^2 / (2A) (not the discrete stop) and lands a few periods later. Over 20 000 cases:
    // at most 1 period beyond the continuous least time inside the bound, 6 at the bound.
    const double optimal =
        rest_to_rest_time(distance, limits.rate_radps, limits.acceleration_radps2);
    const int allowed =
        static_cast<int>(std::ceil(optimal / h)) + 2 + (std::abs(raw) >= bound ? 8 : 0);
    SteeringSaturator saturator(limits);
    saturator.reset(start);
    int reached = -1;
    const int steps = allowed + 200;
    const std::string context = describe(limits) + " h " + std::to_string(h) + " start " +
                                std::to_string(start) + " raw " + std::to_string(raw) + "; " +
                                testing::seed_message(seed);
    for (int k = 0; k < steps; ++k) {
      double rate = 0.0;
      const double u = saturator.apply(raw, h, rate);
      ASSERT_LE(direction * (u - target), 1e-9 * bound) << "overshoot at " << k << "; " << context;
      if (reached < 0 && u == target) reached = k;
      if (reached >= 0) {
        ASSERT_EQ(u, target) << "left the target at " << k << "; " << context;
      }
    }
    ASSERT_GE(reached, 0) << context;
    EXPECT_LE(reached + 1, allowed) << "optimal " << optimal / h << " periods; " << context;
  }
}

TEST(SecondOrderLimiter, StepOvershootAtVaryingPeriodsStaysWithinOnePeriod) {
  const int cases = testing::property_cases(40);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed + 14);
    const SteeringLimits limits = random_limits(random);
    const double bound = limits.angle_rad;
    const double target = random.uniform(-0.9 * bound, 0.9 * bound);
    const double start = random.uniform(-0.9 * bound, 0.9 * bound);
    // Twice the least time, in the shortest periods, plus a margin.
    const double optimal =
        rest_to_rest_time(std::abs(target - start), limits.rate_radps, limits.acceleration_radps2);
    const double shortest = std::exp(random.uniform(std::log(1e-3), std::log(0.1)));
    const double ratio = random.uniform(1.0, 5.0);
    std::vector<double> periods(static_cast<std::size_t>(2.0 * optimal / shortest) + 2000);
    for (double& h : periods) h = shortest * random.uniform(1.0, ratio);
    const double longest = *std::max_element(periods.begin(), periods.end());
    const double direction = target >= start ? 1.0 : -1.0;
    SteeringSaturator saturator(limits);
    saturator.reset(start);
    double overshoot = 0.0;
    for (double h : periods) {
      double rate = 0.0;
      overshoot = std::max(overshoot, direction * (saturator.apply(target, h, rate) - target));
    }
    EXPECT_LE(overshoot, limits.rate_radps * longest)
        << describe(limits) << " ratio " << ratio << "; " << testing::seed_message(seed);
    EXPECT_NEAR(saturator.previous(), target, 1e-9 * bound) << testing::seed_message(seed);
  }
}

TEST(SecondOrderLimiter, StatisticsCountEveryClamp) {
  const int cases = testing::property_cases(40);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed + 15);
    const SteeringLimits limits = random_limits(random);
    constexpr int steps = 2000;
    double ratio = 1.0;
    const std::vector<double> periods = random_periods(random, steps, ratio);
    std::vector<double> raw = hostile_commands(random, steps, limits.angle_rad, limits.rate_radps);
    // Away from the counting tolerance of the angle bound.
    for (double& value : raw) {
      if (std::abs(std::abs(value) - limits.angle_rad) < 1e-6) value *= 0.5;
    }
    SteeringSaturator saturator(limits);
    SaturationStatistics expected;
    double previous = 0.0;
    double previous_rate = 0.0;
    for (int k = 0; k < steps; ++k) {
      const double h = periods[static_cast<std::size_t>(k)];
      const double x = raw[static_cast<std::size_t>(k)];
      double rate = 0.0;
      const double u = saturator.apply(x, h, rate);
      ++expected.updates;
      const bool finite = std::isfinite(x);
      const double clamped = finite ? std::clamp(x, -limits.angle_rad, limits.angle_rad) : previous;
      const bool angle = finite && std::abs(x) > limits.angle_rad;
      if (angle) {
        ++expected.angle_limited;
        expected.max_angle_excess_rad =
            std::max(expected.max_angle_excess_rad, std::abs(x) - limits.angle_rad);
      }
      const double change = clamped - previous;
      const bool rate_clamp = std::abs(change) > limits.rate_radps * h * (1.0 + 1e-9);
      const double first_order =
          rate_clamp ? previous + std::copysign(limits.rate_radps * h, change) : clamped;
      if (rate_clamp) {
        ++expected.rate_limited;
        expected.max_rate_excess_radps =
            std::max(expected.max_rate_excess_radps, std::abs(change) / h - limits.rate_radps);
      }
      const double first_order_acceleration = ((first_order - previous) / h - previous_rate) / h;
      expected.max_acceleration_excess_radps2 =
          std::max(expected.max_acceleration_excess_radps2,
                   std::abs(first_order_acceleration) - limits.acceleration_radps2);
      const bool acceleration =
          std::abs(u - first_order) > 1e-9 * limits.acceleration_radps2 * h * h;
      if (acceleration) ++expected.acceleration_limited;
      if (angle || rate_clamp || acceleration) ++expected.limited;
      previous_rate = (u - previous) / h;
      previous = u;
    }
    const SaturationStatistics& s = saturator.statistics();
    const std::string context = describe(limits) + "; " + testing::seed_message(seed);
    EXPECT_EQ(s.updates, expected.updates) << context;
    EXPECT_EQ(s.angle_limited, expected.angle_limited) << context;
    EXPECT_EQ(s.rate_limited, expected.rate_limited) << context;
    EXPECT_EQ(s.acceleration_limited, expected.acceleration_limited) << context;
    EXPECT_EQ(s.limited, expected.limited) << context;
    EXPECT_DOUBLE_EQ(s.max_angle_excess_rad, expected.max_angle_excess_rad) << context;
    EXPECT_NEAR(s.max_rate_excess_radps, expected.max_rate_excess_radps,
                1e-9 * expected.max_rate_excess_radps)
        << context;
    EXPECT_NEAR(s.max_acceleration_excess_radps2, expected.max_acceleration_excess_radps2,
                1e-9 * expected.max_acceleration_excess_radps2)
        << context;
    EXPECT_NEAR(s.limited_fraction(),
                static_cast<double>(expected.limited) / static_cast<double>(steps), 1e-12);
  }
}

TEST(SecondOrderLimiter, ExactStepFromRest) {
  // D = 0.5, R = 1, A = 10, h = 0.01 from rest at 0 towards 0.5: the rate may grow by
  // A h = 0.1 rad/s per period, so the first command is A h^2 = 0.001 rad.
  SteeringSaturator saturator({0.5, 1.0, 10.0});
  double rate = 0.0;
  EXPECT_DOUBLE_EQ(saturator.apply(0.5, 0.01, rate), 0.001);
  EXPECT_DOUBLE_EQ(rate, 0.1);
  const SaturationStatistics& s = saturator.statistics();
  EXPECT_EQ(s.angle_limited, 0);
  EXPECT_EQ(s.rate_limited, 1);
  EXPECT_EQ(s.acceleration_limited, 1);
  EXPECT_EQ(s.limited, 1);
  EXPECT_DOUBLE_EQ(s.max_rate_excess_radps, 49.0);           // 0.5 / 0.01 - 1
  EXPECT_DOUBLE_EQ(s.max_acceleration_excess_radps2, 90.0);  // 1 / 0.01 - 10
  EXPECT_DOUBLE_EQ(saturator.apply(0.5, 0.01, rate), 0.003);
  EXPECT_DOUBLE_EQ(rate, 0.2);
}

TEST(SecondOrderLimiter, WithoutAccelerationLimitItIsTheFirstOrderClamp) {
  const int cases = testing::property_cases(40);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed + 16);
    SteeringLimits limits = random_limits(random);
    limits.acceleration_radps2 = inf;
    double ratio = 1.0;
    const std::vector<double> periods = random_periods(random, 1000, ratio);
    const std::vector<double> raw =
        hostile_commands(random, 1000, limits.angle_rad, limits.rate_radps);
    SteeringSaturator saturator(limits);
    double previous = 0.0;
    for (std::size_t k = 0; k < raw.size(); ++k) {
      const double h = periods[k];
      const double angle = std::isfinite(raw[k])
                               ? std::clamp(raw[k], -limits.angle_rad, limits.angle_rad)
                               : previous;
      const double change = angle - previous;
      const double largest = limits.rate_radps * h;
      const double expected = std::abs(change) > largest * (1.0 + 1e-9)
                                  ? previous + std::clamp(change, -largest, largest)
                                  : angle;
      double rate = 0.0;
      const double u = saturator.apply(raw[k], h, rate);
      ASSERT_EQ(u, expected) << "sample " << k << " raw " << raw[k] << "; "
                             << testing::seed_message(seed);
      previous = u;
    }
    EXPECT_EQ(saturator.statistics().acceleration_limited, 0);
  }
}

TEST(SecondOrderLimiter, NonFiniteRawCommandBrakesToThePreviousCommand) {
  SteeringSaturator saturator({0.5, 1.0, 10.0});
  double rate = 0.0;
  // At rest: the previous command stays exactly.
  saturator.reset(0.2);
  EXPECT_EQ(saturator.apply(std::nan(""), 0.01, rate), 0.2);
  EXPECT_EQ(rate, 0.0);
  // Moving at 0.5 rad/s: holding would need 50 rad/s^2; it brakes at A instead and stops.
  saturator.reset(0.0, 0.5);
  double previous_rate = 0.5;
  for (int k = 0; k < 20; ++k) {
    saturator.apply(std::nan(""), 0.01, rate);
    EXPECT_LE(std::abs(rate - previous_rate), 10.0 * 0.01 * (1.0 + 1e-9)) << k;
    previous_rate = rate;
  }
  EXPECT_EQ(rate, 0.0);
  EXPECT_EQ(saturator.apply(std::nan(""), 0.01, rate), saturator.previous());
  // A bad period changes nothing.
  const double held = saturator.previous();
  EXPECT_EQ(saturator.apply(0.4, 0.0, rate), held);
  EXPECT_EQ(saturator.apply(0.4, std::nan(""), rate), held);
  EXPECT_EQ(rate, 0.0);
}

TEST(SecondOrderLimiter, ResetClampsTheRateIntoTheSetItCanStopFrom) {
  // From 0.49 rad towards the bound 0.5 the car can stop at A = 10 only from
  // sqrt(2 A 0.01) = 0.447 rad/s.
  SteeringSaturator saturator({0.5, 1.0, 10.0});
  saturator.reset(0.49, 0.9);
  EXPECT_NEAR(saturator.previous_rate(), std::sqrt(0.2), 1e-15);
  saturator.reset(0.49, -5.0);  // away from the near bound: only the rate limit
  EXPECT_EQ(saturator.previous_rate(), -1.0);
  saturator.reset(0.7, std::nan(""));
  EXPECT_EQ(saturator.previous(), 0.5);
  EXPECT_EQ(saturator.previous_rate(), 0.0);
}

TEST(SecondOrderLimiter, AccelerationLimitIsValidatedByName) {
  SteeringLimits limits;
  limits.acceleration_radps2 = 0.0;
  EXPECT_EQ(limits.validation_error(),
            "SteeringLimits: acceleration_radps2 = 0 must be > 0 (+inf: no limit)");
  limits.acceleration_radps2 = std::nan("");
  EXPECT_NE(limits.validation_error().find("acceleration_radps2 = nan"), std::string::npos)
      << limits.validation_error();
  limits.acceleration_radps2 = -inf;
  EXPECT_FALSE(limits.is_valid());
  limits.acceleration_radps2 = inf;
  EXPECT_TRUE(limits.is_valid());
  EXPECT_THROW(SteeringSaturator({0.5, 1.0, -1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace smoothsteer
