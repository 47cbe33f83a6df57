// One validation shape for the comparison controllers' parameters and the controller's
// own structs: is_valid() noexcept, validation_error() and validate() agree on one message
// "<Struct>: <field> = <exact value> <rule>".

#include <gtest/gtest.h>

#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/baselines/hosm_controller.hpp"
#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/controller/cusp_sequencer.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "support/validation_shape.hpp"

namespace smoothsteer {
namespace {

using testing::expect_shape;

TEST(ValidationShape, ComparisonControllersParameters) {
  StanleyParameters stanley;
  stanley.gain_per_s = -1.5;
  expect_shape(StanleyParameters{}, stanley,
               "StanleyParameters: gain_per_s = -1.5 must be finite and > 0");
  PurePursuitParameters pursuit;
  pursuit.max_lookahead_m = 2.5;
  expect_shape(PurePursuitParameters{}, pursuit,
               "PurePursuitParameters: max_lookahead_m = 2.5 must be finite and >= "
               "min_lookahead_m");
  LqrParameters lqr;
  lqr.weight_lateral = 0.0200001;
  lqr.weight_lateral = -lqr.weight_lateral;
  expect_shape(LqrParameters{}, lqr,
               "LqrParameters: weight_lateral = -0.0200001 must be finite and > 0 (else e is not "
               "stabilised)");
  NewtonRaphsonParameters newton;
  newton.limits.rate_radps = 0.0;
  expect_shape(NewtonRaphsonParameters{}, newton,
               "SteeringLimits: rate_radps = 0 must be finite and > 0");
  MpcParameters mpc;
  mpc.horizon_steps = 1;
  expect_shape(MpcParameters{}, mpc, "MpcParameters: horizon_steps = 1 must be in [2, 200]");
  HosmParameters hosm;
  hosm.substep_m = 0.0;
  expect_shape(HosmParameters{}, hosm, "HosmParameters: substep_m = 0 must be finite and > 0");
  SteeringLimits limits;
  limits.angle_rad = 2.0;
  expect_shape(SteeringLimits{}, limits, "SteeringLimits: angle_rad = 2 must be in (0, pi/2)");

  ComparisonSetup setup;
  setup.path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 10.0));
  ComparisonSetup bad = setup;
  bad.wheelbase_m = 1e308;
  expect_shape(setup, bad, "ComparisonSetup: wheelbase_m = 1e+308 must be in (0, 1000]");
  ComparisonSetup no_path;
  EXPECT_FALSE(no_path.is_valid());
  EXPECT_EQ(no_path.validation_error(), "ComparisonSetup: path is null; a path is required");
}

TEST(ValidationShape, ControllerStructs) {
  ControllerParameters parameters;
  parameters.law.k_rob = 1.5;
  expect_shape(ControllerParameters{}, parameters,
               "ControllerParameters: k_rob = 1.5 must be in [0, 1) (eq. sigma divides by 1 - "
               "k_rob)");
  CuspSpeedOptions cusp;
  cusp.deceleration_mps2 = -2.0;
  expect_shape(CuspSpeedOptions{}, cusp,
               "CuspSpeedOptions: deceleration_mps2 = -2 must be finite and > 0");
}

}  // namespace
}  // namespace smoothsteer
