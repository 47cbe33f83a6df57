#include "smoothsteer/sim/kinematic_closed_loop.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "closed_loop.hpp"
#include "smoothsteer/sim/closed_loop_count.hpp"

namespace smoothsteer {

KinematicLoopResult run_kinematic_closed_loop(SteeringController& controller, const Pose2& start,
                                              const KinematicLoopOptions& options) {
  detail::count_closed_loop();
  KinematicLoopResult result;
  result.options = options;
  KinematicSingleTrack plant{options.wheelbase_m};
  const int steps = static_cast<int>(std::ceil(options.duration_s / options.period_s));
  if (options.record_trace) result.trace.reserve(static_cast<std::size_t>(steps));
  Pose2 pose = start;
  double distance = 0.0;
  double previous_steering = 0.0;
  ControllerOutput output;
  for (int k = 0; k < steps; ++k) {
    const ControllerInput input{pose.position, pose.heading_rad, options.speed_mps, 0.0,
                                options.period_s};
    const Status status = controller.update(input, output);
    if (status != Status::ok) {
      result.status = status;
      break;
    }
    const double steering = output.steering_angle_rad;
    const bool finite = std::isfinite(steering) && std::isfinite(output.steering_rate_radps) &&
                        std::isfinite(output.steering_acceleration_radps2) &&
                        std::isfinite(output.diagnostics.lateral_error_m);
    result.any_non_finite = result.any_non_finite || !finite;
    result.max_abs_steering_rad = std::max(result.max_abs_steering_rad, std::abs(steering));
    result.max_abs_steering_rate_radps =
        std::max(result.max_abs_steering_rate_radps, std::abs(output.steering_rate_radps));
    result.max_abs_steering_acceleration_radps2 = std::max(
        result.max_abs_steering_acceleration_radps2, std::abs(output.steering_acceleration_radps2));
    if (k > 0) {
      result.max_abs_steering_difference_rate_radps =
          std::max(result.max_abs_steering_difference_rate_radps,
                   std::abs(steering - previous_steering) / options.period_s);
    }
    previous_steering = steering;
    if (options.record_trace) {
      result.trace.push_back({k * options.period_s, distance, pose, output});
    }
    result.final_lateral_error_m = output.diagnostics.lateral_error_m;
    result.final_heading_error_rad = output.diagnostics.heading_error_rad;
    // Zero-order hold over the period; the disturbance bends the rear-axle path as an extra
    // curvature: tan(delta_eff) / lambda = tan(delta) / lambda + kappa_d.
    const double disturbed =
        disturbed_steering_angle(steering, options.wheelbase_m, options.curvature_disturbance);
    pose = plant.step(pose, disturbed, options.speed_mps, options.period_s);
    distance += std::abs(options.speed_mps) * options.period_s;
  }
  return result;
}

TraceSample kinematic_trace_sample(const KinematicTraceSample& k,
                                   const KinematicLoopOptions& options) noexcept {
  const TrackingDiagnostics& d = k.output.diagnostics;
  TraceSample s;
  s.time_s = k.time_s;
  s.distance_m = k.distance_m;
  s.rear_axle = k.pose;
  s.speed_mps = options.speed_mps;
  s.path_arc_length_m = d.path_arc_length_m;
  s.path_curvature = d.path_curvature;
  s.lateral_error_m = d.lateral_error_m;
  s.heading_error_rad = d.heading_error_rad;
  s.front_lateral_error_m = d.front_lateral_error_m;
  detail::record_controller_report(s, d);
  s.steering_command_rad = k.output.steering_angle_rad;
  s.steering_command_rate_radps = k.output.steering_rate_radps;
  s.steering_command_acceleration_radps2 = k.output.steering_acceleration_radps2;
  // No actuator: the wheels are at the command.
  s.steering_actual_rad = s.steering_command_rad;
  s.steering_actual_rate_radps = s.steering_command_rate_radps;
  s.steering_actual_acceleration_radps2 = s.steering_command_acceleration_radps2;
  s.yaw_rate_radps =
      options.speed_mps *
      (std::tan(k.output.steering_angle_rad) / options.wheelbase_m + options.curvature_disturbance);
  return s;
}

void write_kinematic_trace_csv(const KinematicLoopResult& result, const std::string& file_path) {
  const std::string temporary = file_path + ".tmp";
  {
    std::ofstream file(temporary);
    if (!file) throw std::runtime_error("cannot open '" + temporary + "' for writing");
    file.precision(9);
    file << "t,distance,x,y,psi,delta_cmd,delta_rate,delta_acc,e,heading_error,e_front,e_lead,"
            "psi_lead,sigma,kappa_lead,path_s\n";
    for (const KinematicTraceSample& sample : result.trace) {
      const TrackingDiagnostics& d = sample.output.diagnostics;
      file << sample.time_s << ',' << sample.distance_m << ',' << sample.pose.position.x << ','
           << sample.pose.position.y << ',' << sample.pose.heading_rad << ','
           << sample.output.steering_angle_rad << ',' << sample.output.steering_rate_radps << ','
           << sample.output.steering_acceleration_radps2 << ',' << d.lateral_error_m << ','
           << d.heading_error_rad << ',' << d.front_lateral_error_m << ',' << d.lead_lateral_error_m
           << ',' << d.lead_heading_error_rad << ',' << d.sliding_variable << ','
           << d.lead_curvature << ',' << d.path_arc_length_m << '\n';
    }
    if (!file) throw std::runtime_error("failed while writing '" + temporary + "'");
  }
  if (std::rename(temporary.c_str(), file_path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot rename '" + temporary + "' to '" + file_path + "'");
  }
}

}  // namespace smoothsteer
