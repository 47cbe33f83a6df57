// Replanning with set_path(): a planner replaces the path at 10 Hz, or jumps it sideways by a
// lane width. The command must stay as smooth as without replanning and within the certified
// bounds (ChainBounds). (No allocation in set_path: test_no_allocation.cpp.)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "smoothsteer/controller/lead_wheel_controller.hpp"
#include "smoothsteer/math/angles.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

namespace smoothsteer {
namespace {

constexpr double kSpeed_mps = 10.0;
constexpr double kPeriod_s = 0.02;

//! The S-curve: straight, a 6 m sideways S (y = 3 (1 - cos(x / 25)), zero slope at both ends)
//! over 78.5 m, straight again, and a second S back.
double s_curve_y(double x) {
  constexpr double half = 25.0 * pi;
  if (x < 0.0) return 0.0;
  if (x < half) return 3.0 * (1.0 - std::cos(x / 25.0));
  if (x < half + 40.0) return 6.0;
  if (x < 2.0 * half + 40.0) return 3.0 * (1.0 + std::cos((x - half - 40.0) / 25.0));
  return 0.0;
}

//! What a planner sends: the curve from `from_x` to `from_x + 200` m, sampled every `spacing`
//! metres starting at `from_x` (so that the samples differ from one plan to the next), shifted
//! sideways by `shift_m`.
std::shared_ptr<const Path> planned_path(double from_x, double spacing, double shift_m) {
  std::vector<Vec2> waypoints;
  for (double x = from_x; x <= from_x + 200.0; x += spacing) {
    waypoints.push_back({x, s_curve_y(x) + shift_m});
  }
  return std::make_shared<const Path>(Path::from_waypoints(waypoints));
}

struct DriveResult {
  double peak_rate_radps = 0.0;  //!< of the held command, |delta_k - delta_{k-1}| / dt
  double peak_reported_rate_radps = 0.0;
  double peak_angle_rad = 0.0;
  double final_error_m = 0.0;
  double largest_step_at_swap_rad = 0.0;
  //! Change of the reported rate d(delta)/dt from one period to the next: at a swap, and the
  //! largest anywhere else (n = 2 makes the command C^1, so a swap must not stand out).
  double rate_change_at_swap_radps = 0.0;
  double largest_rate_change_elsewhere_radps = 0.0;
};

//! Drives 30 s along the S-curve from `start_offset_m` beside its lead-in. `replan(k, x)` returns a
//! new path or nullptr.
template <typename Replan>
DriveResult drive(LeadWheelController& controller, double start_offset_m, Replan replan) {
  const KinematicSingleTrack model{controller.parameters().chain.vehicle_wheelbase_m};
  Pose2 pose{{-20.0, start_offset_m}, 0.0};
  ControllerOutput output;
  DriveResult run;
  double previous = 0.0;
  double previous_rate = 0.0;
  const int steps = static_cast<int>(30.0 / kPeriod_s);
  for (int k = 0; k < steps; ++k) {
    bool swapped = false;
    if (auto next = replan(k, pose.position.x)) {
      EXPECT_EQ(controller.set_path(std::move(next)), Status::ok);
      swapped = true;
    }
    const Status status =
        controller.update({pose.position, pose.heading_rad, kSpeed_mps, 0.0, kPeriod_s}, output);
    EXPECT_EQ(status, Status::ok) << "step " << k;
    const double delta = output.steering_angle_rad;
    if (k > 0) {
      const double step = std::abs(delta - previous);
      run.peak_rate_radps = std::max(run.peak_rate_radps, step / kPeriod_s);
      const double rate_change = std::abs(output.steering_rate_radps - previous_rate);
      if (swapped) {
        run.largest_step_at_swap_rad = std::max(run.largest_step_at_swap_rad, step);
        run.rate_change_at_swap_radps = std::max(run.rate_change_at_swap_radps, rate_change);
      } else {
        run.largest_rate_change_elsewhere_radps =
            std::max(run.largest_rate_change_elsewhere_radps, rate_change);
      }
    }
    previous_rate = output.steering_rate_radps;
    run.peak_reported_rate_radps =
        std::max(run.peak_reported_rate_radps, std::abs(output.steering_rate_radps));
    run.peak_angle_rad = std::max(run.peak_angle_rad, std::abs(delta));
    run.final_error_m = output.diagnostics.lateral_error_m;
    previous = delta;
    pose = model.step(pose, delta, kSpeed_mps, kPeriod_s);
  }
  return run;
}

ControllerParameters s_curve_parameters() {
  ControllerParameters parameters;
  parameters.chain.order = 2;
  parameters.chain.lead_curvature_bound = 0.1;
  return parameters;
}

TEST(Replanning, TenHertzReplanningKeepsThePeakRateAndTheFinalError) {
  const auto reference = planned_path(-40.0, 2.0, 0.0);
  LeadWheelController fixed(s_curve_parameters(), planned_path(-40.0, 2.0, 0.0));
  const DriveResult without =
      drive(fixed, 0.0, [](int, double) { return std::shared_ptr<const Path>(); });

  LeadWheelController replanned(s_curve_parameters(), reference);
  int plans = 0;
  const DriveResult with =
      drive(replanned, 0.0, [&plans](int k, double x) -> std::shared_ptr<const Path> {
        if (k == 0 || k % 5 != 0) return nullptr;  // every 0.1 s at 50 Hz
        ++plans;
        // Re-sampled (spacing 1.5-2.5 m, grid starting a little behind the car) at every plan.
        return planned_path(x - 10.0 - 0.37 * (plans % 7), 1.5 + 0.1 * (plans % 11), 0.0);
      });
  EXPECT_GT(plans, 200);
  EXPECT_LE(with.peak_rate_radps, 1.1 * without.peak_rate_radps)
      << "without " << without.peak_rate_radps << " rad/s, with " << with.peak_rate_radps;
  EXPECT_NEAR(with.final_error_m, without.final_error_m, 0.01);
  EXPECT_LT(std::abs(with.final_error_m), 0.05);
  std::printf(
      "10 Hz replanning: peak held-command rate %.4f rad/s (without: %.4f), final e %.5f m "
      "(without: %.5f)\n",
      with.peak_rate_radps, without.peak_rate_radps, with.final_error_m, without.final_error_m);
}

TEST(Replanning, LaneWidthJumpIsReachedWithinTheCertifiedBoundsWithoutAKink) {
  LeadWheelController controller(s_curve_parameters(), planned_path(-40.0, 2.0, 0.0));
  const ChainBounds bounds = controller.bounds();
  const double rate_bound = kSpeed_mps * bounds.steering_rate_per_meter;
  bool jumped = false;
  const DriveResult run =
      drive(controller, 0.5, [&jumped](int k, double x) -> std::shared_ptr<const Path> {
        if (k != 250) return nullptr;  // after 5 s, well settled on the curve
        jumped = true;
        return planned_path(x - 20.0, 2.0, 3.5);  // one lane to the left
      });
  ASSERT_TRUE(jumped);
  // Reached: the final error is measured against the shifted path.
  EXPECT_LT(std::abs(run.final_error_m), 0.05);
  // Within the certified bounds: angle and rate (reported and of the held command; the held
  // command's difference quotient is a mean of the rate, so the same bound applies).
  EXPECT_LE(run.peak_angle_rad, bounds.steering_angle_rad * (1.0 + 1e-9));
  EXPECT_LE(run.peak_reported_rate_radps, rate_bound * (1.0 + 1e-9));
  EXPECT_LE(run.peak_rate_radps, rate_bound * (1.0 + 1e-6));
  // No kink: the command moves at the swap no more than one period at the bounded rate allows.
  EXPECT_LE(run.largest_step_at_swap_rad, rate_bound * kPeriod_s);
  EXPECT_LE(run.rate_change_at_swap_radps, run.largest_rate_change_elsewhere_radps)
      << "rate change at the swap " << run.rate_change_at_swap_radps << " rad/s, elsewhere "
      << run.largest_rate_change_elsewhere_radps;
  std::printf(
      "lane jump: peak angle %.4f (bound %.4f) rad, peak rate %.4f (bound %.4f) rad/s, "
      "rate change at swap %.4f, elsewhere %.4f rad/s, final e %.4f m\n",
      run.peak_angle_rad, bounds.steering_angle_rad, run.peak_rate_radps, rate_bound,
      run.rate_change_at_swap_radps, run.largest_rate_change_elsewhere_radps, run.final_error_m);
}

TEST(Replanning, NullPathIsRejectedAndTheOldPathKept) {
  LeadWheelController controller(s_curve_parameters(), planned_path(-40.0, 2.0, 0.0));
  EXPECT_EQ(controller.set_path(nullptr), Status::invalid_input);
  ControllerOutput output;
  EXPECT_EQ(controller.update({{0.0, 0.0}, 0.0, kSpeed_mps, 0.0, kPeriod_s}, output), Status::ok);
}

}  // namespace
}  // namespace smoothsteer
