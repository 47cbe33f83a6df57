// No controller's update() returns ok with a non-finite value. Inputs whose
// magnitude breaks the arithmetic (|x| or |y| >= 1e155 gave -inf lateral errors with ok, LQR at
// v = 1e308 NaN diagnostics) are refused with invalid_input and leave the output unchanged; a
// non-finite result of the controller's own step becomes numerical_error. Seeded: every case
// prints its seed, controller, field and value.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>

#include "smoothsteer/baselines/comparison_controllers.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

ComparisonSetup setup_on(std::shared_ptr<const Path> path) {
  ComparisonSetup setup;
  setup.path = std::move(path);
  setup.limits = {0.5, 0.6};
  return setup;
}

std::shared_ptr<const Path> random_path(testing::Random& random) {
  if (random.coin()) {
    return std::make_shared<const Path>(Path::straight_line({-50.0, 0.0}, 0.0, 2000.0));
  }
  return std::make_shared<const Path>(Path::circle({0.0, 0.0}, random.uniform(20.0, 200.0)));
}

//! Sets field `index` (0..5: x, y, heading, speed, acceleration, period) of `input` to `value`.
const std::array<const char*, 6> field_names{"x",     "y", "heading", "speed", "acceleration",
                                             "period"};
void set_field(ControllerInput& input, int index, double value) {
  double* fields[] = {&input.rear_axle_position.x, &input.rear_axle_position.y,
                      &input.heading_rad,          &input.speed_mps,
                      &input.acceleration_mps2,    &input.period_s};
  *fields[index] = value;
}

//! Values that no controller can use: non-finite, or beyond ControllerInputRange.
double hostile_value(testing::Random& random, int field) {
  using R = ControllerInputRange;
  const std::array<double, 6> bound{R::max_abs_coordinate_m,      R::max_abs_coordinate_m,
                                    R::max_abs_heading_rad,       R::max_abs_speed_mps,
                                    R::max_abs_acceleration_mps2, R::max_period_s};
  const double sign = field == 5 || random.coin() ? 1.0 : -1.0;
  switch (random.integer(0, 4)) {
    case 0:
      return nan;
    case 1:
      return sign * inf;
    case 2:
      return sign * 1e155;
    case 3:
      return sign * 1e308;
    default:
      return sign * bound[static_cast<std::size_t>(field)] * random.uniform(1.0 + 1e-12, 1e3);
  }
}

//! Values at the edge of the accepted range: the controller may refuse them, but an ok must come
//! with a finite output.
double extreme_value(testing::Random& random, int field) {
  using R = ControllerInputRange;
  const double sign = field == 5 || random.coin() ? 1.0 : -1.0;
  switch (field) {
    case 0:
    case 1:
      return sign * R::max_abs_coordinate_m * random.uniform(0.5, 1.0);
    case 2:
      return sign * R::max_abs_heading_rad * random.uniform(0.5, 1.0);
    case 3:
      return sign * R::max_abs_speed_mps * random.uniform(0.5, 1.0);
    case 4:
      return sign * R::max_abs_acceleration_mps2 * random.uniform(0.5, 1.0);
    default:
      return random.coin() ? 1e-300 * random.uniform(1.0, 2.0) : R::max_period_s;
  }
}

class EveryControllerUnderHostileInput : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryControllerUnderHostileInput, NeverReturnsOkWithNonFiniteValues) {
  // The constrained MPC solves a QP per update: its count is capped.
  const int requested = testing::property_cases(40);
  const int cases = GetParam() == "mpc_constrained" ? std::min(requested, 20) : requested;
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed);
    auto controller = make_comparison_controller(GetParam(), setup_on(random_path(random)));
    const ControllerInput good{{random.uniform(-20.0, 20.0), random.uniform(-20.0, 20.0)},
                               random.uniform(-3.0, 3.0),
                               random.uniform(1.0, 20.0),
                               0.0,
                               0.02};
    ControllerOutput output;
    ASSERT_EQ(controller->update(good, output), Status::ok) << testing::seed_message(seed);

    const int field = random.integer(0, 5);
    const bool hostile = random.coin();
    const double value = hostile ? hostile_value(random, field) : extreme_value(random, field);
    ControllerInput bad = good;
    set_field(bad, field, value);
    SCOPED_TRACE(GetParam() + ": " + field_names[static_cast<std::size_t>(field)] + " = " +
                 std::to_string(value) + " (" + (hostile ? "hostile" : "extreme") + "); " +
                 testing::seed_message(seed));
    const ControllerOutput before = output;
    const Status status = controller->update(bad, output);
    if (hostile) {
      EXPECT_EQ(status, Status::invalid_input);
    }
    if (status == Status::ok) {
      EXPECT_TRUE(all_finite(output));
    } else {
      EXPECT_EQ(std::memcmp(&before, &output, sizeof output), 0) << "output changed on error";
    }
    // The controller carries on with a good input.
    controller->reset(0.0);
    EXPECT_EQ(controller->update(good, output), Status::ok);
    EXPECT_TRUE(all_finite(output));
  }
}

INSTANTIATE_TEST_SUITE_P(Baselines, EveryControllerUnderHostileInput,
                         ::testing::ValuesIn(comparison_controller_names()));

// The inputs that once came back ok with non-finite values: a coordinate of 1e155, whose squared
// distances overflow (-inf lateral errors), and a speed of 1e308 (LQR's NaN diagnostics). They lie
// far beyond ControllerInputRange, so every comparison controller must refuse them with
// invalid_input before any arithmetic.
TEST(HostileControllerInput, OverflowingCoordinatesAndSpeedsAreRefused) {
  auto path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 1000.0));
  for (const std::string& name : comparison_controller_names()) {
    auto controller = make_comparison_controller(name, setup_on(path));
    ControllerOutput output;
    for (const ControllerInput& input : {ControllerInput{{1e155, 0.0}, 0.0, 10.0, 0.0, 0.02},
                                         ControllerInput{{0.0, -1e155}, 0.0, 10.0, 0.0, 0.02},
                                         ControllerInput{{0.0, 0.0}, 0.0, 1e308, 0.0, 0.02}}) {
      EXPECT_EQ(controller->update(input, output), Status::invalid_input) << name;
    }
  }
}

//! A step that reports ok with a NaN diagnostic (as controllers did at |x| >= 1e155).
class NanDiagnostic final : public SteeringController {
 public:
  Status compute_command(const ControllerInput&, ControllerOutput& output) noexcept override {
    output.steering_angle_rad = 0.1;
    output.diagnostics.lateral_error_m = nan;
    return Status::ok;
  }
  Status reset(double angle) noexcept override {
    reset_to = angle;
    return Status::ok;
  }
  const char* name() const noexcept override { return "nan_diagnostic"; }
  double reset_to = -1.0;
};

TEST(HostileControllerInput, NonFiniteResultIsNumericalErrorAndResets) {
  NanDiagnostic controller;
  ControllerOutput output;
  output.steering_angle_rad = 0.25;
  EXPECT_EQ(controller.update({{0.0, 0.0}, 0.0, 10.0, 0.0, 0.02}, output), Status::numerical_error);
  EXPECT_EQ(output.steering_angle_rad, 0.25);
  EXPECT_TRUE(std::isfinite(output.diagnostics.lateral_error_m));
  EXPECT_EQ(controller.reset_to, 0.25);
}

TEST(HostileControllerInput, ComparisonSetupRefusesMagnitudesThatBreakTheArithmetic) {
  ComparisonSetup setup =
      setup_on(std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 100.0)));
  setup.wheelbase_m = 1e308;
  EXPECT_THROW(setup.validate(), std::invalid_argument);
  try {
    setup.validate();
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("ComparisonSetup: wheelbase_m = 1e+308"),
              std::string::npos)
        << error.what();
  }
  setup.wheelbase_m = 2.7;
  setup.nominal_speed_mps = 1e308;
  EXPECT_THROW(setup.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace smoothsteer
