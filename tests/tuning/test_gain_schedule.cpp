// The velocity-dependent optimal parameters (paper Sec. III, O1-O4, regions 1-4): limits hold at
// every grid speed (exact worst case), relaxing a limit never lowers kbar_l, infeasible limits
// name the speed and the binding limit, and the online interpolation is continuous.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "smoothsteer/tuning/gain_schedule.hpp"
#include "smoothsteer/tuning/worst_case.hpp"
#include "support/property.hpp"
#include "support/shared_static_map.hpp"

namespace smoothsteer {
namespace {

//! The paper's route (Certificate::box); the feedforward route has its own tests.
TuningOptions box_route() {
  TuningOptions options;
  options.certificate = Certificate::box;
  return options;
}

using namespace smoothsteer::testing;

VehicleLimits random_vehicle(Random& random) {
  VehicleLimits v;
  v.wheelbase_m = random.uniform(2.0, 3.5);
  v.max_steering_angle_rad = random.uniform(0.4, 1.1);
  v.max_steering_rate_radps = random.uniform(0.3, 1.0);
  v.max_steering_acceleration_radps2 = random.uniform(3.0, 12.0);
  return v;
}

std::string describe(const VehicleLimits& v) {
  std::ostringstream text;
  text << "lambda_veh=" << v.wheelbase_m << " angle=" << v.max_steering_angle_rad
       << " rate=" << v.max_steering_rate_radps << " acc=" << v.max_steering_acceleration_radps2;
  return text.str();
}

TEST(GainSchedule, LimitsHoldAtEveryGridSpeed) {
  int feasible = 0;
  const int cases = property_cases(6);
  for (int k = 0; k < cases; ++k) {
    Random random(case_seed(k) + 21);
    const VehicleLimits vehicle = random_vehicle(random);
    TuningOptions options;
    options.certificate = Certificate::box;  // the paper's route
    options.max_longitudinal_acceleration_mps2 = random.uniform(0.0, 3.0);
    SCOPED_TRACE(seed_message(case_seed(k)) + " " + describe(vehicle) +
                 " dv/dt=" + std::to_string(options.max_longitudinal_acceleration_mps2));
    GainSchedule schedule;
    try {
      schedule = compute_gain_schedule(vehicle, options, speed_grid(1.0, 30.0, 1.0), shared_map());
    } catch (const InfeasibleLimits& error) {
      // Tight random limits can be infeasible at 30 m/s: that is a valid answer if it says so.
      EXPECT_GT(error.speed_mps(), 0.0);
      EXPECT_NE(std::string(error.what()).find(error.binding_limit()), std::string::npos);
      continue;
    }
    ++feasible;
    ASSERT_EQ(schedule.entries().size(), 30u);
    for (const ScheduleEntry& e : schedule.entries()) {
      SCOPED_TRACE("v=" + std::to_string(e.speed_mps));
      // Recompute the exact worst case independently of the stored figures.
      const ControllerParameters p = schedule.parameters_at(e.speed_mps);
      ASSERT_TRUE(p.is_valid()) << p.validation_error();
      const SteeringDerivatives worst = worst_case_steering_derivatives(p);
      const double v = e.speed_mps, a = options.max_longitudinal_acceleration_mps2;
      EXPECT_LE(compute_chain_bounds(p).steering_angle_rad,
                vehicle.max_steering_angle_rad * (1 + 1e-9));
      EXPECT_LE(v * worst.rate_per_meter, vehicle.max_steering_rate_radps * (1 + 1e-9));
      EXPECT_LE(v * v * worst.acceleration_per_meter2 + a * worst.rate_per_meter,
                vehicle.max_steering_acceleration_radps2 * (1 + 1e-9));
      EXPECT_GE(e.lead_curvature_bound, options.min_lead_curvature_bound);
      EXPECT_NEAR(
          e.fictive_wheelbase_m * e.fictive_wheelbase_m + e.lead_wheelbase_m * e.lead_wheelbase_m,
          vehicle.wheelbase_m * vehicle.wheelbase_m, 1e-9);  // eq. cornering_constr
    }
  }
  EXPECT_GE(feasible, (cases + 1) / 2) << "most random vehicles should be feasible";
}

TEST(GainSchedule, RelaxingALimitNeverLowersTheLeadCurvature) {
  for (int k = 0; k < property_cases(6); ++k) {
    Random random(case_seed(k) + 22);
    const VehicleLimits vehicle = random_vehicle(random);
    VehicleLimits relaxed = vehicle;
    const int which = random.integer(0, 2);
    const double factor = random.uniform(1.05, 2.0);
    if (which == 0)
      relaxed.max_steering_angle_rad = std::min(1.4, vehicle.max_steering_angle_rad * factor);
    if (which == 1) relaxed.max_steering_rate_radps *= factor;
    if (which == 2) relaxed.max_steering_acceleration_radps2 *= factor;
    SCOPED_TRACE(seed_message(case_seed(k)) + " " + describe(vehicle) + " relaxed " +
                 describe(relaxed));
    const std::vector<double> speeds = speed_grid(1.0, 30.0, 2.0);
    const GainSchedule a = compute_gain_schedule(vehicle, box_route(), speeds, shared_map());
    const GainSchedule b = compute_gain_schedule(relaxed, box_route(), speeds, shared_map());
    for (std::size_t i = 0; i < speeds.size(); ++i) {
      EXPECT_GE(b.entries()[i].lead_curvature_bound,
                a.entries()[i].lead_curvature_bound * (1.0 - 1e-6))
          << "v=" << speeds[i];
    }
  }
}

TEST(GainSchedule, RegionsOfTheExampleVehicle) {
  // CommonRoad vehicle 2 with a steering-acceleration limit: region 1 at walking pace, then
  // regions 2-3 and region 4 at speed; kbar_l never grows with v, and in region 4 lambda_l sits
  // at the minimum of delta''.
  VehicleLimits vehicle;
  vehicle.max_steering_acceleration_radps2 = 5.0;
  const GainSchedule s =
      compute_gain_schedule(vehicle, box_route(), speed_grid(0.05, 30.0, 0.05), shared_map());
  bool seen[6] = {};
  for (std::size_t i = 0; i < s.entries().size(); ++i) {
    const ScheduleEntry& e = s.entries()[i];
    seen[static_cast<int>(e.region)] = true;
    if (i > 0) {
      EXPECT_LE(e.lead_curvature_bound, s.entries()[i - 1].lead_curvature_bound * (1 + 1e-9));
    }
    if (e.region == VelocityRegion::region1) {
      EXPECT_NEAR(e.lead_curvature_bound,
                  std::sin(vehicle.max_steering_angle_rad) / vehicle.wheelbase_m, 1e-12);
      EXPECT_NEAR(e.lead_wheelbase_m, shared_map().ratio_at(0) * vehicle.wheelbase_m, 1e-12);
    }
  }
  EXPECT_TRUE(seen[1] && seen[3] && seen[4]);
  EXPECT_EQ(s.entries().back().region, VelocityRegion::region4);
}

TEST(GainSchedule, FirstOrderUsesAngleAndRateOnly) {
  VehicleLimits vehicle;  // acceleration limit +inf
  TuningOptions options;
  options.certificate = Certificate::box;  // the paper's route
  options.order = 1;
  const GainSchedule s =
      compute_gain_schedule(vehicle, options, speed_grid(0.1, 30, 0.1), shared_map());
  for (const ScheduleEntry& e : s.entries()) {
    const double kbar0 = std::min(std::tan(vehicle.max_steering_angle_rad) / vehicle.wheelbase_m,
                                  vehicle.max_steering_rate_radps / (2.0 * e.speed_mps));
    EXPECT_NEAR(e.lead_curvature_bound,
                kbar0 / std::sqrt(1 + kbar0 * kbar0 * vehicle.wheelbase_m * vehicle.wheelbase_m),
                1e-9 * kbar0);
    EXPECT_LE(e.max_steering_rate_radps, vehicle.max_steering_rate_radps * (1 + 1e-9));
  }
  vehicle.max_steering_acceleration_radps2 = 1.0;
  EXPECT_THROW(compute_gain_schedule(vehicle, options, {1.0}, shared_map()), std::invalid_argument);
}

TEST(GainSchedule, InfeasibleLimitNamesSpeedAndLimit) {
  VehicleLimits vehicle;
  vehicle.max_steering_acceleration_radps2 = 1.0;
  try {
    compute_gain_schedule(vehicle, box_route(), speed_grid(1.0, 30.0, 0.5), shared_map());
    FAIL() << "expected InfeasibleLimits";
  } catch (const InfeasibleLimits& error) {
    const std::string text = error.what();
    EXPECT_EQ(error.binding_limit(), "steering acceleration") << text;
    EXPECT_GT(error.speed_mps(), 1.0);
    EXPECT_NE(text.find("v = " + std::to_string(static_cast<int>(error.speed_mps()))),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("steering acceleration limit (1 rad/s^2)"), std::string::npos) << text;
    // The previous grid speed is feasible: the message names the FIRST infeasible speed.
    EXPECT_NO_THROW(
        compute_gain_schedule(vehicle, box_route(), {error.speed_mps() - 0.5}, shared_map()));
  }
  TuningOptions options;
  options.certificate = Certificate::box;  // the paper's route
  options.path_curvature_bound = 0.5;      // k_rob would need kbar_l > 0.53 1/m
  try {
    compute_gain_schedule(VehicleLimits{}, options, {5.0}, shared_map());
    FAIL() << "expected InfeasibleLimits";
  } catch (const InfeasibleLimits& error) {
    EXPECT_EQ(error.binding_limit(), "steering angle") << error.what();
  }
}

TEST(GainSchedule, BadInputsAreRejectedWithTheirName) {
  auto message = [](auto&& call) {
    try {
      call();
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  VehicleLimits bad;
  bad.max_steering_rate_radps = -1.0;
  EXPECT_NE(message([&] {
              compute_gain_schedule(bad, box_route(), {1.0}, shared_map());
            }).find("max_steering_rate_radps = -1"),
            std::string::npos);
  bad = {};
  bad.max_steering_angle_rad = std::nan("");
  EXPECT_NE(message([&] {
              compute_gain_schedule(bad, box_route(), {1.0}, shared_map());
            }).find("max_steering_angle_rad"),
            std::string::npos);
  EXPECT_NE(message([&] {
              compute_gain_schedule({}, box_route(), {2.0, 1.0}, shared_map());
            }).find("speeds_mps[1] = 1"),
            std::string::npos);
  TuningOptions three;
  three.certificate = Certificate::box;
  three.order = 3;
  EXPECT_NE(
      message([&] { compute_gain_schedule({}, three, {1.0}, shared_map()); }).find("order = 3"),
      std::string::npos);
  EXPECT_THROW(speed_grid(0.0, 30.0, 0.5), std::invalid_argument);
  EXPECT_THROW(speed_grid(1.0, 30.0, -0.5), std::invalid_argument);
}

TEST(GainSchedule, InterpolationIsContinuousAndConservative) {
  VehicleLimits vehicle;
  vehicle.max_steering_acceleration_radps2 = 5.0;
  const GainSchedule s =
      compute_gain_schedule(vehicle, box_route(), speed_grid(1.0, 30.0, 0.5), shared_map());
  ControllerParameters previous = s.parameters_at(0.0);
  for (double v = 0.0; v <= 30.0; v += 0.001) {
    const ControllerParameters p = s.parameters_at(v);
    ASSERT_TRUE(p.is_valid()) << "v=" << v;
    const double jump =
        std::abs(p.chain.lead_curvature_bound - previous.chain.lead_curvature_bound) +
        std::abs(p.chain.wheelbases_m[1] - previous.chain.wheelbases_m[1]);
    ASSERT_LT(jump, 0.01) << "v=" << v;
    previous = p;
  }
  // Blends between grid speeds keep the limits (checked on a fine grid of speeds).
  for (double v = 1.0; v <= 30.0; v += 0.1) {
    const ControllerParameters p = s.parameters_at(v);
    const SteeringDerivatives worst = worst_case_steering_derivatives(p);
    EXPECT_LE(v * worst.rate_per_meter, vehicle.max_steering_rate_radps * (1 + 1e-9)) << v;
    EXPECT_LE(v * v * worst.acceleration_per_meter2,
              vehicle.max_steering_acceleration_radps2 * (1 + 1e-9))
        << v;
  }
}

TEST(ControllerParameters, IsValidAgreesWithValidationError) {
  for (int k = 0; k < property_cases(400); ++k) {
    Random random(case_seed(k) + 23);
    ControllerParameters p;
    p.chain.order = random.integer(-1, 9);
    p.chain.vehicle_wheelbase_m = random.coin() ? random.uniform(-1.0, 4.0) : 2.7;
    for (double& l : p.chain.wheelbases_m) l = random.uniform(-0.5, 4.0);
    p.chain.lead_curvature_bound = random.uniform(-0.1, 1.5);
    p.law.k_rob = random.uniform(-0.2, 1.2);
    if (random.integer(0, 9) == 0) p.law.approach_angle_rad = random.uniform(-1.0, 2.0);
    if (random.integer(0, 9) == 0) p.chain.lead_curvature_bound = std::nan("");
    EXPECT_EQ(p.is_valid(), p.validation_error().empty())
        << seed_message(case_seed(k)) << " " << p.validation_error();
  }
}

}  // namespace
}  // namespace smoothsteer
