// The MPC baseline (mpc_controller.hpp): the unconstrained plan equals a direct least-squares
// solve of the cost written out term by term (docs/baselines.md "MPC"), and the constrained
// plan respects its angle and rate constraints on random problems.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <vector>

#include "smoothsteer/baselines/mpc_controller.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

struct Case {
  bool circle = false;
  double radius_m = 40.0;
  Vec2 position;
  double heading_rad = 0.0;
  double speed_mps = 10.0;
  double initial_steering_rad = 0.0;
};

std::shared_ptr<const Path> path_of(const Case& c) {
  return std::make_shared<const Path>(c.circle ? Path::circle({0.0, 0.0}, c.radius_m)
                                               : Path::straight_line({-50.0, 0.0}, 0.0, 500.0));
}

Case random_case(testing::Random& random) {
  Case c;
  c.circle = random.coin();
  c.radius_m = random.uniform(20.0, 80.0);
  const double offset = random.uniform(-2.0, 2.0);
  const double heading_error = random.uniform(-0.3, 0.3);
  if (c.circle) {  // counter-clockwise from angle 0: heading pi/2, left = inwards
    c.position = {c.radius_m - offset, 0.0};
    c.heading_rad = pi / 2.0 + heading_error;
  } else {
    c.position = {0.0, offset};
    c.heading_rad = heading_error;
  }
  c.speed_mps = random.uniform(3.0, 25.0);
  c.initial_steering_rad = random.uniform(-0.2, 0.2);
  return c;
}

// The cost residual r(U) written out term by term from docs/baselines.md, with its own
// prediction (continuous model, Tustin by LU), independent of the controller's stacked form.
Eigen::VectorXd residual(const MpcParameters& p, double e0, double psi0, double delta0, double v,
                         double kappa, double period, double u_prev, double u_pprev,
                         const Eigen::VectorXd& u) {
  const int n = p.horizon_steps;
  const double delta_r = std::atan(p.wheelbase_m * kappa);
  const double sec2 = 1.0 + std::tan(delta_r) * std::tan(delta_r);
  Eigen::Matrix3d a;
  a << 0, v, 0, 0, 0, v / p.wheelbase_m * sec2, 0, 0, -1.0 / p.steering_time_constant_s;
  const Eigen::Vector3d b(0, 0, 1.0 / p.steering_time_constant_s);
  const Eigen::Vector3d w(0, -v * kappa + v / p.wheelbase_m * (std::tan(delta_r) - delta_r * sec2),
                          0);
  const double dt = p.prediction_step_s;
  const Eigen::PartialPivLU<Eigen::Matrix3d> lu(Eigen::Matrix3d::Identity() - dt / 2 * a);
  const Eigen::Matrix3d ad = lu.solve(Eigen::Matrix3d::Identity() + dt / 2 * a);
  const Eigen::Vector3d bd = lu.solve(b * dt), wd = lu.solve(w * dt);
  const double u_ref = std::abs(delta_r) < p.zero_feedforward_angle_rad ? 0.0 : delta_r;
  std::vector<double> r;
  Eigen::Vector3d x(e0, psi0, delta0);
  const double v2 = v * v;
  for (int k = 0; k < n; ++k) {
    x = ad * x + bd * u(k) + wd;
    const bool last = k == n - 1;
    r.push_back(std::sqrt(last ? p.weight_terminal_lateral_error : p.weight_lateral_error) * x(0));
    r.push_back(std::sqrt((last ? p.weight_terminal_heading_error : p.weight_heading_error) +
                          p.weight_heading_error_squared_speed * v2) *
                x(1));
    r.push_back(std::sqrt(p.weight_steering_input + p.weight_steering_input_squared_speed * v2) *
                (u(k) - u_ref));
  }
  const double wr = std::sqrt(p.weight_steering_rate),
               wa = std::sqrt(p.weight_steering_acceleration);
  r.push_back(wr * (u(0) - u_prev) / period);
  for (int k = 1; k < n; ++k) r.push_back(wr * (u(k) - u(k - 1)) / dt);
  r.push_back(wa * (u(0) - 2 * u_prev + u_pprev) / (period * period));
  r.push_back(wa * ((u(1) - u(0)) / dt - (u(0) - u_prev) / period) / dt);
  for (int k = 2; k < n; ++k) r.push_back(wa * (u(k) - 2 * u(k - 1) + u(k - 2)) / (dt * dt));
  return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

TEST(MpcController, UnconstrainedPlanEqualsADirectLeastSquaresSolve) {
  const int cases = testing::property_cases(20);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed);
    const Case c = random_case(random);
    MpcParameters parameters;
    parameters.horizon_steps = random.integer(2, 60);
    parameters.weight_steering_rate = random.coin() ? 0.0 : random.uniform(0.0, 0.1);
    parameters.weight_steering_acceleration = random.uniform(0.0, 1e-3);
    parameters.limits = {1.2, 3.0};
    MpcController controller(parameters, path_of(c));
    controller.reset(c.initial_steering_rad);
    ControllerOutput output;
    const double period = 0.02;
    ASSERT_EQ(controller.update({c.position, c.heading_rad, c.speed_mps, 0.0, period}, output),
              Status::ok);
    const double e0 = output.diagnostics.lateral_error_m;
    const double psi0 = output.diagnostics.heading_error_rad;
    const double kappa = c.circle ? 1.0 / c.radius_m : 0.0;
    const double u0 = c.initial_steering_rad;
    const int n = parameters.horizon_steps;
    const auto r = [&](const Eigen::VectorXd& u) {
      return residual(parameters, e0, psi0, u0, c.speed_mps, kappa, period, u0, u0, u);
    };
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
    const Eigen::VectorXd r0 = r(zero);
    Eigen::MatrixXd jacobian(r0.size(), n);
    for (int j = 0; j < n; ++j) jacobian.col(j) = r(Eigen::VectorXd::Unit(n, j)) - r0;
    const Eigen::VectorXd direct = jacobian.colPivHouseholderQr().solve(-r0);
    const auto plan = controller.planned_steering();
    ASSERT_EQ(static_cast<int>(plan.size()), n);
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR(plan[static_cast<std::size_t>(k)], direct(k), 1e-7 * (1.0 + direct.norm()))
          << "k=" << k << " N=" << n << " circle=" << c.circle << " v=" << c.speed_mps
          << " e0=" << e0 << " psi0=" << psi0 << "; " << testing::seed_message(seed);
    }
  }
}

TEST(MpcController, ConstrainedPlanRespectsAngleAndRateConstraints) {
  const int cases = testing::property_cases(20);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed);
    Case c = random_case(random);
    MpcParameters parameters;
    parameters.solver = MpcSolver::constrained;
    parameters.horizon_steps = random.integer(5, 50);
    parameters.limits = {random.uniform(0.1, 0.6), random.uniform(0.05, 1.0)};
    c.initial_steering_rad = random.uniform(-1.0, 1.0) * parameters.limits.angle_rad;
    MpcController controller(parameters, path_of(c));
    controller.reset(c.initial_steering_rad);
    double previous = c.initial_steering_rad;
    ControllerOutput output;
    const double period = 0.02, dt = parameters.prediction_step_s;
    const double angle = parameters.limits.angle_rad, rate = parameters.limits.rate_radps;
    Pose2 pose{c.position, c.heading_rad};
    for (int step = 0; step < 5; ++step) {
      ASSERT_EQ(
          controller.update({pose.position, pose.heading_rad, c.speed_mps, 0.0, period}, output),
          Status::ok);
      const auto plan = controller.planned_steering();
      SCOPED_TRACE("step " + std::to_string(step) + " N=" + std::to_string(plan.size()) +
                   " angle=" + std::to_string(angle) + " rate=" + std::to_string(rate) +
                   " v=" + std::to_string(c.speed_mps) + "; " + testing::seed_message(seed));
      const double tolerance = 1e-6;
      EXPECT_LE(std::abs(plan[0] - previous), rate * period + tolerance);
      for (std::size_t k = 0; k < plan.size(); ++k) {
        EXPECT_LE(std::abs(plan[k]), angle + tolerance) << "k=" << k;
        if (k > 0) {
          EXPECT_LE(std::abs(plan[k] - plan[k - 1]), rate * dt + tolerance) << "k=" << k;
        }
      }
      EXPECT_EQ(controller.solver_failures(), 0);
      previous = output.steering_angle_rad;
      pose.position = pose.position + c.speed_mps * period * unit_from_heading(pose.heading_rad);
      pose.heading_rad += c.speed_mps * period * std::tan(previous) / parameters.wheelbase_m;
    }
  }
}

TEST(MpcController, ConstrainedEqualsUnconstrainedWhenNoConstraintIsActive) {
  Case c;
  c.position = {0.0, 0.3};
  c.heading_rad = 0.02;
  MpcParameters parameters;
  parameters.limits = {1.2, 100.0};
  MpcController unconstrained(parameters, path_of(c));
  parameters.solver = MpcSolver::constrained;
  MpcController constrained(parameters, path_of(c));
  ControllerOutput output;
  const ControllerInput input{c.position, c.heading_rad, 10.0, 0.0, 0.02};
  ASSERT_EQ(unconstrained.update(input, output), Status::ok);
  ASSERT_EQ(constrained.update(input, output), Status::ok);
  for (std::size_t k = 0; k < unconstrained.planned_steering().size(); ++k) {
    EXPECT_NEAR(constrained.planned_steering()[k], unconstrained.planned_steering()[k], 1e-6)
        << "k=" << k;
  }
}

TEST(MpcController, SetPathSwapsTheReferenceAndKeepsTheCommand) {
  Case c;
  c.position = {0.0, 0.5};
  MpcController controller(MpcParameters{}, path_of(c));
  ControllerOutput output;
  ASSERT_EQ(controller.update({c.position, 0.0, 10.0, 0.0, 0.02}, output), Status::ok);
  const double before = output.steering_angle_rad;
  EXPECT_EQ(controller.set_path(nullptr), Status::invalid_input);
  // The same line shifted 0.5 m left: the car is on it, so the MPC eases off, continuously.
  EXPECT_EQ(controller.set_path(
                std::make_shared<const Path>(Path::straight_line({-50.0, 0.5}, 0.0, 500.0))),
            Status::ok);
  ASSERT_EQ(controller.update({c.position, 0.0, 10.0, 0.0, 0.02}, output), Status::ok);
  EXPECT_NEAR(output.diagnostics.lateral_error_m, 0.0, 1e-9);
  EXPECT_LE(std::abs(output.steering_angle_rad - before), 0.6 * 0.02 + 1e-12);
}

TEST(MpcController, ValidationNamesTheField) {
  MpcParameters parameters;
  parameters.horizon_steps = 1;
  try {
    parameters.validate();
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("MpcParameters: horizon_steps = 1"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace smoothsteer
