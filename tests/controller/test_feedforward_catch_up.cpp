// The feedforward's catch-up (ControllerParameters::feedforward_catch_up, docs/feedforward.md
// section 4): where the rate limit L_ff holds kappa_ff back from its target, the switching part
// adds up to g kbar_sw of the gap. On random S-shaped paths whose curvature changes faster than
// L_ff allows, on the kinematic plant, the rear axle stays closer to the path with it: by a
// median factor of 1.3 at least (1.55 over 800 cases). It is not better in every case: in 13 %
// of them it is worse, by at most 2.7 mm or 1.36x where the error without it is >= 5 mm (the
// rate limit also filters the waypoint spline's curvature, and a law near saturation loses a
// little help from the lagging kappa_ff), so each case is only held to 1.5x + 1 mm. The
// certificate and the convergence from far starts with it are covered by
// test_feedforward_certificate.cpp (its random parameters draw the catch-up too).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/sim/kinematic_closed_loop.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using namespace smoothsteer::testing;

//! Largest rear-axle |e| past the start, on y = a (1 - cos(w x)), with the given catch-up.
double worst_error(const std::shared_ptr<const Path>& path, double length, double speed,
                   double rate, double catch_up, int order) {
  ControllerParameters p;
  p.chain.order = order;
  p.chain.lead_curvature_bound = 0.12;
  p.feedforward.share = 0.7;
  p.feedforward.curvature_rate = rate;
  p.feedforward.catch_up = catch_up;
  p.law.boundary_layer = 0.01;
  p.feedforward.cornering_target = CorneringTarget::rear_axle_exact;
  LeadWheelController controller(p, path);
  KinematicLoopOptions options;
  options.wheelbase_m = p.chain.vehicle_wheelbase_m;
  options.speed_mps = speed;
  options.period_s = 0.02;
  options.duration_s = length / speed;
  const KinematicLoopResult r = run_kinematic_closed_loop(controller, {{0.0, 0.0}, 0.0}, options);
  EXPECT_EQ(r.status, Status::ok);
  double worst = 0.0;
  for (const auto& sample : r.trace) {
    if (sample.distance_m < 20.0 || sample.distance_m > length - 20.0) continue;
    worst = std::max(worst, std::abs(sample.output.diagnostics.lateral_error_m));
  }
  return worst;
}

TEST(FeedforwardCatchUp, KeepsTheRearAxleCloserWhereTheRateLimitLags) {
  const int cases = std::max(5, property_cases(40) / 10);
  std::vector<double> gains;
  for (int k = 0; k < cases; ++k) {
    const std::uint64_t seed = case_seed(k);  // replays with SMOOTHSTEER_SEED=seed
    Random random(seed + 601);
    const double amplitude = random.uniform(1.0, 4.0);
    const double wavenumber = random.uniform(0.05, 0.1);
    const double speed = random.uniform(4.0, 15.0);
    const int order = random.integer(1, 2);
    // The path's curvature rate is a w^3 at most; L_ff is a fraction of it.
    const double path_rate = amplitude * wavenumber * wavenumber * wavenumber;
    const double rate = random.uniform(0.3, 0.7) * path_rate;
    const double catch_up = random.uniform(0.5, 1.0);
    std::ostringstream context;
    context << seed_message(seed) << " y = " << amplitude << " (1 - cos(" << wavenumber
            << " x)), v = " << speed << ", n = " << order << ", L_ff = " << rate
            << ", catch-up = " << catch_up;
    SCOPED_TRACE(context.str());
    std::vector<Vec2> points;
    const double length = 2.5 * 2.0 * 3.14159265358979 / wavenumber;
    for (double x = 0.0; x <= length; x += 1.0)
      points.push_back({x, amplitude * (1.0 - std::cos(wavenumber * x))});
    const auto path = std::make_shared<const Path>(Path::from_waypoints(points));
    const double without = worst_error(path, length, speed, rate, 0.0, order);
    const double with = worst_error(path, length, speed, rate, catch_up, order);
    EXPECT_LE(with, 1.5 * without + 0.001) << "without " << without << " m, with " << with << " m";
    gains.push_back(without / std::max(with, 1e-12));
  }
  std::sort(gains.begin(), gains.end());
  const double median = gains[gains.size() / 2];
  std::printf("catch-up: the rear axle's max |e| shrinks by a median %.2fx (%.2fx to %.2fx)\n",
              median, gains.front(), gains.back());
  EXPECT_GE(median, 1.3) << "over " << cases << " cases from " << seed_message(case_seed(0) + 601);
}

}  // namespace
}  // namespace smoothsteer
