// The baselines' gains are controller keys of scenario files (docs/scenarios.md): they reach
// the controller, and a bad value gets an error that names the file and the key.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <memory>
#include <string>

#include "smoothsteer/baselines/geometric_controllers.hpp"
#include "smoothsteer/baselines/mpc_controller.hpp"
#include "smoothsteer/evaluation/controller_registration.hpp"
#include "smoothsteer/runner/controller_registry.hpp"

namespace smoothsteer {
namespace {

std::unique_ptr<SteeringController> build(const std::string& yaml) {
  register_comparison_controllers();
  auto path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 100.0));
  return runner::make_controller(YAML::Load(yaml), "controller", "scenario.yaml",
                                 {path, VehicleParameters{}, ActuatorParameters{}});
}

std::string error_of(const std::string& yaml) {
  try {
    build(yaml);
  } catch (const io::ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(BaselineRegistration, GainsReachTheController) {
  auto controller = build("{type: mpc, horizon_steps: 7, weight_lateral_error: 0.5}");
  auto* saturated = dynamic_cast<SaturatedController*>(controller.get());
  ASSERT_NE(saturated, nullptr);
  auto* mpc = dynamic_cast<MpcController*>(&saturated->inner());
  ASSERT_NE(mpc, nullptr);
  EXPECT_EQ(mpc->parameters().horizon_steps, 7);
  EXPECT_DOUBLE_EQ(mpc->parameters().weight_lateral_error, 0.5);
  EXPECT_EQ(mpc->parameters().solver, MpcSolver::unconstrained);
  EXPECT_NE(build("{type: stanley, gain_per_s: 5}"), nullptr);
  EXPECT_NE(build("{type: pure_pursuit, min_lookahead_m: 4, lookahead_time_s: 1}"), nullptr);
  EXPECT_NE(build("{type: lqr, weight_lateral: 2, curvature_feedforward: false}"), nullptr);
  EXPECT_NE(build("{type: newton_raphson, horizon_s: 0.8, gain_per_s: 3}"), nullptr);
  EXPECT_NE(build("{type: mpc_constrained, prediction_step_s: 0.05}"), nullptr);
}

TEST(BaselineRegistration, BadValuesNameTheFileAndTheKey) {
  const std::string stanley = error_of("{type: stanley, gain_per_s: -1}");
  EXPECT_NE(stanley.find("scenario.yaml: key 'controller.gain_per_s'"), std::string::npos)
      << stanley;
  const std::string mpc = error_of("{type: mpc, horizon_steps: 1}");
  EXPECT_NE(mpc.find("'controller.horizon_steps'"), std::string::npos) << mpc;
  // Cross-field rules come from validate(), which names the field (= the key).
  const std::string pure_pursuit =
      error_of("{type: pure_pursuit, min_lookahead_m: 10, max_lookahead_m: 5}");
  EXPECT_NE(pure_pursuit.find("scenario.yaml: key 'controller'"), std::string::npos)
      << pure_pursuit;
  EXPECT_NE(pure_pursuit.find("max_lookahead_m"), std::string::npos) << pure_pursuit;
  const std::string unknown = error_of("{type: lqr, gain_per_s: 1}");
  EXPECT_NE(unknown.find("gain_per_s"), std::string::npos) << unknown;
}

TEST(BaselineRegistration, LimitsAreTheVehiclesUnlessTheSectionSetsThem) {
  // VehicleParameters{} has no acceleration limit: none unless the key sets one.
  auto plain = build("{type: stanley}");
  auto* saturated = dynamic_cast<SaturatedController*>(plain.get());
  ASSERT_NE(saturated, nullptr);
  EXPECT_EQ(saturated->limits().angle_rad, VehicleParameters{}.max_steering_angle_rad);
  EXPECT_EQ(saturated->limits().rate_radps, VehicleParameters{}.max_steering_rate_radps);
  EXPECT_TRUE(std::isinf(saturated->limits().acceleration_radps2));
  auto limited = build("{type: pure_pursuit, max_steering_acceleration_radps2: 8}");
  saturated = dynamic_cast<SaturatedController*>(limited.get());
  ASSERT_NE(saturated, nullptr);
  EXPECT_EQ(saturated->limits().acceleration_radps2, 8.0);
  const std::string bad = error_of("{type: lqr, max_steering_acceleration_radps2: 0}");
  EXPECT_NE(bad.find("scenario.yaml: key 'controller.max_steering_acceleration_radps2'"),
            std::string::npos)
      << bad;
}

}  // namespace
}  // namespace smoothsteer
