#include "smoothsteer/sim/metrics.hpp"

#include <algorithm>
#include <cmath>

namespace smoothsteer {
namespace {

//! Population standard deviation and maximum of |x| (Welford).
struct Spread {
  long count = 0;
  double mean = 0.0, m2 = 0.0, max_abs = 0.0;
  void add(double x) {
    ++count;
    const double delta = x - mean;
    mean += delta / static_cast<double>(count);
    m2 += delta * (x - mean);
    max_abs = std::max(max_abs, std::abs(x));
  }
  double std_dev() const { return count > 0 ? std::sqrt(m2 / static_cast<double>(count)) : 0.0; }
};

bool exceeds(double value, double limit, double tolerance) {
  return std::isfinite(limit) && std::abs(value) > limit * (1.0 + tolerance);
}

int count_non_finite(const TraceSample& s) {
  const auto values = trace_row(s);
  int count = 0;
  for (double v : values) count += std::isfinite(v) ? 0 : 1;
  return count;
}

}  // namespace

std::string MetricsParameters::validation_error() const {
  if (!std::isfinite(reaching_threshold_m) || reaching_threshold_m <= 0.0) {
    return "MetricsParameters: reaching_threshold_m = " + std::to_string(reaching_threshold_m) +
           " must be finite and > 0";
  }
  if (!(steering_angle_limit_rad > 0.0)) {
    return "MetricsParameters: steering_angle_limit_rad = " +
           std::to_string(steering_angle_limit_rad) + " must be > 0";
  }
  if (!(steering_rate_limit_radps > 0.0)) {
    return "MetricsParameters: steering_rate_limit_radps = " +
           std::to_string(steering_rate_limit_radps) + " must be > 0";
  }
  if (!(steering_acceleration_limit_radps2 > 0.0)) {
    return "MetricsParameters: steering_acceleration_limit_radps2 = " +
           std::to_string(steering_acceleration_limit_radps2) + " must be > 0";
  }
  if (!std::isfinite(violation_tolerance) || violation_tolerance < 0.0) {
    return "MetricsParameters: violation_tolerance = " + std::to_string(violation_tolerance) +
           " must be finite and >= 0";
  }
  return {};
}

Metrics compute_metrics(const std::vector<TraceSample>& trace, const MetricsParameters& p) {
  Metrics m;
  m.steps = static_cast<int>(trace.size());
  if (trace.empty()) return m;
  m.duration_s = trace.back().time_s;
  m.distance_m = trace.back().distance_m;
  m.final_abs_rear_error_m = std::abs(trace.back().lateral_error_m);

  // Reaching index: one past the last sample with |e_lead| >= threshold.
  std::size_t first_reached = trace.size();
  for (std::size_t i = trace.size(); i-- > 0;) {
    if (!(std::abs(trace[i].lead_lateral_error_m) < p.reaching_threshold_m)) break;
    first_reached = i;
  }
  m.reached = first_reached < trace.size();
  if (m.reached) {
    m.reaching_time_s = trace[first_reached].time_s;
    m.reaching_distance_m = trace[first_reached].distance_m;
    m.max_abs_lead_error_after_reaching_m = 0.0;
    m.max_abs_front_error_after_reaching_m = 0.0;
    m.max_abs_rear_error_after_reaching_m = 0.0;
  }

  Spread command_rate, command_acceleration, actual_rate, actual_acceleration;
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const TraceSample& s = trace[i];
    m.non_finite_values += count_non_finite(s);
    m.max_abs_rear_error_m = std::max(m.max_abs_rear_error_m, std::abs(s.lateral_error_m));
    m.max_abs_front_error_m = std::max(m.max_abs_front_error_m, std::abs(s.front_lateral_error_m));
    m.max_abs_lead_error_m = std::max(m.max_abs_lead_error_m, std::abs(s.lead_lateral_error_m));
    if (m.reached && i >= first_reached) {
      m.max_abs_lead_error_after_reaching_m =
          std::max(m.max_abs_lead_error_after_reaching_m, std::abs(s.lead_lateral_error_m));
      m.max_abs_front_error_after_reaching_m =
          std::max(m.max_abs_front_error_after_reaching_m, std::abs(s.front_lateral_error_m));
      m.max_abs_rear_error_after_reaching_m =
          std::max(m.max_abs_rear_error_after_reaching_m, std::abs(s.lateral_error_m));
    }
    command_rate.add(s.steering_command_rate_radps);
    command_acceleration.add(s.steering_command_acceleration_radps2);
    actual_rate.add(s.steering_actual_rate_radps);
    actual_acceleration.add(s.steering_actual_acceleration_radps2);
    m.max_abs_command_rad = std::max(m.max_abs_command_rad, std::abs(s.steering_command_rad));
    m.max_abs_actual_rad = std::max(m.max_abs_actual_rad, std::abs(s.steering_actual_rad));
    m.max_abs_side_slip_rad = std::max(m.max_abs_side_slip_rad, std::abs(s.side_slip_rad));
    const bool angle =
        exceeds(s.steering_command_rad, p.steering_angle_limit_rad, p.violation_tolerance);
    const bool rate =
        exceeds(s.steering_command_rate_radps, p.steering_rate_limit_radps, p.violation_tolerance);
    const bool acceleration = exceeds(s.steering_command_acceleration_radps2,
                                      p.steering_acceleration_limit_radps2, p.violation_tolerance);
    m.angle_violations += angle ? 1 : 0;
    m.rate_violations += rate ? 1 : 0;
    m.acceleration_violations += acceleration ? 1 : 0;
    m.bound_violations += (angle || rate || acceleration) ? 1 : 0;
  }
  m.command_rate_std_radps = command_rate.std_dev();
  m.command_rate_max_radps = command_rate.max_abs;
  m.command_acceleration_std_radps2 = command_acceleration.std_dev();
  m.command_acceleration_max_radps2 = command_acceleration.max_abs;
  m.actual_rate_std_radps = actual_rate.std_dev();
  m.actual_rate_max_radps = actual_rate.max_abs;
  m.actual_acceleration_std_radps2 = actual_acceleration.std_dev();
  m.actual_acceleration_max_radps2 = actual_acceleration.max_abs;
  return m;
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
          {"angle_violations", m.angle_violations},
          {"rate_violations", m.rate_violations},
          {"acceleration_violations", m.acceleration_violations},
          {"bound_violations", m.bound_violations},
          {"non_finite_values", m.non_finite_values}};
}

}  // namespace smoothsteer
