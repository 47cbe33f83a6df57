// PoseLatencyEstimator (system/pose_latency_estimator.hpp): the pose's age from its heading
// against the gyro, when the driving stack does not give it.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/system/pose_latency_estimator.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::property_cases;
using testing::Random;
using testing::seed_message;

constexpr double kPeriod = 0.02;

//! A car turning at a random sum of slow sines: its true heading every period, and the gyro's
//! reading (noise 0.002 rad/s and a bias).
struct Drive {
  std::vector<double> heading, gyro;
};

Drive random_drive(Random& random, int periods, double amplitude_radps, double bias_radps,
                   double start_heading = NAN) {
  double frequency[2], phase[2];
  for (int i = 0; i < 2; ++i) {
    frequency[i] = random.uniform(0.2, 1.0);
    phase[i] = random.uniform(0.0, 2.0 * pi);
  }
  std::normal_distribution<double> noise(0.0, 0.002);
  Drive drive;
  double heading = std::isnan(start_heading) ? random.uniform(-pi, pi) : start_heading;
  for (int k = 0; k < periods; ++k) {
    const double t = k * kPeriod;
    auto rate = [&](double time) {
      return amplitude_radps * 0.5 *
             (std::sin(2.0 * pi * frequency[0] * time + phase[0]) +
              std::sin(2.0 * pi * frequency[1] * time + phase[1]));
    };
    if (k > 0) {  // Simpson's rule over the period: the true heading
      heading += kPeriod / 6.0 * (rate(t - kPeriod) + 4.0 * rate(t - 0.5 * kPeriod) + rate(t));
    }
    drive.heading.push_back(wrap_angle(heading));
    drive.gyro.push_back(rate(t) + bias_radps + noise(random.engine()));
  }
  return drive;
}

//! Runs the estimator on poses `lag` periods late, sampled every `every` periods; returns the
//! ages it gave.
std::vector<double> ages(PoseLatencyEstimator& estimator, const Drive& drive, int lag, int every) {
  std::vector<double> result;
  int delivered = -1;
  for (std::size_t k = 0; k < drive.heading.size(); ++k) {
    const int sample = (static_cast<int>(k) - lag) / every * every;  // the latest old enough
    const bool usable = static_cast<int>(k) >= lag;
    const bool new_pose = usable && sample != delivered;
    if (new_pose) delivered = sample;
    const double heading = drive.heading[static_cast<std::size_t>(std::max(delivered, 0))];
    result.push_back(estimator.update(heading, new_pose, drive.gyro[k], kPeriod, 0.5));
  }
  return result;
}

// Poses 0-5 periods (0-100 ms) late, every period or at 10 Hz, a gyro bias up to 0.005 rad/s,
// turning at 0.05-0.2 rad/s: after 10 s the lag is known within 0.6 of a period (12 ms at 50 Hz;
// measured over 400 cases: within a quarter period but for 2 cases at half a period), and every
// age given is within [0, 0.5] s.
TEST(PoseLatencyEstimator, FindsTheLagOfTheHeadingBehindTheGyro) {
  const int cases = property_cases(60);
  for (int c = 0; c < cases; ++c) {
    const std::uint64_t seed = case_seed(c);
    Random random(seed);
    const int lag = random.integer(0, 5);
    const int every = random.coin() ? 1 : 5;
    const double bias = random.uniform(-0.005, 0.005);
    const Drive drive = random_drive(random, 500, random.uniform(0.05, 0.2), bias);
    PoseLatencyEstimator estimator;
    const std::vector<double> given = ages(estimator, drive, lag, every);
    const std::string inputs = "lag " + std::to_string(lag) + " periods, pose every " +
                               std::to_string(every) + ", gyro bias " + std::to_string(bias) +
                               "; " + seed_message(seed);
    EXPECT_NEAR(estimator.latency_s(), lag * kPeriod, 0.6 * kPeriod) << inputs;
    for (std::size_t k = 300; k < given.size(); ++k) {
      EXPECT_GE(given[k], 0.0);
      EXPECT_LE(given[k], 0.5);
    }
  }
}

// On time it stays 0 exactly (a run whose pose is current is not changed by the estimator), and
// on a straight road a lag learned before stays (its refinement between the grid lags moves with
// the gyro's noise, by less than half a period: measured 0.4): every lag fits a straight alike.
TEST(PoseLatencyEstimator, StaysZeroOnTimeAndKeepsALagOnStraights) {
  const int cases = property_cases(30);
  for (int c = 0; c < cases; ++c) {
    const std::uint64_t seed = case_seed(c);
    Random random(seed);
    const Drive turning =
        random_drive(random, 400, random.uniform(0.05, 0.2), random.uniform(-0.005, 0.005));
    PoseLatencyEstimator on_time;
    for (const double age : ages(on_time, turning, 0, 1)) {
      ASSERT_EQ(age, 0.0) << seed_message(seed);
    }
    PoseLatencyEstimator late;
    (void)ages(late, turning, 3, 1);
    const double learned = late.latency_s();
    // The straight goes on from where the turns ended.
    const Drive straight = random_drive(random, 400, 0.0, 0.0, turning.heading.back());
    (void)ages(late, straight, 3, 1);
    EXPECT_NEAR(late.latency_s(), learned, 0.5 * kPeriod) << seed_message(seed);
  }
}

TEST(PoseLatencyEstimator, RestartKeepsTheLagResetForgetsIt) {
  Random random(11);
  const Drive drive = random_drive(random, 400, 0.15, 0.0);
  PoseLatencyEstimator estimator;
  (void)ages(estimator, drive, 4, 1);
  ASSERT_NEAR(estimator.latency_s(), 4 * kPeriod, 0.25 * kPeriod);
  estimator.restart();
  EXPECT_NEAR(estimator.latency_s(), 4 * kPeriod, 0.25 * kPeriod);
  estimator.reset();
  EXPECT_EQ(estimator.latency_s(), 0.0);
}

}  // namespace
}  // namespace smoothsteer
