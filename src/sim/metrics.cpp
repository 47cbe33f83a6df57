#include "smoothsteer/sim/metrics.hpp"

#include <algorithm>
#include <cmath>

namespace smoothsteer {
namespace {

bool exceeds(double value, double limit, double tolerance) {
  return std::isfinite(limit) && std::abs(value) > limit * (1.0 + tolerance);
}

int count_non_finite(const TraceSample& s) {
  const auto values = trace_values(s);
  int count = 0;
  for (double v : values) count += std::isfinite(v) ? 0 : 1;
  return count;
}

}  // namespace

std::optional<Violation> MetricsParameters::first_violation() const noexcept {
  auto bad = [](const char* field, double value, const char* rule) {
    return Violation{"MetricsParameters", "", field, value, rule};
  };
  if (!std::isfinite(reaching_threshold_m) || reaching_threshold_m <= 0.0) {
    return bad("reaching_threshold_m", reaching_threshold_m, "must be finite and > 0");
  }
  if (!(steering_angle_limit_rad > 0.0)) {
    return bad("steering_angle_limit_rad", steering_angle_limit_rad, "must be > 0");
  }
  if (!(steering_rate_limit_radps > 0.0)) {
    return bad("steering_rate_limit_radps", steering_rate_limit_radps, "must be > 0");
  }
  if (!(steering_acceleration_limit_radps2 > 0.0)) {
    return bad("steering_acceleration_limit_radps2", steering_acceleration_limit_radps2,
               "must be > 0");
  }
  if (!std::isfinite(violation_tolerance) || violation_tolerance < 0.0) {
    return bad("violation_tolerance", violation_tolerance, "must be finite and >= 0");
  }
  if (!(friction_limit_mps2 > 0.0)) {
    return bad("friction_limit_mps2", friction_limit_mps2, "must be > 0 (+inf: not counted)");
  }
  return std::nullopt;
}

std::string MetricsParameters::validation_error() const {
  return describe(first_violation());
}

void MetricsParameters::validate() const {
  throw_if_violated(first_violation());
}

void MetricsAccumulator::Spread::add(double x) {  // Welford
  ++count;
  const double delta = x - mean;
  mean += delta / static_cast<double>(count);
  m2 += delta * (x - mean);
  sum_squares += x * x;
  max_abs = std::max(max_abs, std::abs(x));
}

double MetricsAccumulator::Spread::std_dev() const {
  return count > 0 ? std::sqrt(m2 / static_cast<double>(count)) : 0.0;
}

double MetricsAccumulator::Spread::rms() const {
  return count > 0 ? std::sqrt(sum_squares / static_cast<double>(count)) : 0.0;
}

MetricsAccumulator::MetricsAccumulator(const MetricsParameters& parameters)
    : parameters_(parameters) {}

void MetricsAccumulator::add(const TraceSample& s) {
  const MetricsParameters& p = parameters_;
  const long index = m_.steps++;
  m_.duration_s = s.time_s;
  m_.distance_m = s.distance_m;
  m_.final_abs_rear_error_m = std::abs(s.lateral_error_m);
  m_.non_finite_values += count_non_finite(s);
  m_.max_abs_rear_error_m = std::max(m_.max_abs_rear_error_m, std::abs(s.lateral_error_m));
  rear_error_.add(s.lateral_error_m);
  m_.max_abs_front_error_m = std::max(m_.max_abs_front_error_m, std::abs(s.front_lateral_error_m));
  m_.max_abs_lead_error_m = std::max(m_.max_abs_lead_error_m, std::abs(s.lead_lateral_error_m));

  // Reaching: the candidate index restarts after every sample with |e_lead| >= threshold; the
  // "after reaching" maxima cover the samples since the candidate.
  if (!(std::abs(s.lead_lateral_error_m) < p.reaching_threshold_m)) {
    first_reached_ = index + 1;
  } else {
    if (index == first_reached_) {
      m_.reaching_time_s = s.time_s;
      m_.reaching_distance_m = s.distance_m;
      m_.max_abs_lead_error_after_reaching_m = 0.0;
      m_.max_abs_front_error_after_reaching_m = 0.0;
      m_.max_abs_rear_error_after_reaching_m = 0.0;
    }
    m_.max_abs_lead_error_after_reaching_m =
        std::max(m_.max_abs_lead_error_after_reaching_m, std::abs(s.lead_lateral_error_m));
    m_.max_abs_front_error_after_reaching_m =
        std::max(m_.max_abs_front_error_after_reaching_m, std::abs(s.front_lateral_error_m));
    m_.max_abs_rear_error_after_reaching_m =
        std::max(m_.max_abs_rear_error_after_reaching_m, std::abs(s.lateral_error_m));
  }

  command_rate_.add(s.steering_command_rate_radps);
  command_acceleration_.add(s.steering_command_acceleration_radps2);
  actual_rate_.add(s.steering_actual_rate_radps);
  actual_acceleration_.add(s.steering_actual_acceleration_radps2);
  m_.max_abs_command_rad = std::max(m_.max_abs_command_rad, std::abs(s.steering_command_rad));
  m_.max_abs_actual_rad = std::max(m_.max_abs_actual_rad, std::abs(s.steering_actual_rad));
  m_.max_abs_side_slip_rad = std::max(m_.max_abs_side_slip_rad, std::abs(s.side_slip_rad));
  m_.max_abs_rear_slip_input_error_rad =
      std::max(m_.max_abs_rear_slip_input_error_rad,
               std::abs(s.rear_side_slip_rad - s.rear_side_slip_input_rad));
  const double path_demand = s.speed_mps * s.speed_mps * std::abs(s.path_curvature);
  m_.max_path_lateral_acceleration_mps2 =
      std::max(m_.max_path_lateral_acceleration_mps2, path_demand);
  m_.path_friction_exceedances += path_demand > p.friction_limit_mps2 ? 1 : 0;
  const double tolerance = p.violation_tolerance;
  const bool angle = exceeds(s.steering_command_rad, p.steering_angle_limit_rad, tolerance);
  const bool rate = exceeds(s.steering_command_rate_radps, p.steering_rate_limit_radps, tolerance);
  const bool acceleration = exceeds(s.steering_command_acceleration_radps2,
                                    p.steering_acceleration_limit_radps2, tolerance);
  m_.angle_violations += angle ? 1 : 0;
  m_.rate_violations += rate ? 1 : 0;
  m_.acceleration_violations += acceleration ? 1 : 0;
  m_.bound_violations += (angle || rate || acceleration) ? 1 : 0;
  m_.actual_rate_violations +=
      exceeds(s.steering_actual_rate_radps, p.steering_rate_limit_radps, tolerance) ? 1 : 0;
  m_.actual_acceleration_violations += exceeds(s.steering_actual_acceleration_radps2,
                                               p.steering_acceleration_limit_radps2, tolerance)
                                           ? 1
                                           : 0;

  // Held command: differences over the control period (the spacing of the samples).
  if (index >= 1 && s.time_s > last_time_s_) {
    const double period = s.time_s - last_time_s_;
    const double held_rate = (s.steering_command_rad - last_command_rad_) / period;
    held_rate_.add(held_rate);
    m_.held_rate_violations += exceeds(held_rate, p.steering_rate_limit_radps, tolerance) ? 1 : 0;
    if (index >= 2) {
      const double held_acceleration = (held_rate - last_held_rate_radps_) / period;
      held_acceleration_.add(held_acceleration);
      m_.held_acceleration_violations +=
          exceeds(held_acceleration, p.steering_acceleration_limit_radps2, tolerance) ? 1 : 0;
    }
    last_held_rate_radps_ = held_rate;
  }
  last_time_s_ = s.time_s;
  last_command_rad_ = s.steering_command_rad;
}

Metrics MetricsAccumulator::result() const {
  Metrics m = m_;
  m.reached = m.steps > 0 && first_reached_ < m.steps;
  if (!m.reached) {
    m.reaching_time_s = -1.0;
    m.reaching_distance_m = -1.0;
    m.max_abs_lead_error_after_reaching_m = -1.0;
    m.max_abs_front_error_after_reaching_m = -1.0;
    m.max_abs_rear_error_after_reaching_m = -1.0;
  }
  m.command_rate_std_radps = command_rate_.std_dev();
  m.command_rate_max_radps = command_rate_.max_abs;
  m.command_acceleration_std_radps2 = command_acceleration_.std_dev();
  m.command_acceleration_max_radps2 = command_acceleration_.max_abs;
  m.actual_rate_std_radps = actual_rate_.std_dev();
  m.actual_rate_max_radps = actual_rate_.max_abs;
  m.actual_acceleration_std_radps2 = actual_acceleration_.std_dev();
  m.actual_acceleration_max_radps2 = actual_acceleration_.max_abs;
  m.actual_rate_rms_radps = actual_rate_.rms();
  m.actual_acceleration_rms_radps2 = actual_acceleration_.rms();
  m.held_rate_rms_radps = held_rate_.rms();
  m.held_rate_max_radps = held_rate_.max_abs;
  m.held_acceleration_rms_radps2 = held_acceleration_.rms();
  m.held_acceleration_max_radps2 = held_acceleration_.max_abs;
  m.rms_rear_error_m = rear_error_.rms();
  return m;
}

Metrics compute_metrics(const std::vector<TraceSample>& trace, const MetricsParameters& p) {
  MetricsAccumulator accumulator(p);
  for (const TraceSample& sample : trace) accumulator.add(sample);
  return accumulator.result();
}

std::vector<std::pair<std::string, double>> metric_values(const Metrics& m) {
  return {{"steps", m.steps},
          {"duration_s", m.duration_s},
          {"distance_m", m.distance_m},
          {"reached", m.reached ? 1.0 : 0.0},
          {"reaching_time_s", m.reaching_time_s},
          {"reaching_distance_m", m.reaching_distance_m},
          {"max_abs_lead_error_after_reaching_m", m.max_abs_lead_error_after_reaching_m},
          {"max_abs_front_error_after_reaching_m", m.max_abs_front_error_after_reaching_m},
          {"max_abs_rear_error_after_reaching_m", m.max_abs_rear_error_after_reaching_m},
          {"max_abs_rear_error_m", m.max_abs_rear_error_m},
          {"max_abs_front_error_m", m.max_abs_front_error_m},
          {"max_abs_lead_error_m", m.max_abs_lead_error_m},
          {"final_abs_rear_error_m", m.final_abs_rear_error_m},
          {"command_rate_std_radps", m.command_rate_std_radps},
          {"command_rate_max_radps", m.command_rate_max_radps},
          {"command_acceleration_std_radps2", m.command_acceleration_std_radps2},
          {"command_acceleration_max_radps2", m.command_acceleration_max_radps2},
          {"actual_rate_std_radps", m.actual_rate_std_radps},
          {"actual_rate_max_radps", m.actual_rate_max_radps},
          {"actual_acceleration_std_radps2", m.actual_acceleration_std_radps2},
          {"actual_acceleration_max_radps2", m.actual_acceleration_max_radps2},
          {"max_abs_command_rad", m.max_abs_command_rad},
          {"max_abs_actual_rad", m.max_abs_actual_rad},
          {"max_abs_side_slip_rad", m.max_abs_side_slip_rad},
          {"max_abs_rear_slip_input_error_rad", m.max_abs_rear_slip_input_error_rad},
          {"max_path_lateral_acceleration_mps2", m.max_path_lateral_acceleration_mps2},
          {"path_friction_exceedances", m.path_friction_exceedances},
          {"angle_violations", m.angle_violations},
          {"rate_violations", m.rate_violations},
          {"acceleration_violations", m.acceleration_violations},
          {"bound_violations", m.bound_violations},
          {"non_finite_values", m.non_finite_values},
          {"held_rate_rms_radps", m.held_rate_rms_radps},
          {"held_rate_max_radps", m.held_rate_max_radps},
          {"held_acceleration_rms_radps2", m.held_acceleration_rms_radps2},
          {"held_acceleration_max_radps2", m.held_acceleration_max_radps2},
          {"held_rate_violations", m.held_rate_violations},
          {"held_acceleration_violations", m.held_acceleration_violations},
          {"actual_rate_rms_radps", m.actual_rate_rms_radps},
          {"actual_acceleration_rms_radps2", m.actual_acceleration_rms_radps2},
          {"actual_rate_violations", m.actual_rate_violations},
          {"actual_acceleration_violations", m.actual_acceleration_violations},
          {"rms_rear_error_m", m.rms_rear_error_m}};
}

}  // namespace smoothsteer
