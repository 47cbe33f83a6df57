// The columns of trace.csv (include/smoothsteer/io/trace_csv.hpp, docs/cli.md).

#include "smoothsteer/io/trace_csv.hpp"

namespace smoothsteer::io {

static_assert(trace_column_count == trace_sample_size,
              "every TraceSample field needs a trace.csv column (and docs/cli.md a line)");

const std::array<const char*, trace_column_count>& trace_column_names() noexcept {
  static constexpr std::array<const char*, trace_column_count> names{"t",
                                                                     "s",
                                                                     "x",
                                                                     "y",
                                                                     "psi",
                                                                     "v",
                                                                     "a",
                                                                     "path_s",
                                                                     "path_kappa",
                                                                     "e",
                                                                     "heading_error",
                                                                     "e_front",
                                                                     "e_lead",
                                                                     "e_measured",
                                                                     "sigma",
                                                                     "kappa_lead",
                                                                     "delta_cmd",
                                                                     "delta_cmd_rate",
                                                                     "delta_cmd_acc",
                                                                     "delta_actual",
                                                                     "delta_actual_rate",
                                                                     "delta_actual_acc",
                                                                     "side_slip",
                                                                     "vy",
                                                                     "yaw_rate",
                                                                     "beta_rear",
                                                                     "beta_rear_input",
                                                                     "kappa_d_estimate",
                                                                     "slip_error",
                                                                     "course_bias"};
  return names;
}

std::array<double, trace_column_count> trace_row(const TraceSample& s) noexcept {
  return {s.time_s,
          s.distance_m,
          s.rear_axle.position.x,
          s.rear_axle.position.y,
          s.rear_axle.heading_rad,
          s.speed_mps,
          s.acceleration_mps2,
          s.path_arc_length_m,
          s.path_curvature,
          s.lateral_error_m,
          s.heading_error_rad,
          s.front_lateral_error_m,
          s.lead_lateral_error_m,
          s.measured_lateral_error_m,
          s.sliding_variable,
          s.lead_curvature,
          s.steering_command_rad,
          s.steering_command_rate_radps,
          s.steering_command_acceleration_radps2,
          s.steering_actual_rad,
          s.steering_actual_rate_radps,
          s.steering_actual_acceleration_radps2,
          s.side_slip_rad,
          s.lateral_velocity_mps,
          s.yaw_rate_radps,
          s.rear_side_slip_rad,
          s.rear_side_slip_input_rad,
          s.disturbance_curvature,
          s.slip_error,
          s.course_bias_rad};
}

}  // namespace smoothsteer::io
