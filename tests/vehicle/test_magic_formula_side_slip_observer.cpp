// The side-slip observer with the Magic Formula tire (ObserverTireModel::magic_formula,
// docs/vehicle_dynamics.md section 2): its force slope is the derivative of the plant's force,
// it tracks the rear axle's slip near the friction limit where the linear filter understates it,
// and its new parameters are named when they are wrong.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/vehicle/side_slip_observer.hpp"
#include "smoothsteer/vehicle/vehicle_model.hpp"
#include "support/property.hpp"
#include "support/sim_test_support.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::noisy_slip_sensors;
using testing::property_cases;
using testing::Random;
using testing::seed_message;
using testing::vehicle_rk4_step;

TEST(MagicFormula, SlopeIsTheDerivativeOfTheForce) {
  const int cases = property_cases(40);
  for (int c = 0; c < cases; ++c) {
    const std::uint64_t seed = case_seed(c);
    Random random(seed);
    TireParameters tire;
    tire.stiffness_factor_b = random.uniform(4.0, 25.0);
    tire.shape_factor_c = random.uniform(1.0, 1.9);
    tire.friction_mu = random.uniform(0.3, 1.2);
    tire.curvature_factor_e = random.uniform(-2.0, 1.0);
    const double load = random.uniform(1e3, 1e4);
    const double alpha = random.uniform(-0.5, 0.5);
    const double h = 1e-6;
    const double difference = (DynamicSingleTrack::lateral_force(tire, alpha + h, load) -
                               DynamicSingleTrack::lateral_force(tire, alpha - h, load)) /
                              (2 * h);
    const double slope = DynamicSingleTrack::lateral_force_slope(tire, alpha, load);
    EXPECT_NEAR(slope, difference, 1e-5 * tire.friction_mu * load * tire.stiffness_factor_b)
        << "alpha " << alpha << "; " << seed_message(seed);
  }
  const TireParameters tire;
  EXPECT_NEAR(DynamicSingleTrack::lateral_force_slope(tire, 0.0, 5000.0),
              tire.normalized_cornering_stiffness() * 5000.0, 1e-9);
}

// Near the friction limit: slow random manoeuvres of the kinetic model (Pacejka tires) with
// lateral accelerations of 60-90 % of mu g, a steady turn at the start that the observer does not
// know, noisy gyro (0.002 rad/s) and accelerometer (0.05 m/s^2). Both filters see the same
// measurements. After 1.5 s the Magic Formula filter's worst rear-slip error is within 10 % of
// the manoeuvre's largest slip plus 2 mrad, and over all cases its worst errors add up to at most
// a quarter of the linear filter's (measured: 0.9-1.8 mrad against 2.6-19 mrad, about 1/8).
TEST(SideSlipObserver, MagicFormulaTracksTheSlipNearTheFrictionLimit) {
  const VehicleParameters car;
  const DynamicSingleTrack model(car);
  const int cases = property_cases(40);
  double magic_total = 0.0, linear_total = 0.0;
  for (int c = 0; c < cases; ++c) {
    const std::uint64_t seed = case_seed(c);
    Random random(seed);
    const double speed = random.uniform(10.0, 25.0);
    const double peak_acceleration = random.uniform(0.6, 0.9) * car.friction_limit_mps2();
    // Kinematic steering for that lateral acceleration; the slip adds the rest.
    const double amplitude = car.wheelbase_m() * peak_acceleration / (speed * speed);
    double frequency[2], phase[2];
    for (int i = 0; i < 2; ++i) {
      frequency[i] = random.uniform(0.05, 0.4);
      phase[i] = random.uniform(0.0, 2.0 * pi);
    }
    auto steering = [&](double t) {
      return amplitude * 0.5 *
             (std::sin(2 * pi * frequency[0] * t + phase[0]) +
              std::sin(2 * pi * frequency[1] * t + phase[1]));
    };
    VehicleState x{0.0, 0.0, 0.0, speed, 0.0, 0.0};
    for (int k = 0; k < 3000; ++k) x = vehicle_rk4_step(model, x, steering(0.0), 1e-3);
    SideSlipObserver magic(
        SideSlipObserverParameters::from_vehicle(car, 1.0, 1.0, ObserverTireModel::magic_formula));
    SideSlipObserver linear(SideSlipObserverParameters::from_vehicle(car));
    double largest = 0.0, magic_worst = 0.0, linear_worst = 0.0;
    const double period = 0.02;
    for (int k = 0; k <= 500; ++k) {
      const double t = k * period;
      const double delta = steering(t);
      const SideSlipMeasurement m = noisy_slip_sensors(model, x, delta, random.engine());
      ASSERT_EQ(magic.update(m, period), Status::ok) << seed_message(seed);
      ASSERT_EQ(linear.update(m, period), Status::ok) << seed_message(seed);
      const double truth = rear_axle_side_slip_angle(x, car);
      largest = std::max(largest, std::abs(truth));
      if (t >= 1.5) {
        magic_worst = std::max(magic_worst, std::abs(magic.rear_axle_side_slip_rad() - truth));
        linear_worst = std::max(linear_worst, std::abs(linear.rear_axle_side_slip_rad() - truth));
      }
      for (int j = 0; j < 20; ++j)
        x = vehicle_rk4_step(model, x, delta, 1e-3);  // held over the period
    }
    EXPECT_LE(magic_worst, 0.10 * largest + 0.002)
        << "v " << speed << " peak a_y " << peak_acceleration << " largest slip " << largest
        << " (linear filter: " << linear_worst << "); " << seed_message(seed);
    magic_total += magic_worst;
    linear_total += linear_worst;
  }
  EXPECT_LE(magic_total, 0.25 * linear_total)
      << "sum of worst errors over " << cases << " cases: magic_formula " << magic_total
      << " rad, linear " << linear_total << " rad";
}

TEST(SideSlipObserver, MagicFormulaParametersAreNamed) {
  SideSlipObserverParameters observer = SideSlipObserverParameters::from_vehicle(
      VehicleParameters{}, 1.0, 1.0, ObserverTireModel::magic_formula);
  EXPECT_TRUE(observer.is_valid()) << observer.validation_error();
  observer.rear_tire.shape_factor_c = 2.5;
  EXPECT_NE(observer.validation_error().find("rear_tire.shape_factor_c = 2.5"), std::string::npos)
      << observer.validation_error();
  EXPECT_THROW(SideSlipObserver{observer}, std::invalid_argument);
  observer = {};
  observer.front_tire.friction_mu = std::nan("");
  EXPECT_NE(observer.validation_error().find("front_tire.friction_mu"), std::string::npos);
  observer = {};
  observer.tire_model = static_cast<ObserverTireModel>(5);
  EXPECT_NE(observer.validation_error().find("tire_model"), std::string::npos);
  observer = {};
  observer.gravity_mps2 = 0.0;
  EXPECT_NE(observer.validation_error().find("gravity_mps2"), std::string::npos);
  SimulationParameters sim;
  sim.side_slip.tire_model = static_cast<ObserverTireModel>(-1);
  EXPECT_NE(sim.validation_error().find("side_slip.tire_model"), std::string::npos);
}

}  // namespace
}  // namespace smoothsteer
