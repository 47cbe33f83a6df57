// update() performs no heap allocation: a counting global operator new observes every
// allocation made by this test binary.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "support/counting_allocator.hpp"

namespace smoothsteer {
namespace {

TEST(RealTime, UpdateDoesNotAllocate) {
  std::vector<Vec2> waypoints;
  for (int k = 0; k < 2000; ++k) waypoints.push_back({k * 1.0, 10.0 * std::sin(k * 0.01)});
  auto path = std::make_shared<const Path>(Path::from_waypoints(waypoints));
  for (int order = 0; order <= 4; ++order) {
    ControllerParameters parameters;
    parameters.chain.order = order;
    parameters.chain.lead_curvature_bound = 0.05;
    // Odd orders cover the delay prediction.
    parameters.delay_compensation = {.enabled = order % 2 == 1,
                                     .actuator_delay_s = order % 2 == 1 ? 0.3 : 0.0};
    if (order % 2 == 0) parameters.feedforward.curvature_rate = 0.01;  // and the preview
    if (order == 1 || order == 2) {                                    // and the steering governor
      parameters.governor.enabled = true;
      parameters.governor.max_steering_rate_radps = 0.4;
      parameters.governor.max_steering_acceleration_radps2 = 8.0;
      parameters.governor.fixed_law_length = true;
      parameters.governor.law_length_m = 4.0;
    }
    LeadWheelController controller(parameters, path);
    ControllerOutput output;
    Vec2 position{5.0, 30.0};
    ControllerParameters retuned = parameters, invalid = parameters;
    invalid.law.k_rob = 2.0;
    const long before = allocation_count.load();
    for (int k = 0; k < 5000; ++k) {
      // retune() (gain schedules) is a real-time call too, valid or not.
      retuned.chain.lead_curvature_bound =
          parameters.chain.lead_curvature_bound * (1.0 - 0.5 * (k % 7) / 7.0);
      controller.retune(retuned);
      controller.retune(invalid);
      // Includes far-away global searches, warm starts, reversing and invalid input.
      const double speed = k < 4000 ? 10.0 : -3.0;
      controller.update({position, 0.0, speed, 0.0, 0.02}, output);
      controller.update({{position.x, std::nan("")}, 0.0, speed, 0.0, 0.02}, output);
      position.x += 0.2;
      position.y *= 0.999;
    }
    EXPECT_EQ(allocation_count.load() - before, 0) << "order " << order;
  }
}

// The planned jumps (jump_plan.hpp) keep their plans and the lag simulation on the stack, also
// with more jumps within reach than max_planned_jumps.
TEST(RealTime, PlannedJumpsUpdateDoesNotAllocate) {
  PathBuilder builder({0.0, 0.0}, 0.0);
  builder.line(20.0);
  // Arcs meeting with curvature jumps, and clothoids between some of them: planned jumps and
  // planned kinks (jump_plan.hpp) within reach at once.
  for (int k = 0; k < 60; ++k) {
    builder.arc(k % 3 == 0 ? 40.0 : 25.0, k % 2 == 0 ? 0.05 : -0.05);
    if (k % 4 == 1) builder.clothoid(4.0, 0.0);
  }
  builder.line(50.0);
  auto path = std::make_shared<const Path>(builder.build());
  ASSERT_GT(path->curvature_jumps().size(), 40u);
  ASSERT_GT(path->curvature_kinks().size(), 20u);
  for (int order = 1; order <= 2; ++order) {
    ControllerParameters parameters;
    parameters.chain.order = order;
    parameters.chain.lead_curvature_bound = 0.08;
    parameters.feedforward.share = 0.8;
    parameters.feedforward.curvature_rate = 0.02;
    parameters.feedforward.cornering_target = CorneringTarget::rear_axle_exact;
    parameters.feedforward.curvature_preview = CurvaturePreview::planned_jumps;
    LeadWheelController controller(parameters, path);
    ControllerOutput output;
    Vec2 position{0.0, 1.0};
    const long before = allocation_count.load();
    for (int k = 0; k < 2000; ++k) {
      controller.update({position, 0.0, 8.0, 0.0, 0.02}, output);
      position.x += 0.1;
    }
    EXPECT_EQ(allocation_count.load() - before, 0) << "order " << order;
  }
}

// Replanning: set_path() swaps a path built outside the measured section (the planner's job)
// and re-seeds the hints, without allocating; update() on the new path does not either.
TEST(RealTime, SetPathDoesNotAllocate) {
  std::vector<std::shared_ptr<const Path>> plans;
  for (int plan = 0; plan < 20; ++plan) {
    std::vector<Vec2> waypoints;
    for (int k = 0; k < 300; ++k) {
      const double x = 0.9 * k + 0.1 * plan;
      waypoints.push_back({x, 10.0 * std::sin(x * 0.01) + 0.05 * plan});
    }
    plans.push_back(std::make_shared<const Path>(Path::from_waypoints(waypoints)));
  }
  LeadWheelController controller(ControllerParameters{}, plans.front());
  ControllerOutput output;
  Vec2 position{0.0, 1.0};
  const long before = allocation_count.load();
  for (int k = 0; k < 2000; ++k) {
    if (k % 5 == 0) controller.set_path(plans[static_cast<std::size_t>(k / 5) % plans.size()]);
    controller.update({position, 0.0, 10.0, 0.0, 0.02}, output);
    position.x += 0.1;
  }
  EXPECT_EQ(allocation_count.load() - before, 0);
}

}  // namespace
}  // namespace smoothsteer
