// The actuator's exact solution with rate and angle saturation (src/sim/exact_actuator.hpp)
// against RK4 of SteeringActuator::derivative at a 0.1 us step (its own error at a kink of the
// saturation, O(h^2), stays below 1e-9 rad there; at 1 us it reaches 1.4e-9), and the adaptive
// plant integrators against fixed_rk4 at a 0.05 ms sub-step (RK4 at 0.1 ms is itself too far from
// converged under saturation, see below) and at 10 us, under commands that drive the actuator
// into its saturation (dead times 0, 10 and 30 ms, speed ramps). Seeded; the count comes from
// SMOOTHSTEER_PROPERTY_CASES, and a failure prints the seed and the case's inputs.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "../../src/sim/exact_actuator.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "support/property.hpp"

namespace smoothsteer {
namespace {

using testing::case_seed;
using testing::property_cases;
using testing::Random;
using testing::seed_message;

std::string describe(const ActuatorParameters& p) {
  std::ostringstream text;
  text.precision(17);
  text << "bandwidth_hz " << p.bandwidth_hz << ", max_rate_radps " << p.max_rate_radps
       << ", max_angle_rad " << p.max_angle_rad << ", dead_time_s " << p.dead_time_s;
  return text.str();
}

TEST(ExactActuator, MatchesFineRk4AcrossRateAndAngleSaturation) {
  constexpr double fine_step_s = 1e-7, substep_s = 0.001;
  constexpr int substeps = 20, fine_per_substep = 10000;
  int saturated_cases = 0, angle_cases = 0;
  for (int k = 0; k < property_cases(); ++k) {
    const auto seed = case_seed(k);
    Random random(seed);
    ActuatorParameters p;
    p.bandwidth_hz = random.uniform(2.0, 20.0);
    p.max_rate_radps = random.uniform(0.05, 2.0);
    p.max_angle_rad = random.uniform(0.05, 1.1);
    p.dead_time_s = 0.0;
    // Start anywhere inside the limits, with lags apart; two stretches of constant input (a
    // held command behind a delay line) or one, with inputs beyond the angle limit at times.
    SteeringActuator::State start{};
    for (double& x : start) x = random.uniform(-1.2, 1.2) * p.max_angle_rad;
    start[2] = std::clamp(start[2], -p.max_angle_rad, p.max_angle_rad);
    if (random.coin()) {  // at the angle limit, the middle lag beyond it: angle saturation
      const double side = random.coin() ? 1.0 : -1.0;
      start[2] = side * random.uniform(0.98, 1.0) * p.max_angle_rad;
      start[1] = side * random.uniform(1.0, 1.3) * p.max_angle_rad;
    }
    const int switch_at = random.integer(0, substeps - 1);
    const double first = random.uniform(-1.5, 1.5) * p.max_angle_rad;
    const double second = random.uniform(-1.5, 1.5) * p.max_angle_rad;
    std::vector<double> inputs(substeps);
    for (int j = 0; j < substeps; ++j)
      inputs[static_cast<std::size_t>(j)] = j < switch_at ? first : second;
    std::ostringstream inputs_text;
    inputs_text.precision(17);
    inputs_text << describe(p) << "; start " << start[0] << ", " << start[1] << ", " << start[2]
                << "; input " << first << " then " << second << " from sub-step " << switch_at;
    const std::string context = seed_message(seed) + "; " + inputs_text.str();

    detail::ExactActuatorPeriod exact;
    ASSERT_TRUE(exact.solve(p, start, inputs.data(), substeps, substep_s)) << context;
    SteeringActuator fine(p, fine_step_s);
    fine.set_state(start);
    for (int j = 0; j < substeps; ++j) {
      for (int i = 0; i < fine_per_substep; ++i) fine.advance(inputs[static_cast<std::size_t>(j)]);
      const SteeringActuator::State x = exact.state((j + 1) * substep_s);
      for (std::size_t i = 0; i < 3; ++i) {
        ASSERT_NEAR(x[i], fine.state()[i], 1e-9)
            << "lag " << i << " at sub-step " << j << "; " << context;
      }
    }
    for (int i = 0; i < exact.segments(); ++i) {
      const detail::ActuatorMode mode = exact.segment_mode(i);
      if (mode != detail::ActuatorMode::linear) ++saturated_cases;
      if (mode == detail::ActuatorMode::angle_up || mode == detail::ActuatorMode::angle_down) {
        ++angle_cases;
      }
    }
  }
  // The random cases do reach both saturations (else the test would prove nothing); a replay
  // of one seed need not.
  if (property_cases() < 20) return;
  EXPECT_GT(saturated_cases, property_cases() / 4);
  EXPECT_GT(angle_cases, property_cases() / 20);
}

//! Open-loop held command a sin(2 pi f t) + b (steps of the offset every 0.7 s): fast enough to
//! exceed the rate limit, at times beyond the angle limit.
class SaturatingSteering final : public SteeringController {
 public:
  SaturatingSteering(double amplitude, double frequency_hz, double step)
      : amplitude_(amplitude), frequency_hz_(frequency_hz), step_(step) {}
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override {
    output = ControllerOutput{};
    const double offset = (static_cast<int>(t_ / 0.7) % 2 == 0) ? step_ : -step_;
    output.steering_angle_rad =
        amplitude_ * std::sin(2.0 * std::numbers::pi * frequency_hz_ * t_) + offset;
    t_ += input.period_s;
    return Status::ok;
  }
  Status reset(double) noexcept override {
    t_ = 0.0;
    return Status::ok;
  }
  const char* name() const noexcept override { return "saturating"; }

 private:
  double amplitude_, frequency_hz_, step_;
  double t_ = 0.0;
};

//! One random open-loop run that saturates the actuator's rate (and at times its angle), with a
//! speed ramp; the dead time cycles through 0, 10 and 30 ms with k.
struct SaturatingCase {
  ActuatorParameters actuator;
  double amplitude = 0.0, frequency = 0.0, step = 0.0;
  SpeedProfile speed;
  std::string text;  //!< seed and inputs, for failure messages

  SaturatingCase(std::uint64_t seed, int k) {
    Random random(seed);
    actuator.bandwidth_hz = random.uniform(3.0, 15.0);
    actuator.max_rate_radps = random.uniform(0.1, 0.6);
    actuator.max_angle_rad = random.uniform(0.08, 0.3);
    actuator.dead_time_s = std::array{0.0, 0.01, 0.03}[static_cast<std::size_t>(k % 3)];
    amplitude = random.uniform(0.05, 0.25);
    frequency = random.uniform(0.5, 2.0);
    // Toggling +-step through the lags peaks at a rate of 0.27 p 2 step > 0.6 rad/s: saturates.
    step = random.uniform(0.05, 0.15);
    // The ramp starts and ends inside control periods and 1 ms sub-steps, on a 0.1 ms grid: the
    // reference samples the acceleration at its sub-steps' midpoints, so a kink off its grid
    // would cost it O(h) in speed (1e-4 m in position after 4 s).
    const double initial = random.uniform(6.0, 15.0);
    const double final = initial + random.uniform(2.0, 5.0) * (random.coin() ? 1.0 : -1.0);
    const double ramp_start = 1e-4 * random.integer(3000, 15000);
    const double ramp_duration = 1e-4 * random.integer(5000, 30000);
    speed = SpeedProfile{initial, final, std::abs(final - initial) / ramp_duration, ramp_start};
    std::ostringstream out;
    out.precision(17);
    out << seed_message(seed) << "; " << describe(actuator) << "; command " << amplitude
        << " sin(2 pi " << frequency << " t) +- " << step << "; speed " << initial << " -> "
        << final << " at " << speed.acceleration_mps2 << " from " << ramp_start << " s";
    text = out.str();
  }

  SimulationResult run(PlantIntegrator integrator, double substep_s,
                       double tolerance = SimulationParameters{}.integrator_tolerance) const {
    static const VehicleParameters car;
    static const DynamicSingleTrack model(car);
    static const Path path = Path::straight_line({0, 0}, 0.0, 500.0);
    SimulationParameters sim;
    sim.duration_s = 4.0;
    sim.substep_s = substep_s;
    sim.integrator = integrator;
    sim.integrator_tolerance = tolerance;
    SaturatingSteering controller(amplitude, frequency, step);
    return simulate(path, model, actuator, speed, sim, {{0.0, 0.0}, 0.0}, controller);
  }
};

//! Largest differences of two runs' traces at the control instants.
struct Deviation {
  double position_m = 0.0, heading_rad = 0.0, steering_rad = 0.0;
};
Deviation deviation(const SimulationResult& a, const SimulationResult& b) {
  Deviation d;
  for (std::size_t i = 0; i < std::min(a.trace.size(), b.trace.size()); ++i) {
    const TraceSample& x = a.trace[i];
    const TraceSample& y = b.trace[i];
    d.position_m = std::max(d.position_m, norm(x.rear_axle.position - y.rear_axle.position));
    d.heading_rad =
        std::max(d.heading_rad, std::abs(x.rear_axle.heading_rad - y.rear_axle.heading_rad));
    d.steering_rad =
        std::max(d.steering_rad, std::abs(x.steering_actual_rad - y.steering_actual_rad));
  }
  return d;
}

bool adaptive_available() {
  SimulationParameters adaptive;
  adaptive.integrator = PlantIntegrator::rkf78;
  return adaptive.is_valid();
}

TEST(ExactActuator, AdaptivePlantMatchesFineRk4UnderSaturation) {
  if (!adaptive_available()) GTEST_SKIP() << "built without Boost.Odeint";
  const int cases = std::max(3, property_cases() / 4);  // three simulations per case
  for (int k = 0; k < cases; ++k) {
    const SaturatingCase c(case_seed(k), k);
    const SimulationResult fine = c.run(PlantIntegrator::fixed_rk4, 0.00005);
    const double rk4_evaluations = 80.0 * static_cast<double>(fine.trace.size() - 1);
    bool saturated = false;
    for (const TraceSample& sample : fine.trace) {
      saturated |= std::abs(sample.steering_actual_rate_radps) >= 0.999 * c.actuator.max_rate_radps;
    }
    EXPECT_TRUE(saturated) << c.text;
    for (PlantIntegrator integrator : {PlantIntegrator::rkf78, PlantIntegrator::dopri5}) {
      // At 1e-8 the vehicle's integration error stays far below the reference's; the default
      // tolerance is checked against RK4 at 10 us below.
      const SimulationResult result = c.run(integrator, 0.001, 1e-8);
      const std::string context =
          c.text + "; integrator " + std::to_string(static_cast<int>(integrator));
      ASSERT_EQ(result.trace.size(), fine.trace.size()) << context;
      // RK4 at 0.1 ms is itself up to 2.8e-4 m, 1.2e-5 rad in heading and 1e-6 rad in steering
      // from RK4 at 10 us in these runs (its error at the saturation's kinks), at 0.05 ms about
      // a quarter of that; rkf78 and dopri5 stay within 3e-6 m and 6e-9 rad of RK4 at 10 us
      // (ExactActuator.AdaptivePlantMatchesConvergedRk4).
      const Deviation d = deviation(result, fine);
      EXPECT_LT(d.position_m, 2e-4) << context;
      EXPECT_LT(d.heading_rad, 1e-5) << context;
      EXPECT_LT(d.steering_rad, 2e-6) << context;
      // No period falls back to RK4, and even with a saturation in most periods (a restart at
      // each of its ends) over 1.5 times fewer evaluations than RK4 at 1 ms (rkf78 and dopri5
      // need 2-4 times fewer here; 5-6 times on the shipped scenarios).
      EXPECT_EQ(result.plant_fallback_periods, 0U) << context;
      EXPECT_LT(1.5 * static_cast<double>(result.model_evaluations), rk4_evaluations) << context;
    }
  }
}

TEST(ExactActuator, AdaptivePlantMatchesConvergedRk4) {
  if (!adaptive_available()) GTEST_SKIP() << "built without Boost.Odeint";
  // At a tolerance of 1e-8 the adaptive runs converge on RK4 at 10 us; at the default (1e-6)
  // they stay within 1e-4 m, far below the 1 mm the shipped scenarios' metrics are held to.
  // The steering angle does not depend on the tolerance (the actuator is solved exactly).
  struct Setting {
    double tolerance, position_m, heading_rad;
  };
  const double default_tolerance = SimulationParameters{}.integrator_tolerance;
  for (const Setting setting :
       {Setting{1e-8, 1e-5, 1e-6}, Setting{default_tolerance, 1e-4, 1e-5}}) {
    for (int k = 0; k < 3; ++k) {  // dead times 0, 10 and 30 ms
      const SaturatingCase c(case_seed(k), k);
      const SimulationResult converged = c.run(PlantIntegrator::fixed_rk4, 0.00001);
      for (PlantIntegrator integrator : {PlantIntegrator::rkf78, PlantIntegrator::dopri5}) {
        const Deviation d = deviation(c.run(integrator, 0.001, setting.tolerance), converged);
        const std::string context = c.text + "; integrator " +
                                    std::to_string(static_cast<int>(integrator)) + ", tolerance " +
                                    std::to_string(setting.tolerance);
        EXPECT_LT(d.position_m, setting.position_m) << context;
        EXPECT_LT(d.heading_rad, setting.heading_rad) << context;
        EXPECT_LT(d.steering_rad, 1e-8) << context;
      }
    }
  }
}

}  // namespace
}  // namespace smoothsteer
