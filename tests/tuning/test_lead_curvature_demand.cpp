// lead_curvature_rate_demand (path_demand.hpp): the lead wheel's curvature rate on a reference
// path, which sizes the feedforward's rate limit L_ff, and the tuner's use of it.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "smoothsteer/controller/feedforward.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/tuning/gain_schedule.hpp"
#include "smoothsteer/tuning/path_demand.hpp"
#include "smoothsteer/tuning/vehicle_limits.hpp"

namespace smoothsteer {
namespace {

TEST(LeadCurvatureRateDemand, IsZeroOnACircleAndShowsAJump) {
  const double lambda[2] = {2.5, 0.4};
  const Path circle = Path::circle({0.0, 0.0}, 30.0, true, 0.0);
  EXPECT_LT(lead_curvature_rate_demand(circle, lambda, 2), 1e-9);
  // A line joined to a circle: a jump, which the demand shows as jump / step and more.
  const auto jump = PathBuilder({0.0, 0.0}, 0.0).line(20.0).arc(30.0, 1.0).build();
  EXPECT_GT(lead_curvature_rate_demand(jump, lambda, 2), (1.0 / 30.0) / curvature_jet_step_m);
}

TEST(LeadCurvatureRateDemand, TheTunerCoversItWhereTheBudgetAllows) {
  std::vector<Vec2> points;
  for (int i = 0; i <= 200; ++i) points.push_back({i * 1.0, 3.0 * std::sin(0.05 * i)});
  auto path = std::make_shared<const Path>(Path::from_waypoints(points));
  VehicleLimits car;  // defaults: the shipped passenger car, 0.4 rad/s
  car.max_steering_acceleration_radps2 = 8.0;
  TuningOptions bounds_only;
  bounds_only.path_curvature_bound = path->max_abs_curvature();
  bounds_only.path_curvature_rate_bound = path_demand(*path).max_curvature_rate;
  TuningOptions with_path;
  apply_path_demand(with_path, path);
  ASSERT_EQ(with_path.reference_path, path);
  EXPECT_DOUBLE_EQ(with_path.path_curvature_rate_bound, bounds_only.path_curvature_rate_bound);
  const GainSchedule a = compute_feedforward_schedule(car, bounds_only, {3.0});
  const GainSchedule b = compute_feedforward_schedule(car, with_path, {3.0});
  const ScheduleEntry& e = b.entries().front();
  // At 3 m/s the rate budget is ample: L_ff covers the lead wheel's demand with its margin.
  const ControllerParameters p = b.parameters_at(3.0);
  const double demand =
      lead_curvature_rate_demand(*path, p.chain.wheelbases_m.data(), p.chain.order);
  EXPECT_GT(demand, bounds_only.path_curvature_rate_bound);
  EXPECT_NEAR(e.feedforward_curvature_rate, with_path.feedforward_rate_margin * demand,
              1e-9 + 0.2 * demand);
  EXPECT_GT(e.feedforward_curvature_rate, a.entries().front().feedforward_curvature_rate);
}

}  // namespace
}  // namespace smoothsteer
