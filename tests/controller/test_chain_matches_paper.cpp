// The general trailer chain reproduces the paper's explicit n = 1 (eq. ext1, sigmaf) and n = 2
// (eqs. deltalead, dddelta, control_law) formulas on random states, to 1e-9.

#include <gtest/gtest.h>

#include <cmath>

#include "smoothsteer/controller/dubins_switching_law.hpp"
#include "smoothsteer/controller/trailer_chain.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/path/path.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::property_cases;
using testing::Random;
using testing::seed_message;

// Straight reference along +x, so e = y and the path heading is 0 (paper Fig. problem).
const Path& x_axis() {
  static const Path path = Path::straight_line({-1000.0, 0.0}, 0.0, 2000.0);
  return path;
}

TEST(ChainMatchesPaper, FirstOrderEqualsExt1) {
  for (int c = 0; c < property_cases(200); ++c) {
    const auto seed = case_seed(c);
    Random random(seed);
    const double lambda = random.uniform(0.5, 4.0);
    const double kbar = random.uniform(0.01, 0.95) / lambda;
    const double k_rob = random.uniform(0.0, 0.9);
    const double e = random.uniform(-3.0, 3.0);
    const double psi = random.uniform(-1.2, 1.2);
    const double delta = random.uniform(-1.0, 1.0) * std::asin(kbar * lambda);
    const double kappa_f = random.uniform(-kbar, kbar);
    SCOPED_TRACE(seed_message(seed));

    ChainAngles angles{delta};
    ChainAngles rates{};
    chain_rates(angles, &lambda, 1, kappa_f, rates);
    // eq. (ext1): delta' = kappa_f / cos(delta) - tan(delta) / lambda
    EXPECT_NEAR(rates[0], kappa_f / std::cos(delta) - std::tan(delta) / lambda, 1e-9);

    // eq. (efronta) and (sigmaf): the chain's front wheel, projected on the path.
    ChainGeometry geometry;
    chain_geometry({0.0, e}, psi, angles, &lambda, 1, geometry);
    const PathProjection front = x_axis().project(geometry.position[1]);
    EXPECT_NEAR(front.lateral_error_m, e + std::sin(psi) * lambda, 1e-9);
    const double psi_f = wrap_angle(geometry.heading[1] - front.heading_rad);
    const double sigma_chain = paper_sliding_variable(front.lateral_error_m, psi_f, kbar, k_rob);
    // eq. (sigmaf) prints sign(psi + delta); for |psi + delta| < pi it equals sign(sin(.)).
    const double sigma_paper =
        -e - std::sin(psi) * lambda -
        (1.0 - std::cos(psi + delta)) / ((1.0 - k_rob) * kbar) * sign(psi + delta);
    EXPECT_NEAR(sigma_chain, sigma_paper, 1e-9);
  }
}

TEST(ChainMatchesPaper, SecondOrderEqualsControlLaw) {
  for (int c = 0; c < property_cases(200); ++c) {
    const auto seed = case_seed(c);
    Random random(seed);
    const double lambda = random.uniform(0.5, 3.0);
    const double lambda_l = random.uniform(0.2, 2.0);
    const double kbar_l = random.uniform(0.05, 0.9) / lambda_l;
    const double kbar_f = kbar_l / std::sqrt(1.0 - kbar_l * kbar_l * lambda_l * lambda_l);
    if (kbar_f * lambda >= 0.95) continue;  // outside the valid parameter set
    const double k_rob = random.uniform(0.0, 0.9);
    const double e = random.uniform(-3.0, 3.0);
    const double psi = random.uniform(-1.0, 1.0);
    const double delta = random.uniform(-1.0, 1.0) * std::asin(kbar_f * lambda);
    // Paper state (e, psi, delta, delta'); delta' chosen such that delta_l is inside its set.
    const double delta_l_target = random.uniform(-1.0, 1.0) * std::asin(kbar_l * lambda_l);
    const double ddelta =
        std::tan(delta_l_target) / (lambda_l * std::cos(delta)) - std::tan(delta) / lambda;
    SCOPED_TRACE(seed_message(seed));

    // eq. (deltalead)
    const double delta_l =
        std::atan((std::tan(delta) / lambda + ddelta) * lambda_l * std::cos(delta));
    ASSERT_NEAR(delta_l, delta_l_target, 1e-9);

    // Chain with the same state.
    const double wheelbases[2] = {lambda, lambda_l};
    const ChainAngles angles{delta, delta_l};
    ChainGeometry geometry;
    chain_geometry({0.0, e}, psi, angles, wheelbases, 2, geometry);
    const PathProjection lead = x_axis().project(geometry.position[2]);
    const double psi_l = wrap_angle(geometry.heading[2] - lead.heading_rad);
    const double sigma_chain = paper_sliding_variable(lead.lateral_error_m, psi_l, kbar_l, k_rob);
    // eq. (control_law), sigma
    const double sigma_paper = -(e + std::sin(psi) * lambda + std::sin(psi + delta) * lambda_l) -
                               (1.0 - std::cos(psi + delta + delta_l)) / ((1.0 - k_rob) * kbar_l) *
                                   sign(std::sin(psi + delta + delta_l));
    EXPECT_NEAR(sigma_chain, sigma_paper, 1e-9);
    const double kappa_l = kbar_l * sign(sigma_paper);

    const FrontAngleDerivatives chain = front_angle_derivatives(angles, wheelbases, 2, kappa_l);
    EXPECT_NEAR(chain.first, ddelta, 1e-9);
    // eq. (control_law): delta_l' and delta''
    const double ddelta_l =
        kappa_l / (std::cos(delta) * std::cos(delta_l)) - std::tan(delta) / lambda - ddelta;
    const double dddelta_control_law =
        ddelta_l / (std::cos(delta_l) * std::cos(delta_l) * std::cos(delta) * lambda_l) -
        ddelta / lambda + ddelta * ddelta * std::tan(delta);
    EXPECT_NEAR(chain.second, dddelta_control_law, 1e-9);
    // eq. (dddelta)
    const double front_curvature = std::tan(delta) / lambda + ddelta;
    const double dddelta_closed =
        (kappa_l / (std::cos(delta) * std::cos(delta_l)) - front_curvature) *
            (front_curvature * front_curvature * lambda_l * lambda_l * std::cos(delta) *
                 std::cos(delta) +
             1.0) /
            (lambda_l * std::cos(delta)) -
        ddelta / lambda + ddelta * ddelta * std::tan(delta);
    EXPECT_NEAR(chain.second, dddelta_closed, 1e-9);
    // eq. (ext2), last row with the typo fixed (tan(delta_l) / lambda_l).
    ChainAngles rates{};
    chain_rates(angles, wheelbases, 2, kappa_l, rates);
    EXPECT_NEAR(rates[1],
                (kappa_l / std::cos(delta_l) - std::tan(delta_l) / lambda_l) / std::cos(delta),
                1e-9);
  }
}

TEST(ChainMatchesPaper, SecondDerivativeMatchesFiniteDifferenceForLongerChains) {
  for (int c = 0; c < property_cases(100); ++c) {
    const auto seed = case_seed(c);
    Random random(seed);
    const int n = random.integer(2, 6);
    ControllerParameters parameters;
    parameters.chain.order = n;
    for (int i = 0; i < n; ++i)
      parameters.chain.wheelbases_m[static_cast<std::size_t>(i)] = random.uniform(0.3, 2.0);
    parameters.chain.lead_curvature_bound = 0.02;
    const ChainBounds bounds = compute_chain_bounds(parameters);
    ChainAngles angles{};
    for (int i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      angles[k] = random.uniform(-0.9, 0.9) * bounds.angle[k];
    }
    const double kappa = random.uniform(-1.0, 1.0) * parameters.chain.lead_curvature_bound;
    SCOPED_TRACE(seed_message(seed) + " n=" + std::to_string(n));
    const FrontAngleDerivatives analytic =
        front_angle_derivatives(angles, parameters.chain.wheelbases_m.data(), n, kappa);
    const double h = 1e-5;
    ChainAngles forward = angles, backward = angles;
    integrate_chain(forward, parameters.chain.wheelbases_m.data(), n, kappa, h, bounds.angle);
    integrate_chain(backward, parameters.chain.wheelbases_m.data(), n, kappa, -h, bounds.angle);
    EXPECT_NEAR(analytic.first, (forward[0] - backward[0]) / (2.0 * h), 1e-7);
    EXPECT_NEAR(analytic.second, (forward[0] - 2.0 * angles[0] + backward[0]) / (h * h), 2e-3);
  }
}

TEST(ChainBounds, RateBoundEqualsBruteForce) {
  // compute_chain_bounds() finds sup |d delta_veh/ds| with 64 samples and golden-section search;
  // brute force over 200 000 samples of the invariant set must not exceed it.
  for (int c = 0; c < property_cases(100); ++c) {
    const auto seed = case_seed(c);
    Random random(seed);
    ControllerParameters parameters;
    parameters.chain.order = random.integer(1, 4);
    parameters.chain.vehicle_wheelbase_m = random.uniform(1.5, 4.0);
    for (int i = 0; i < parameters.chain.order; ++i) {
      parameters.chain.wheelbases_m[static_cast<std::size_t>(i)] =
          random.uniform(i == 0 ? 0.3 : 0.1, 0.95) * parameters.chain.vehicle_wheelbase_m;
    }
    parameters.chain.lead_curvature_bound =
        random.uniform(0.05, 0.9) /
        parameters.chain.wheelbases_m[static_cast<std::size_t>(parameters.chain.order - 1)];
    if (!parameters.is_valid()) continue;
    SCOPED_TRACE(seed_message(seed));
    const ChainBounds bounds = compute_chain_bounds(parameters);
    const double ratio = parameters.chain.vehicle_wheelbase_m / parameters.chain.wheelbases_m[0];
    const double kbar_1 = bounds.curvature[1], lambda_1 = parameters.chain.wheelbases_m[0];
    double brute = 0.0;
    constexpr int samples = 200000;
    for (int k = 0; k <= samples; ++k) {
      const double angle = bounds.angle[0] * k / samples;
      brute = std::max(brute, vehicle_angle_gain(angle, ratio) *
                                  (kbar_1 / std::cos(angle) + std::tan(angle) / lambda_1));
    }
    EXPECT_GE(bounds.steering_rate_per_meter, brute * (1.0 - 1e-12));
    EXPECT_LE(bounds.steering_rate_per_meter, brute * (1.0 + 1e-6));
  }
}

TEST(ChainMatchesPaper, KappaLMaxNeedsTheSquareRoot) {
  // Notes §2: eq. (kappalmax) with the square root makes the invariant set of delta_1 exactly
  // [-dbar, dbar]; the printed form without it does not (and is dimensionally wrong).
  for (int c = 0; c < property_cases(200); ++c) {
    const auto seed = case_seed(c);
    Random random(seed);
    ControllerParameters parameters;
    parameters.chain.order = 2;
    parameters.chain.vehicle_wheelbase_m = random.uniform(2.0, 4.0);
    parameters.chain.wheelbases_m[1] =
        random.uniform(0.2, 0.9) * parameters.chain.vehicle_wheelbase_m;
    const double lambda_l = parameters.chain.wheelbases_m[1];
    parameters.chain.wheelbases_m[0] =
        std::sqrt(parameters.chain.vehicle_wheelbase_m * parameters.chain.vehicle_wheelbase_m -
                  lambda_l * lambda_l);
    const double lambda = parameters.chain.wheelbases_m[0];
    const double dbar = random.uniform(0.1, 1.0);
    const double s = std::sin(dbar);
    parameters.chain.lead_curvature_bound =
        s / std::sqrt(lambda * lambda + lambda_l * lambda_l * s * s);
    SCOPED_TRACE(seed_message(seed));
    ASSERT_TRUE(parameters.validation_error().empty()) << parameters.validation_error();
    EXPECT_NEAR(compute_chain_bounds(parameters).angle[0], dbar, 1e-12);
    const double printed = s / (lambda * lambda + lambda_l * lambda_l * s * s);
    if (std::abs(lambda * lambda + lambda_l * lambda_l * s * s - 1.0) > 0.05) {
      EXPECT_GT(std::abs(printed - parameters.chain.lead_curvature_bound), 1e-3);
    }
  }
}

}  // namespace
}  // namespace smoothsteer
