// set_path() on every comparison controller: after 5 s on one straight line, the path is replaced
// by a parallel line 1 m to the left; each controller must return ok and reach the new line.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "smoothsteer/baselines/geometric_controllers.hpp"
#include "smoothsteer/baselines/hosm_controller.hpp"
#include "smoothsteer/baselines/lqr_controller.hpp"
#include "smoothsteer/baselines/mpc_controller.hpp"
#include "smoothsteer/baselines/newton_raphson_controller.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

namespace smoothsteer {
namespace {

TEST(SetPathBaselines, EveryComparisonControllerReachesTheReplacedPath) {
  const auto first = std::make_shared<const Path>(Path::straight_line({-50.0, 0.0}, 0.0, 1000.0));
  const auto second = std::make_shared<const Path>(Path::straight_line({-50.0, 1.0}, 0.0, 1000.0));
  MpcParameters constrained;
  constrained.solver = MpcSolver::constrained;
  std::vector<std::unique_ptr<SteeringController>> controllers;
  controllers.push_back(std::make_unique<StanleyController>(StanleyParameters{}, first));
  controllers.push_back(std::make_unique<PurePursuitController>(PurePursuitParameters{}, first));
  controllers.push_back(std::make_unique<LqrController>(LqrParameters{}, first));
  controllers.push_back(std::make_unique<HosmController>(HosmParameters{}, first));
  controllers.push_back(
      std::make_unique<NewtonRaphsonController>(NewtonRaphsonParameters{}, first));
  controllers.push_back(std::make_unique<MpcController>(MpcParameters{}, first));
  controllers.push_back(std::make_unique<MpcController>(constrained, first));
  const KinematicSingleTrack model{2.7};
  for (auto& controller : controllers) {
    const std::string name = controller->name();
    Pose2 pose{{0.0, 0.0}, 0.0};
    ControllerOutput output;
    for (int k = 0; k < 1000; ++k) {  // 20 s at 50 Hz and 10 m/s
      if (k == 250) {
        ASSERT_EQ(controller->set_path(second), Status::ok) << name;
      }
      ASSERT_EQ(controller->update({pose.position, pose.heading_rad, 10.0, 0.0, 0.02}, output),
                Status::ok)
          << name << " step " << k;
      pose = model.step(pose, output.steering_angle_rad, 10.0, 0.02);
    }
    EXPECT_NEAR(pose.position.y, 1.0, 0.05) << name;
    EXPECT_NEAR(output.diagnostics.lateral_error_m, 0.0, 0.05) << name;
    EXPECT_EQ(controller->set_path(nullptr), Status::invalid_input) << name;
  }
}

}  // namespace
}  // namespace smoothsteer
