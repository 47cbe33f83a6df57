// Plant integration over one control period (src/sim/plant_integration.hpp).

#include "plant_integration.hpp"

#include <algorithm>
#include <cmath>

#include "exact_actuator.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

#if SMOOTHSTEER_HAS_ODEINT
#include "odeint.hpp"
#endif

// Boost.Odeint copies default-constructed temporaries of its steppers (GCC 12 false positive).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace smoothsteer::detail {
namespace {

using PlantArray = std::array<double, VehicleState::size>;

VehicleState derivative(const PlantContext& c, const VehicleState& s, double delta,
                        double acceleration, double t) noexcept {
  if (c.model_evaluations) ++*c.model_evaluations;
  return plant_derivative(c, s, delta, acceleration, t);
}

//! Speed of the rear axle from the state and its derivative (model-independent: the kinematic
//! model keeps vy and r algebraic).
double rear_axle_speed(const VehicleState& s, const VehicleState& d, double lr) noexcept {
  const double vx = d.x_m + lr * d.heading_rad * std::sin(s.heading_rad);
  const double vy = d.y_m - lr * d.heading_rad * std::cos(s.heading_rad);
  return std::hypot(vx, vy);
}

// ---- fixed: RK4 at the sub-step (the method of earlier releases) ----

VehicleState rk4_step(const PlantContext& c, const VehicleState& state, double time, double h,
                      double delta_start, double delta_end, double acceleration) noexcept {
  const PlantArray x = state.to_array();
  auto eval = [&](const PlantArray& y, double fraction) {
    const double delta = delta_start + fraction * (delta_end - delta_start);
    return derivative(c, VehicleState::from_array(y), delta, acceleration, time + 0.5 * h)
        .to_array();
  };
  auto shifted = [&](const PlantArray& k, double scale) {
    PlantArray y = x;
    for (std::size_t i = 0; i < y.size(); ++i) y[i] += scale * k[i];
    return y;
  };
  const PlantArray k1 = eval(x, 0.0);
  const PlantArray k2 = eval(shifted(k1, 0.5 * h), 0.5);
  const PlantArray k3 = eval(shifted(k2, 0.5 * h), 0.5);
  const PlantArray k4 = eval(shifted(k3, h), 1.0);
  PlantArray next = x;
  for (std::size_t i = 0; i < next.size(); ++i) {
    next[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  }
  return VehicleState::from_array(next);
}

//! One sub-step with the delayed input already taken from the delay line.
void fixed_substep(const PlantContext& c, double time, double delayed, VehicleState& state,
                   double& distance) noexcept {
  const double h = c.substep_s;
  const VehicleParameters& car = c.model.parameters();
  SteeringActuator& actuator = c.actuator;
  const double delta_start = plant_steering_angle(c, actuator.angle());
  if (actuator.parameters().ideal) {
    actuator.set_state({delayed, delayed, delayed});
  } else {
    actuator.advance(delayed);
  }
  const double delta_end = plant_steering_angle(c, actuator.angle());
  const double acceleration = c.speed.acceleration(time + 0.5 * h);
  const VehicleState before = state;
  state = rk4_step(c, state, time, h, actuator.parameters().ideal ? delta_end : delta_start,
                   delta_end, acceleration);
  c.model.constrain(state, delta_end);
  const double rear_vy_before = before.vy_mps - car.cg_to_rear_axle_m * before.yaw_rate_radps;
  const double rear_vy_after = state.vy_mps - car.cg_to_rear_axle_m * state.yaw_rate_radps;
  distance += 0.5 * h *
              (std::hypot(before.vx_mps, rear_vy_before) + std::hypot(state.vx_mps, rear_vy_after));
}

// ---- adaptive: exact actuator + an embedded Runge-Kutta pair with error control ----

using AdaptiveState = std::array<double, VehicleState::size + 1>;  // vehicle + distance

//! Integrates vehicle and distance over [from, to] with delta(t) = delta_of(t - origin) and the
//! speed profile's acceleration, constant on the piece, with error control (absolute
//! tolerance), restarted here: no state carries over. The acceleration is held constant (taken
//! at the midpoint) because a jump of it at a stage time is invisible to Fehlberg 7(8)'s error
//! estimate, which compares stages at equal times (a quadrature-type error).
template <typename DeltaOf>
void solve_piece(const PlantContext& c, double origin, double from, double to,
                 const DeltaOf& delta_of, VehicleState& state, double& distance) noexcept {
#if SMOOTHSTEER_HAS_ODEINT
  namespace odeint = boost::numeric::odeint;
#endif
  const double lr = c.model.parameters().cg_to_rear_axle_m;
  const double acceleration = c.speed.acceleration(0.5 * (from + to));
  auto system = [&](const AdaptiveState& y, AdaptiveState& dydt, double t) {
    PlantArray x;
    std::copy_n(y.begin(), x.size(), x.begin());
    const VehicleState s = VehicleState::from_array(x);
    const VehicleState d = derivative(c, s, plant_steering_angle(c, delta_of(t - origin)),
                                      acceleration, 0.5 * (from + to));
    const PlantArray dx = d.to_array();
    std::copy(dx.begin(), dx.end(), dydt.begin());
    dydt.back() = rear_axle_speed(s, d, lr);
  };
  AdaptiveState y;
  const PlantArray x = state.to_array();
  std::copy(x.begin(), x.end(), y.begin());
  y.back() = distance;
#if !SMOOTHSTEER_HAS_ODEINT
  // Built without Boost: SimulationParameters rejects rkf78 / dopri5, so this is unreachable;
  // classic RK4 over the piece keeps it well defined.
  const double h = to - from;
  AdaptiveState k1, k2, k3, k4, tmp;
  auto shifted = [&](const AdaptiveState& k, double scale) {
    for (std::size_t i = 0; i < y.size(); ++i) tmp[i] = y[i] + scale * k[i];
    return tmp;
  };
  system(y, k1, from);
  system(shifted(k1, 0.5 * h), k2, from + 0.5 * h);
  system(shifted(k2, 0.5 * h), k3, from + 0.5 * h);
  system(shifted(k3, h), k4, to);
  for (std::size_t i = 0; i < y.size(); ++i)
    y[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
#else
  if (c.integrator == PlantIntegrator::dopri5) {
    auto stepper =
        odeint::make_controlled(c.tolerance, 0.0, odeint::runge_kutta_dopri5<AdaptiveState>());
    odeint::integrate_adaptive(stepper, system, y, from, to, to - from);
  } else {
    auto stepper =
        odeint::make_controlled(c.tolerance, 0.0, odeint::runge_kutta_fehlberg78<AdaptiveState>());
    odeint::integrate_adaptive(stepper, system, y, from, to, to - from);
  }
#endif
  PlantArray next;
  std::copy_n(y.begin(), next.size(), next.begin());
  state = VehicleState::from_array(next);
  distance = y.back();
}

//! Instants inside a period where the right-hand side is not smooth (offsets from its start).
struct Kinks {
  //! Room for the actuator's mode changes, the ramp's two ends and up to 16 knots of a
  //! tabulated speed profile (more are not split at: their acceleration is then taken at the
  //! middle of the piece).
  std::array<double, ExactActuatorPeriod::max_segments + 2 + 16> at{};
  int count = 0;
  void add(double offset) noexcept {
    if (count < static_cast<int>(at.size())) at[static_cast<std::size_t>(count++)] = offset;
  }
};

//! [t0, t0 + h], split where the speed profile's ramp starts or ends and at `kinks` (offsets):
//! the error estimate of an embedded pair cannot be trusted across a kink of the right-hand
//! side (Fehlberg 7(8)'s compares only its stages at the step's two ends).
template <typename DeltaOf>
void solve_adaptive(const PlantContext& c, double t0, double h, const DeltaOf& delta_of,
                    VehicleState& state, double& distance, Kinks kinks = {}) noexcept {
  if (c.speed.ramp_duration_s() > 0.0) {
    kinks.add(c.speed.start_time_s - t0);
    kinks.add(c.speed.start_time_s + c.speed.ramp_duration_s() - t0);
  }
  if (c.side_force.active()) kinks.add(c.side_force.start_s - t0);  // the gust's step
  if (c.speed.knots) {  // the knots of a tabulated profile inside the period
    const std::vector<SpeedKnot>& knots = *c.speed.knots;
    std::size_t i = c.speed.knot_interval(t0);
    if (i == SpeedProfile::no_interval) i = t0 < knots.front().time_s ? 0 : knots.size();
    for (++i; i < knots.size() && knots[i].time_s < t0 + h; ++i) kinks.add(knots[i].time_s - t0);
  }
  std::sort(kinks.at.begin(), kinks.at.begin() + kinks.count);
  // Kinks closer than a nanosecond to an end or to each other are one (k * T rounds off).
  constexpr double snap_s = 1e-9;
  double from = 0.0;
  for (int i = 0; i < kinks.count; ++i) {
    const double kink = kinks.at[static_cast<std::size_t>(i)];
    if (kink > from + snap_s && kink < h - snap_s) {
      solve_piece(c, t0, t0 + from, t0 + kink, delta_of, state, distance);
      from = kink;
    }
  }
  solve_piece(c, t0, t0 + from, t0 + h, delta_of, state, distance);
  c.model.constrain(state, plant_steering_angle(c, delta_of(h)));
}

}  // namespace

double plant_steering_angle(const PlantContext& c, double delta) noexcept {
  delta += c.steering_offset_rad;
  if (c.plant_disturbance == 0.0) return delta;
  return disturbed_steering_angle(delta, c.model.parameters().wheelbase_m(), c.plant_disturbance);
}

BodyAcceleration body_acceleration(const PlantContext& c, const VehicleState& s, double t,
                                   bool with_crossfall) noexcept {
  // Forces on the body, which the tires carry; the double track's roll does not see them.
  const VehicleParameters& p = c.model.parameters();
  const double kinetic = std::clamp(
      (s.vx_mps - p.kinematic_below_mps) / (p.kinetic_above_mps - p.kinematic_below_mps), 0.0, 1.0);
  BodyAcceleration a;
  if (with_crossfall) a.lateral = c.crossfall_acceleration_mps2;
  if (c.side_force.active() && t >= c.side_force.start_s) {
    a.lateral += c.side_force.force_n / p.mass_kg;
    a.yaw = c.side_force.yaw_moment_nm / p.yaw_inertia_kgm2;
  }
  a.lateral *= kinetic;
  a.yaw *= kinetic;
  return a;
}

VehicleState plant_derivative(const PlantContext& c, const VehicleState& s, double delta,
                              double acceleration, double t) noexcept {
  VehicleState d = c.model.derivative(s, delta, acceleration);
  if (!c.external()) return d;
  const BodyAcceleration a = body_acceleration(c, s, t, true);
  d.vy_mps += a.lateral;
  d.yaw_rate_radps += a.yaw;
  return d;
}

double advance_plant(const PlantContext& c, double t, double command, VehicleState& state,
                     double& distance_m) noexcept {
  SteeringActuator& actuator = c.actuator;
  double* const inputs = c.input_buffer;  // delayed input of every sub-step
  for (int j = 0; j < c.substeps; ++j) {
    inputs[j] = actuator.push_command(command);
  }
  const double last_input = inputs[c.substeps - 1];
  auto fixed = [&] {
    for (int j = 0; j < c.substeps; ++j) {
      fixed_substep(c, t + j * c.substep_s, inputs[j], state, distance_m);
    }
  };
  if (c.integrator == PlantIntegrator::fixed_rk4) {
    fixed();
    return last_input;
  }
  const double period = c.substep_s * c.substeps;
  const ActuatorParameters& p = actuator.parameters();
  if (p.ideal) {  // delta = delayed input; one solve per stretch of constant input
    int begin = 0;
    for (int j = 1; j <= c.substeps; ++j) {
      if (j < c.substeps && inputs[j] == inputs[begin]) continue;
      const double u = inputs[begin];
      solve_adaptive(
          c, t + begin * c.substep_s, (j - begin) * c.substep_s, [u](double) { return u; }, state,
          distance_m);
      begin = j;
    }
    actuator.set_state({last_input, last_input, last_input});
    return last_input;
  }
  // The actuator solved exactly, saturation included (exact_actuator.hpp). Its output is C^2
  // across a jump of the input, so the adaptive solve runs across those, reading delta(t) from
  // the exact solution; where a saturation begins or ends (delta' or delta'' jumps) it restarts.
  ExactActuatorPeriod exact;
  if (!exact.solve(p, actuator.state(), inputs, c.substeps, c.substep_s)) {
    if (c.fallback_periods) ++*c.fallback_periods;
    fixed();  // more segments than fit (not reached in practice): the reference method
    return last_input;
  }
  Kinks kinks;
  for (int i = 1; i < exact.segments(); ++i) {
    if (exact.segment_mode(i) != exact.segment_mode(i - 1)) kinks.add(exact.segment_start(i));
  }
  solve_adaptive(
      c, t, period, [&exact](double tau) { return exact.angle(tau); }, state, distance_m, kinks);
  actuator.set_state(exact.state(period));
  return last_input;
}

}  // namespace smoothsteer::detail
