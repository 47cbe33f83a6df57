#pragma once
//! \file metrics.hpp
//! Performance indicators of a closed-loop run (paper Sec. IV-A). Every definition is written
//! down in docs/metrics.md; metric_values() lists them under their documented names.

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "smoothsteer/sim/simulation.hpp"

namespace smoothsteer {

struct MetricsParameters {
  //! The path counts as reached at the first control step after which |e_lead| stays below
  //! this threshold until the end of the run [m].
  double reaching_threshold_m = 0.1;
  double steering_angle_limit_rad = 1.066;  //!< bound counted by angle_violations [rad]
  double steering_rate_limit_radps = 0.4;   //!< bound counted by rate_violations [rad/s]
  //! Bound counted by acceleration_violations [rad/s^2]; infinity = not counted.
  double steering_acceleration_limit_radps2 = std::numeric_limits<double>::infinity();
  //! Relative tolerance of the bound checks (a command exactly at the bound is no violation).
  double violation_tolerance = 1e-6;
  //! Friction limit mu g [m/s^2] against which the path's own demand v^2 |kappa| is counted
  //! (+inf: not counted).
  double friction_limit_mps2 = std::numeric_limits<double>::infinity();

  //! The first rule broken (validation.hpp); is_valid(), validation_error(), validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  std::string validation_error() const;
  void validate() const;  //!< throws std::invalid_argument
};

struct Metrics {
  int steps = 0;            //!< control steps in the trace
  double duration_s = 0.0;  //!< time of the last sample
  double distance_m = 0.0;  //!< rear-axle distance of the last sample
  bool reached = false;
  double reaching_time_s = -1.0;                       //!< -1 when not reached
  double reaching_distance_m = -1.0;                   //!< -1 when not reached
  double max_abs_lead_error_after_reaching_m = -1.0;   //!< -1 when not reached
  double max_abs_front_error_after_reaching_m = -1.0;  //!< -1 when not reached
  double max_abs_rear_error_after_reaching_m = -1.0;   //!< -1 when not reached
  double max_abs_rear_error_m = 0.0;                   //!< whole run
  double max_abs_front_error_m = 0.0;                  //!< whole run
  double max_abs_lead_error_m = 0.0;                   //!< whole run
  double final_abs_rear_error_m = 0.0;
  double command_rate_std_radps = 0.0;
  double command_rate_max_radps = 0.0;
  double command_acceleration_std_radps2 = 0.0;
  double command_acceleration_max_radps2 = 0.0;
  double actual_rate_std_radps = 0.0;
  double actual_rate_max_radps = 0.0;
  double actual_acceleration_std_radps2 = 0.0;
  double actual_acceleration_max_radps2 = 0.0;
  double max_abs_command_rad = 0.0;
  double max_abs_actual_rad = 0.0;
  double max_abs_side_slip_rad = 0.0;
  //! Largest |beta_r (true) - beta_r (given to the controller)|: the side-slip estimate's error.
  double max_abs_rear_slip_input_error_rad = 0.0;
  //! The path's own demand: largest v^2 |kappa_path| at the rear axle's closest point [m/s^2],
  //! and the samples where it exceeds the friction limit (the path asks more than the tires).
  double max_path_lateral_acceleration_mps2 = 0.0;
  int path_friction_exceedances = 0;
  int angle_violations = 0;         //!< steps with |delta_cmd| above the angle limit
  int rate_violations = 0;          //!< steps with |d delta_cmd/dt| above the rate limit
  int acceleration_violations = 0;  //!< steps with |d2 delta_cmd/dt2| above its limit
  int bound_violations = 0;         //!< steps with at least one of the three
  int non_finite_values = 0;        //!< non-finite numbers in the trace (must be 0)

  // The held command (what the actuator receives: delta_cmd under the zero-order hold), by
  // differences over the control period T: rate (d_k - d_{k-1}) / T, acceleration
  // (d_k - 2 d_{k-1} + d_{k-2}) / T^2. Counts are steps above the vehicle's limits.
  double held_rate_rms_radps = 0.0;
  double held_rate_max_radps = 0.0;
  double held_acceleration_rms_radps2 = 0.0;
  double held_acceleration_max_radps2 = 0.0;
  int held_rate_violations = 0;
  int held_acceleration_violations = 0;
  // The actuator's output delta_actual (its filter states at the control instants).
  double actual_rate_rms_radps = 0.0;
  double actual_acceleration_rms_radps2 = 0.0;
  int actual_rate_violations = 0;
  int actual_acceleration_violations = 0;
  //! RMS of the rear axle's lateral error e over all rows (start included) [m].
  double rms_rear_error_m = 0.0;
};

//! Reduces a trace one sample at a time: the same numbers as compute_metrics() without
//! holding the trace (streaming runs, whose memory does not grow with their length).
class MetricsAccumulator {
 public:
  explicit MetricsAccumulator(const MetricsParameters& parameters);
  void add(const TraceSample& sample);
  Metrics result() const;

 private:
  struct Spread {
    long count = 0;
    double mean = 0.0, m2 = 0.0, sum_squares = 0.0, max_abs = 0.0;
    void add(double x);
    double std_dev() const;
    double rms() const;
  };
  MetricsParameters parameters_;
  Metrics m_;
  long first_reached_ = 0;  //!< one past the last sample with |e_lead| >= threshold
  double last_time_s_ = 0.0, last_command_rad_ = 0.0, last_held_rate_radps_ = 0.0;
  Spread command_rate_, command_acceleration_, actual_rate_, actual_acceleration_;
  Spread held_rate_, held_acceleration_, rear_error_;
};

Metrics compute_metrics(const std::vector<TraceSample>& trace, const MetricsParameters& parameters);

//! (name, value) of every metric, in a fixed documented order (booleans and counts as doubles).
std::vector<std::pair<std::string, double>> metric_values(const Metrics& metrics);

}  // namespace smoothsteer
