// The chain's inverse (feedforward.hpp, docs/feedforward.md "exact rear-axle target"): with the
// rear axle exactly on a path, invert_chain's angles put every wheel on the trajectory the
// chain's kinematics give it, and its lead curvature is the curvature of the lead wheel's
// trajectory. Checked against the geometry by finite differences on random smooth curvature
// profiles, against the stationary cornering relations, and in closed loop: on a smooth path the
// exact target keeps the rear axle closer to the path than the stationary one.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "smoothsteer/controller/feedforward.hpp"
#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/controller/steering_certificate.hpp"
#include "smoothsteer/controller/trailer_chain.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/sim/kinematic_closed_loop.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using namespace smoothsteer::testing;

//! kappa(s) = a + b sin(w s + phi) and its derivatives.
struct SineCurvature {
  double a, b, w, phi;
  CurvatureJet at(double s) const {
    const double x = w * s + phi;
    return {a + b * std::sin(x), b * w * std::cos(x), -b * w * w * std::sin(x)};
  }
};

std::string describe(const SineCurvature& k, const double* lambda, int order) {
  std::ostringstream text;
  text << "kappa = " << k.a << " + " << k.b << " sin(" << k.w << " s + " << k.phi << "), order "
       << order << ", lambda =";
  for (int i = 0; i < order; ++i) text << ' ' << lambda[i];
  return text.str();
}

TEST(ChainInverse, LeadCurvatureIsTheCurvatureOfTheLeadWheelsTrajectory) {
  const int cases = property_cases(40);
  for (int k = 0; k < cases; ++k) {
    const std::uint64_t seed = case_seed(k);  // replays with SMOOTHSTEER_SEED=seed
    Random random(seed + 401);
    const int order = random.integer(1, 2);
    const double lambda[2] = {random.uniform(1.0, 4.0), random.uniform(0.05, 1.5)};
    const SineCurvature kappa{random.uniform(-0.05, 0.05), random.uniform(0.0, 0.08),
                              random.uniform(0.05, 0.4), random.uniform(-pi, pi)};
    SCOPED_TRACE(seed_message(seed) + " " + describe(kappa, lambda, order));
    // The rear axle's trajectory, integrated finely (midpoint rule on the heading).
    const double ds = 1e-3, length = 60.0;
    const auto steps = static_cast<int>(length / ds);
    std::vector<Vec2> rear(static_cast<std::size_t>(steps) + 1);
    std::vector<double> heading(rear.size());
    for (int i = 0; i < steps; ++i) {
      const auto j = static_cast<std::size_t>(i);
      const double mid = heading[j] + 0.5 * ds * kappa.at(i * ds).value;
      rear[j + 1] = rear[j] + ds * unit_from_heading(mid);
      heading[j + 1] = heading[j] + ds * kappa.at((i + 0.5) * ds).value;
    }
    auto lead_at = [&](int i) {
      ChainGeometry g;
      const ChainInverse inverse = invert_chain(kappa.at(i * ds), lambda, order);
      chain_geometry(rear[static_cast<std::size_t>(i)], heading[static_cast<std::size_t>(i)],
                     inverse.angles, lambda, order, g);
      return std::pair{g.position[static_cast<std::size_t>(order)],
                       g.heading[static_cast<std::size_t>(order)]};
    };
    const int h = 20;  // 2 cm central differences
    for (int i = 2 * h; i <= steps - 2 * h; i += 997) {
      const auto [before, heading_before] = lead_at(i - h);
      const auto [at, heading_at] = lead_at(i);
      const auto [after, heading_after] = lead_at(i + h);
      const Vec2 velocity = after - before;
      // The lead wheel moves along its own heading (no side slip of the chain's wheels) ...
      ASSERT_NEAR(wrap_angle(std::atan2(velocity.y, velocity.x) - heading_at), 0.0, 1e-5)
          << "s = " << i * ds;
      // ... and turns at the curvature invert_chain gives it.
      const double numeric = wrap_angle(heading_after - heading_before) / norm(velocity);
      const double exact = invert_chain(kappa.at(i * ds), lambda, order).lead_curvature;
      ASSERT_NEAR(numeric, exact, 1e-5 + 1e-4 * std::abs(exact)) << "s = " << i * ds;
    }
  }
}

TEST(ChainInverse, StationaryCorneringGivesTheConcentricCircles) {
  const int cases = property_cases(40);
  for (int k = 0; k < cases; ++k) {
    const std::uint64_t seed = case_seed(k);  // replays with SMOOTHSTEER_SEED=seed
    Random random(seed + 402);
    const int order = random.integer(1, 3);
    const double lambda[3] = {random.uniform(1.0, 4.0), random.uniform(0.05, 1.5),
                              random.uniform(0.05, 1.0)};
    const double curvature = random.uniform(-0.2, 0.2);
    SCOPED_TRACE(seed_message(seed) + " kappa " + std::to_string(curvature));
    const ChainInverse inverse = invert_chain({curvature, 0.0, 0.0}, lambda, order);
    double squared = 0.0;
    for (int i = 0; i < order; ++i) squared += lambda[i] * lambda[i];
    EXPECT_NEAR(inverse.lead_curvature, stationary_lead_curvature(curvature, squared), 1e-12);
    ChainAngles stationary;
    stationary_chain(std::atan(lambda[0] * curvature), lambda, order, stationary);
    for (std::size_t i = 0; i < static_cast<std::size_t>(order); ++i) {
      EXPECT_NEAR(inverse.angles[i], stationary[i], 1e-12) << "delta_" << i + 1;
    }
    // On a circle the exact target is the stationary offset, with no heading.
    const auto circle =
        Path::circle({0.0, 0.0}, std::abs(1.0 / curvature) + 5.0, curvature > 0.0, 0.0);
    const double on_circle = circle.max_abs_curvature() * (curvature > 0.0 ? 1.0 : -1.0);
    const PathProjection at = circle.project(circle.evaluate(20.0).position);
    const TargetCurve target =
        rear_axle_target_curve(circle, at, {on_circle, 0.0, 0.0}, lambda, order);
    EXPECT_NEAR(target.offset, rear_axle_cornering_offset(on_circle, squared), 1e-6);
    EXPECT_NEAR(target.heading, 0.0, 1e-5);
  }
}

TEST(ChainInverse, ExactTargetTracksASmoothPathTenTimesCloserThanTheStationaryOne) {
  // A smooth path (waypoints every metre on y = 2 (1 - cos(0.08 x))), n = 2, no feedforward
  // limits, the kinematic plant: past the start transient the exact target keeps the rear axle
  // within a millimetre (0.1-0.4 mm at 3-15 m/s), the stationary offset leaves about 5 mm.
  std::vector<Vec2> points;
  for (int i = 0; i <= 160; ++i) points.push_back({1.0 * i, 2.0 * (1.0 - std::cos(0.08 * i))});
  const auto path = std::make_shared<const Path>(Path::from_waypoints(points));
  double worst[2] = {0.0, 0.0};
  for (int exact = 0; exact < 2; ++exact) {
    ControllerParameters p;
    p.chain.lead_curvature_bound = 0.15;
    p.feedforward.share = 0.7;
    p.law.boundary_layer = 0.01;
    p.feedforward.cornering_target =
        exact ? CorneringTarget::rear_axle_exact : CorneringTarget::rear_axle;
    LeadWheelController controller(p, path);
    KinematicLoopOptions options;
    options.wheelbase_m = p.chain.vehicle_wheelbase_m;
    options.speed_mps = 8.0;
    options.period_s = 0.01;
    options.duration_s = 150.0 / options.speed_mps;
    const KinematicLoopResult r = run_kinematic_closed_loop(controller, {{0.0, 0.0}, 0.0}, options);
    ASSERT_EQ(r.status, Status::ok);
    for (const auto& sample : r.trace) {
      if (sample.distance_m < 20.0 || sample.distance_m > 140.0) continue;
      worst[exact] = std::max(worst[exact], std::abs(sample.output.diagnostics.lateral_error_m));
    }
  }
  std::printf("S-path at 8 m/s, max rear error: stationary target %.4f m, exact %.4f m\n", worst[0],
              worst[1]);
  EXPECT_LT(worst[1], 0.005);
  EXPECT_LT(worst[1], 0.3 * worst[0]);
}

}  // namespace
}  // namespace smoothsteer
