// The kinetic tracking reference (kinetic_reference.hpp): 0 on a straight path, and on the
// hairpin at random speeds a converged linear program whose held controls keep every limit and,
// re-simulated by RK4 on the continuous model, reproduce its error; positive where the steering
// rate binds.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "smoothsteer/evaluation/kinetic_reference.hpp"
#include "smoothsteer/runner/scenario.hpp"
#include "support/property.hpp"
#include "support/source_dir.hpp"

namespace smoothsteer {
namespace {

KineticReferenceProblem hairpin_problem(double speed_mps) {
  const runner::Scenario hairpin =
      runner::load_scenario(testing::source_file("scenarios/hairpin.yaml"));
  KineticReferenceProblem problem;
  problem.path = hairpin.path;
  problem.vehicle = hairpin.vehicle;
  problem.speed_mps = speed_mps;
  // From the straight's last 20 m through the corner and 20 m beyond it.
  problem.start_arc_length_m = 30.0;
  problem.duration_s = (hairpin.path->length() - 70.0) / speed_mps;
  return problem;
}

TEST(KineticReference, ZeroOnAStraightPath) {
  KineticReferenceProblem problem = hairpin_problem(15.0);
  problem.path = std::make_shared<const Path>(Path::straight_line({0.0, 0.0}, 0.0, 300.0));
  problem.duration_s = 5.0;
  const KineticReference reference = solve_kinetic_reference(problem);
  ASSERT_TRUE(reference.converged) << reference.solver_status;
  EXPECT_LT(reference.max_abs_lateral_error_m, 1e-6);
}

TEST(KineticReference, HeldControlsKeepTheLimitsAndReproduceTheError) {
  testing::Random random(testing::base_seed());
  for (int index = 0; index < testing::property_cases(3); ++index) {
    const double speed = random.uniform(7.0, 11.0);
    SCOPED_TRACE("seed " + std::to_string(testing::base_seed()) + " case " + std::to_string(index) +
                 " speed " + std::to_string(speed));
    const KineticReferenceProblem problem = hairpin_problem(speed);
    const KineticReference reference = solve_kinetic_reference(problem);
    ASSERT_TRUE(reference.converged) << reference.solver_status;
    const VehicleParameters& car = problem.vehicle;
    for (std::size_t k = 0; k < reference.steering_rad.size(); ++k) {
      ASSERT_LE(std::abs(reference.steering_rad[k]), car.max_steering_angle_rad + 1e-9);
      ASSERT_LE(std::abs(reference.steering_rate_radps[k]), car.max_steering_rate_radps + 1e-7);
      ASSERT_LE(std::abs(reference.lateral_error_m[k]), reference.max_abs_lateral_error_m + 1e-7);
    }
    for (double u : reference.steering_acceleration_radps2) {
      ASSERT_LE(std::abs(u), car.max_steering_acceleration_radps2 + 1e-7);
    }
    // The corner turns the car: the steering leaves 0 for the arc's (0.2 rad and more).
    EXPECT_GT(*std::max_element(reference.steering_rad.begin(), reference.steering_rad.end()),
              0.15);
    const KineticReferenceCheck check = resimulate_kinetic_reference(problem, reference);
    // The transcription takes kappa linear between the nodes (exact on clothoids, not across a
    // joint of two pieces); RK4 reads it continuously.
    EXPECT_LT(check.max_node_lateral_deviation_m, 1e-3);
    // Only the nodes are bounded: between them |e| may exceed z a little.
    EXPECT_GE(check.max_abs_lateral_error_m, reference.max_abs_lateral_error_m - 1e-3);
    EXPECT_LT(check.max_abs_lateral_error_m, reference.max_abs_lateral_error_m + 5e-3);
  }
}

TEST(KineticReference, PositiveWhereTheRateBinds) {
  // At 15-16 m/s the hairpin's 6 m clothoid asks about 0.55 rad/s of the car's 0.4.
  testing::Random random(testing::base_seed() + 1);
  const double speed = random.uniform(15.0, 16.0);
  SCOPED_TRACE("seed " + std::to_string(testing::base_seed() + 1) + " speed " +
               std::to_string(speed));
  const KineticReference fast = solve_kinetic_reference(hairpin_problem(speed));
  ASSERT_TRUE(fast.converged) << fast.solver_status;
  EXPECT_GT(fast.max_abs_lateral_error_m, 0.01);
  const KineticReferenceCheck check = resimulate_kinetic_reference(hairpin_problem(speed), fast);
  EXPECT_LT(check.max_node_lateral_deviation_m, 1e-3);
  EXPECT_GE(check.max_abs_lateral_error_m, fast.max_abs_lateral_error_m - 1e-3);
  EXPECT_LT(check.max_abs_lateral_error_m, fast.max_abs_lateral_error_m + 5e-3);
  // With the rate to spare (half the speed) the preview makes up for the slip's lag.
  const KineticReference slow = solve_kinetic_reference(hairpin_problem(0.5 * speed));
  ASSERT_TRUE(slow.converged) << slow.solver_status;
  EXPECT_LT(slow.max_abs_lateral_error_m, 0.2 * fast.max_abs_lateral_error_m);
}

TEST(KineticReference, ACarWithoutAnAccelerationLimitIsAccepted) {
  KineticReferenceProblem problem = hairpin_problem(15.5);
  const double bounded = solve_kinetic_reference(problem).max_abs_lateral_error_m;
  problem.vehicle.max_steering_acceleration_radps2 = std::numeric_limits<double>::infinity();
  const KineticReference free = solve_kinetic_reference(problem);
  ASSERT_TRUE(free.converged) << free.solver_status;
  // One constraint fewer: never worse.
  EXPECT_LE(free.max_abs_lateral_error_m, bounded + 1e-6);
}

TEST(KineticReference, ProblemsNameTheBrokenRule) {
  KineticReferenceProblem problem = hairpin_problem(8.0);
  problem.speed_mps = 0.0;
  try {
    solve_kinetic_reference(problem);
    FAIL() << "speed 0 accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("KineticReferenceProblem: speed_mps = 0"),
              std::string::npos)
        << error.what();
  }
  problem = hairpin_problem(8.0);
  problem.path.reset();
  EXPECT_THROW(solve_kinetic_reference(problem), std::invalid_argument);
}

}  // namespace
}  // namespace smoothsteer
