// The unconstrained MPC's update() performs no heap allocation (everything is allocated at
// construction): a counting global operator new observes every allocation of this binary.
// The constrained variant is not claimed allocation-free: ALGLIB's C core allocates its work
// arrays with malloc (ae_malloc), which this operator-new counter does not see. The binary's one
// counter also checks the second-order limiter that wraps every comparison controller.

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "smoothsteer/baselines/mpc_controller.hpp"
#include "smoothsteer/baselines/steering_limits.hpp"
#include "support/counting_allocator.hpp"

namespace smoothsteer {
namespace {

long allocations_in_updates(MpcSolver solver) {
  std::vector<Vec2> waypoints;
  for (int k = 0; k < 500; ++k) waypoints.push_back({k * 1.0, 10.0 * std::sin(k * 0.02)});
  auto path = std::make_shared<const Path>(Path::from_waypoints(waypoints));
  MpcParameters parameters;
  parameters.solver = solver;
  parameters.weight_steering_rate = 0.01;
  MpcController controller(parameters, path);
  ControllerOutput output;
  Vec2 position{5.0, 3.0};
  double heading = 0.1;
  const long before = allocation_count.load();
  for (int k = 0; k < 300; ++k) {
    const double speed = k < 250 ? 10.0 : 0.0;  // includes the held command at standstill
    controller.update({position, heading, speed, 0.0, 0.02}, output);
    position = position + 0.2 * unit_from_heading(heading);
    heading += 0.2 * std::tan(output.steering_angle_rad) / parameters.wheelbase_m;
  }
  controller.update({{NAN, 0.0}, 0.0, 10.0, 0.0, 0.02}, output);  // invalid input
  controller.reset(0.1);
  return allocation_count.load() - before;
}

TEST(MpcRealTime, UnconstrainedUpdateDoesNotAllocate) {
  EXPECT_EQ(allocations_in_updates(MpcSolver::unconstrained), 0);
}

TEST(MpcRealTime, ConstrainedUpdateMakesNoOperatorNewAllocation) {
  // Only operator new is counted; ALGLIB's malloc calls are outside this check.
  EXPECT_EQ(allocations_in_updates(MpcSolver::constrained), 0);
}

TEST(SecondOrderLimiterRealTime, ApplyAndResetDoNotAllocate) {
  SteeringSaturator saturator({1.066, 0.4, 8.0});
  const long before = allocation_count.load();
  double rate = 0.0;
  for (int k = 0; k < 1000; ++k) {
    const double raw = k % 97 == 0 ? NAN : std::sin(0.05 * k) * (k % 200 < 100 ? 0.1 : 3.0);
    saturator.apply(raw, k % 3 == 0 ? 0.01 : 0.013, rate);
  }
  saturator.reset(0.2, 0.3);
  EXPECT_EQ(allocation_count.load() - before, 0);
}

}  // namespace
}  // namespace smoothsteer
