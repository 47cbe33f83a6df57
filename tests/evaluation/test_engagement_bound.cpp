// The engagement lower bound (engagement_bound.hpp): its path-coordinate derivatives match finite
// differences, its held controls re-simulated on the Cartesian model keep every limit and
// reproduce the bound, it is near 0 for a start on the path, never below |e(0)|, and grows with
// the heading error on a straight path.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "../../src/evaluation/engagement_model.hpp"
#include "smoothsteer/evaluation/engagement_bound.hpp"
#include "smoothsteer/evaluation/engagement_study.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "support/property.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

EngagementBoundProblem lane_change_problem(int speed, double offset_m, double heading_rad) {
  const runner::Scenario scenario = runner::load_scenario(
      testing::source_file("scenarios/lane_change_" + std::to_string(speed) + ".yaml"),
      {"start.y_m=" + std::to_string(offset_m),
       "start.heading_rad=" + std::to_string(heading_rad)});
  return engagement_bound_problem(scenario);
}

EngagementBoundProblem straight_problem(double offset_m, double heading_rad) {
  EngagementBoundProblem problem;
  problem.path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 300.0));
  problem.speed_mps = 15.0;
  problem.start = {{0.0, offset_m}, heading_rad};
  problem.duration_s = 8.0;
  return problem;
}

//! Converged, the re-simulation within every limit and within 1 cm (or 2 %) of the bound.
void expect_consistent(const EngagementBoundProblem& problem, const EngagementBound& bound) {
  ASSERT_TRUE(bound.converged) << bound.solver_status;
  const EngagementBoundCheck check = resimulate_engagement_bound(problem, bound);
  EXPECT_LE(check.max_steering_excess_rad, 1e-9);
  EXPECT_LE(check.max_rate_excess_radps, 1e-7);
  EXPECT_LE(check.max_acceleration_excess_radps2, 1e-7);
  const double tolerance = std::max(0.01, 0.02 * bound.max_abs_lateral_error_m);
  EXPECT_NEAR(check.max_abs_lateral_error_m, bound.max_abs_lateral_error_m, tolerance);
  EXPECT_LT(check.max_node_lateral_deviation_m, tolerance);
}

TEST(EngagementBound, PathCoordinateJacobianMatchesFiniteDifferences) {
  const EngagementBoundProblem problem = lane_change_problem(15, 0.0, 0.0);
  const Path& path = *problem.path;
  testing::Random random(testing::base_seed());
  for (int index = 0; index < testing::property_cases(20); ++index) {
    const double x[4] = {random.uniform(50.0, 120.0), random.uniform(-1.5, 1.5),
                         random.uniform(-0.3, 0.3), random.uniform(-0.5, 0.5)};
    SCOPED_TRACE("s " + std::to_string(x[0]) + " e " + std::to_string(x[1]) + " psi " +
                 std::to_string(x[2]) + " delta " + std::to_string(x[3]));
    auto rates = [&](const double y[4]) {
      return detail::frenet_rates(15.0, 2.578, detail::path_curvature(path, y[0]), y[1], y[2],
                                  y[3]);
    };
    const detail::FrenetRates at = rates(x);
    for (int j = 0; j < 4; ++j) {
      // The s column holds kappa'(s), itself a difference: a wider step against its noise.
      const double step = j == 0 ? 1e-3 : 1e-6;
      double ahead[4] = {x[0], x[1], x[2], x[3]}, behind[4] = {x[0], x[1], x[2], x[3]};
      ahead[j] += step;
      behind[j] -= step;
      const detail::FrenetRates a = rates(ahead), b = rates(behind);
      for (int i = 0; i < 3; ++i) {
        const double numeric = (a.rate[i] - b.rate[i]) / (2.0 * step);
        EXPECT_NEAR(at.jacobian[i][j], numeric, 1e-5 * (1.0 + std::abs(numeric)))
            << "row " << i << " column " << j;
      }
    }
  }
}

TEST(EngagementBound, PathCoordinateHessianMatchesFiniteDifferences) {
  const EngagementBoundProblem problem = lane_change_problem(15, 0.0, 0.0);
  const Path& path = *problem.path;
  testing::Random random(testing::base_seed() + 3);
  // (row, column) of the seven entries of frenet_second_derivatives, in (s, e, psi, delta).
  const int pairs[7][2] = {{0, 0}, {1, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 2}, {3, 3}};
  for (int index = 0; index < testing::property_cases(20); ++index) {
    const double x[4] = {random.uniform(50.0, 120.0), random.uniform(-1.5, 1.5),
                         random.uniform(-0.3, 0.3), random.uniform(-0.5, 0.5)};
    SCOPED_TRACE("s " + std::to_string(x[0]) + " e " + std::to_string(x[1]) + " psi " +
                 std::to_string(x[2]) + " delta " + std::to_string(x[3]));
    const detail::PathCurvature c = detail::path_curvature(path, x[0]);
    const detail::FrenetCurvatureTerms terms =
        detail::frenet_second_derivatives(15.0, 2.578, c, x[1], x[2], x[3]);
    for (int p = 0; p < 7; ++p) {
      const int row = pairs[p][0], column = pairs[p][1];
      // Differences of the analytic Jacobian's column `column` along `row`, the curvature held
      // in its quadratic Taylor form about s (the spline's curvature is only C0 in kappa').
      auto jacobian = [&](double offset) {
        double y[4] = {x[0], x[1], x[2], x[3]};
        y[row] += offset;
        detail::PathCurvature shifted = c;
        if (row == 0) {
          shifted.kappa =
              c.kappa + c.derivative * offset + 0.5 * c.second_derivative * offset * offset;
          shifted.derivative = c.derivative + c.second_derivative * offset;
        }
        return detail::frenet_rates(15.0, 2.578, shifted, y[1], y[2], y[3]);
      };
      const double step = 1e-5;
      const detail::FrenetRates a = jacobian(step), b = jacobian(-step);
      for (int i = 0; i < 3; ++i) {
        const double numeric = (a.jacobian[i][column] - b.jacobian[i][column]) / (2.0 * step);
        EXPECT_NEAR(terms.hessian[i][p], numeric, 1e-5 * (1.0 + std::abs(numeric)))
            << "rate " << i << " entry (" << row << ", " << column << ")";
      }
    }
  }
}

TEST(EngagementBound, ResimulationKeepsTheLimitsAndReproducesTheBound) {
  for (const auto& [offset, heading] : {std::pair{0.5, 0.1}, std::pair{-1.0, 0.15}}) {
    SCOPED_TRACE("offset " + std::to_string(offset) + " heading " + std::to_string(heading));
    const EngagementBoundProblem problem = lane_change_problem(15, offset, heading);
    const EngagementBound bound = solve_engagement_bound(problem);
    expect_consistent(problem, bound);
    // Node 0 is the start: no steering gets below |e(0)|; a heading away from the path costs more.
    EXPECT_GE(bound.max_abs_lateral_error_m, std::abs(offset) - 1e-6);
    if (offset * heading > 0.0) {
      EXPECT_GT(bound.max_abs_lateral_error_m, std::abs(offset) + 0.05);
    }
  }
}

TEST(EngagementBound, StartOnThePathAtLowSpeedIsNearlyZero) {
  const EngagementBoundProblem problem = lane_change_problem(10, 0.0, 0.0);
  const EngagementBound bound = solve_engagement_bound(problem);
  expect_consistent(problem, bound);
  EXPECT_LT(bound.max_abs_lateral_error_m, 0.01);
}

TEST(EngagementBound, GrowsWithTheHeadingErrorOnAStraightPath) {
  double previous = -1.0;
  for (double heading : {0.0, 0.05, 0.1, 0.15, 0.2}) {
    SCOPED_TRACE("heading " + std::to_string(heading));
    const EngagementBoundProblem problem = straight_problem(0.0, heading);
    const EngagementBound bound = solve_engagement_bound(problem);
    expect_consistent(problem, bound);
    EXPECT_GT(bound.max_abs_lateral_error_m, previous + (heading > 0.0 ? 1e-3 : -1.0));
    // The mirror image has the same bound.
    const EngagementBound mirrored = solve_engagement_bound(straight_problem(0.0, -heading));
    ASSERT_TRUE(mirrored.converged) << mirrored.solver_status;
    EXPECT_NEAR(mirrored.max_abs_lateral_error_m, bound.max_abs_lateral_error_m, 1e-4);
    previous = bound.max_abs_lateral_error_m;
  }
}

TEST(EngagementBound, RandomEngagementsConverge) {
  // One Ipopt solve of the whole lane change per case (0.4-2.5 s): the count follows the
  // environment up to 20, so that CI's large counts do not spend minutes here.
  const int cases = std::min(testing::property_cases(3), 20);
  for (int index = 0; index < cases; ++index) {
    const auto seed = testing::case_seed(index);
    testing::Random random(seed + 11);
    const int speed = std::array{10, 15, 19}[static_cast<std::size_t>(random.integer(0, 2))];
    const double offset = random.uniform(-1.2, 1.2), heading = random.uniform(-0.2, 0.2);
    SCOPED_TRACE(testing::seed_message(seed) + " speed " + std::to_string(speed) + " offset " +
                 std::to_string(offset) + " heading " + std::to_string(heading));
    const EngagementBoundProblem problem = lane_change_problem(speed, offset, heading);
    expect_consistent(problem, solve_engagement_bound(problem));
  }
}

TEST(EngagementBound, ValidationNamesTheField) {
  EngagementBoundProblem problem = straight_problem(0.0, 0.0);
  problem.time_step_s = 0.2;
  EXPECT_NE(problem.validation_error().find("EngagementBoundProblem: time_step_s = 0.2"),
            std::string::npos)
      << problem.validation_error();
  EXPECT_THROW(solve_engagement_bound(problem), std::invalid_argument);
  problem = straight_problem(0.0, 0.0);
  problem.path.reset();
  EXPECT_NE(problem.validation_error().find("path"), std::string::npos);
}

}  // namespace
}  // namespace smoothsteer
