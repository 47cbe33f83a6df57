// Stack mode (SimulationParameters::planner, planner_windows.hpp): the windows a planner would
// send lie on the road they sample, span what they are told to (cut at an open road's ends,
// less than a lap of a closed one), arrive at every planner period, and their rules name the
// field.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "../../src/sim/planner_window.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_builder.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/vehicle/vehicle_model.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

TEST(PlannerWindows, EachRuleNamesItsField) {
  struct Case {
    const char* field;
    void (*set)(PlannerWindows&);
  };
  const Case cases[] = {
      {"planner.period_s", [](PlannerWindows& w) { w.period_s = -0.1; }},
      {"planner.period_s", [](PlannerWindows& w) { w.period_s = 0.03; }},  // not 0.02 k
      {"planner.period_s", [](PlannerWindows& w) { w.period_s = 0.01; }},  // below a period
      {"planner.period_s",
       [](PlannerWindows& w) { w.period_s = std::numeric_limits<double>::quiet_NaN(); }},
      {"planner.behind_m", [](PlannerWindows& w) { w.behind_m = -1.0; }},
      {"planner.spacing_m", [](PlannerWindows& w) { w.spacing_m = 0.0; }},
      {"planner.ahead_m", [](PlannerWindows& w) { w.ahead_m = 1.5; }},  // < 2 spacings
      {"planner.jitter_std_m", [](PlannerWindows& w) { w.jitter_std_m = 2.0; }},
      {"planner.smoothing_tolerance_m", [](PlannerWindows& w) { w.smoothing_tolerance_m = 11.0; }},
  };
  for (const Case& c : cases) {
    SimulationParameters sim;
    sim.planner.period_s = 0.1;
    c.set(sim.planner);
    const std::string error = sim.validation_error();
    EXPECT_NE(error.find(c.field), std::string::npos) << c.field << ": '" << error << "'";
  }
  SimulationParameters valid;
  valid.planner.period_s = 0.1;
  EXPECT_EQ(valid.validation_error(), "");
}

//! Largest distance of `window` from `road` over the window, sampled every 0.25 m.
double distance_from(const Path& window, const Path& road) {
  double worst = 0.0;
  for (double s = 0.0; s <= window.length(); s += 0.25) {
    worst = std::max(worst, std::abs(road.project(window.evaluate(s).position).lateral_error_m));
  }
  return worst;
}

// Random roads (an open S of two arcs and a line, or a closed circle), random window lengths,
// spacings and centres: a clean window lies on the road within the interpolating spline's own
// error and spans behind + ahead (cut to an open road, at most 3/4 of a closed one); a jittered
// one, fitted at sigma sqrt(2), within 5 sigma more away from its ends (where the smoothing cuts
// the S's reversal).
TEST(PlannerWindows, WindowsLieOnTheRoadTheySampleAndSpanWhatTheyAreTold) {
  const int cases = testing::property_cases(40);
  for (int i = 0; i < cases; ++i) {
    const std::uint64_t seed = testing::case_seed(i);
    testing::Random random(seed + 17);
    const bool closed = random.uniform(0.0, 1.0) < 0.3;
    const double radius = random.uniform(15.0, 300.0);
    PathBuilder builder({0.0, 0.0}, 0.0);
    const Path road = closed ? Path::circle({0.0, radius}, radius)
                             : builder.line(random.uniform(5.0, 50.0))
                                   .arc(radius, random.uniform(0.2, 1.2))
                                   .arc(radius, -random.uniform(0.2, 1.2))
                                   .line(random.uniform(5.0, 50.0))
                                   .build();
    PlannerWindows windows;
    windows.period_s = 0.1;
    windows.behind_m = random.uniform(0.0, 20.0);
    windows.ahead_m = random.uniform(20.0, 150.0);
    windows.spacing_m = random.uniform(0.5, 3.0);
    const double centre = random.uniform(-10.0, road.length() + 10.0);
    std::mt19937_64 engine(seed);
    const std::string context =
        testing::seed_message(seed) + (closed ? "; circle R " : "; S R ") + std::to_string(radius) +
        " m, road " + std::to_string(road.length()) + " m, centre " + std::to_string(centre) +
        " m, behind " + std::to_string(windows.behind_m) + ", ahead " +
        std::to_string(windows.ahead_m) + ", spacing " + std::to_string(windows.spacing_m);
    WaypointConditioner conditioner;
    windows.smoothing_tolerance_m = 0.0;  // the interpolation itself
    const std::shared_ptr<const Path> clean =
        detail::planner_window(road, centre, windows, engine, conditioner);
    // The interpolating spline's own error: O(h^2) at the S's curvature reversal (2 / R) and the
    // natural ends, mm elsewhere.
    const double interpolation = 0.15 * windows.spacing_m * windows.spacing_m / radius + 1e-3;
    EXPECT_LE(distance_from(*clean, road), interpolation) << context;
    double span = windows.behind_m + windows.ahead_m;
    if (closed) {
      span = std::min(span, 0.75 * road.length());
    } else {
      const double end =
          std::clamp(centre + windows.ahead_m, std::min(road.length(), 2.0 * windows.spacing_m),
                     road.length());
      span = end - std::max(0.0, std::min(centre - windows.behind_m,
                                          end - std::min(road.length(), 2.0 * windows.spacing_m)));
    }
    EXPECT_NEAR(clean->length(), span, 0.01 * span + 1e-3) << context;

    windows.jitter_std_m = random.uniform(0.005, 0.05);
    // The jitter's own RMS distance: this test is the windows' geometry; the estimate of the
    // jitter is tests/path/test_waypoint_conditioner.cpp's.
    windows.smoothing_tolerance_m = windows.jitter_std_m * std::sqrt(2.0);
    const std::shared_ptr<const Path> jittered =
        detail::planner_window(road, centre, windows, engine, conditioner);
    double worst = 0.0;
    for (double s = 5.0; s <= jittered->length() - 5.0; s += 0.25) {
      worst =
          std::max(worst, std::abs(road.project(jittered->evaluate(s).position).lateral_error_m));
    }
    EXPECT_LE(worst, 5.0 * windows.jitter_std_m + interpolation)
        << context << ", jitter " << windows.jitter_std_m;
  }
}

//! Counts set_path() calls and keeps the lengths of the paths it was handed.
class RecordingController final : public SteeringController {
 public:
  Status compute_command(const ControllerInput&, ControllerOutput& output) noexcept override {
    output = ControllerOutput{};
    return Status::ok;
  }
  Status reset(double) noexcept override { return Status::ok; }
  Status set_path(std::shared_ptr<const Path> path) noexcept override {
    if (!path) return Status::invalid_input;
    lengths.push_back(path->length());
    return Status::ok;
  }
  const char* name() const noexcept override { return "recording"; }
  std::vector<double> lengths;
};

TEST(PlannerWindows, TheSystemGetsAWindowEveryPlannerPeriodFromTheStart) {
  const Path road = Path::straight_line({0.0, 0.0}, 0.0, 500.0);
  const KinematicVehicleModel plant(VehicleParameters{});
  SimulationParameters sim;
  sim.duration_s = 1.0;
  sim.planner.period_s = 0.1;
  RecordingController controller;
  const SimulationResult result =
      simulate(road, plant, ActuatorParameters{}, SpeedProfile{10.0, 10.0, 0.0, 0.0}, sim,
               {{0.0, 0.0}, 0.0}, controller);
  ASSERT_EQ(result.stop_reason, "duration");
  // t = 0, 0.1, ..., 1.0: eleven windows of 5 m behind (cut at the road's start) to 100 m ahead.
  ASSERT_EQ(controller.lengths.size(), 11u);
  EXPECT_NEAR(controller.lengths.front(), 100.0, 0.5);
  EXPECT_NEAR(controller.lengths.back(), 105.0, 0.5);

  RecordingController whole;  // period 0: the road once, at construction (no set_path)
  sim.planner.period_s = 0.0;
  (void)simulate(road, plant, ActuatorParameters{}, SpeedProfile{10.0, 10.0, 0.0, 0.0}, sim,
                 {{0.0, 0.0}, 0.0}, whole);
  EXPECT_TRUE(whole.lengths.empty());
}

}  // namespace
}  // namespace smoothsteer
