#pragma once
//! \file kinematic_closed_loop.hpp
//! Closed loop of a steering controller and the kinematic single-track model at constant speed,
//! with a zero-order hold on the steering command. Used by the tests and the demo; the kinetic
//! simulation with actuator, delay and noise lives in sim/simulation.hpp.

#include <string>
#include <vector>

#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/sim/simulation.hpp"
#include "smoothsteer/vehicle/kinematic_single_track.hpp"

namespace smoothsteer {

struct KinematicLoopOptions {
  double wheelbase_m = 2.7;  //!< lambda_veh of the plant [m]
  double speed_mps = 5.0;    //!< signed constant speed [m/s]
  double period_s = 0.02;    //!< control period [s]
  double duration_s = 60.0;  //!< simulated time [s]
  //! Matched curvature disturbance added to the rear-axle curvature [1/m] (paper eq. sigma:
  //! robustness for |kappa_d| <= k_rob kbar).
  double curvature_disturbance = 0.0;
  bool record_trace = true;
};

struct KinematicTraceSample {
  double time_s = 0.0;
  double distance_m = 0.0;  //!< travelled distance of the rear axle
  Pose2 pose;
  ControllerOutput output;
};

struct KinematicLoopResult {
  Status status = Status::ok;
  KinematicLoopOptions options;  //!< the options of the run
  std::vector<KinematicTraceSample> trace;
  double final_lateral_error_m = 0.0;
  double final_heading_error_rad = 0.0;
  double max_abs_steering_rad = 0.0;
  double max_abs_steering_rate_radps = 0.0;             //!< from the controller's derivative output
  double max_abs_steering_difference_rate_radps = 0.0;  //!< |delta_k - delta_{k-1}| / dt
  double max_abs_steering_acceleration_radps2 = 0.0;
  bool any_non_finite = false;
};

//! Runs the loop; stops early with the controller's status if it returns an error.
KinematicLoopResult run_kinematic_closed_loop(SteeringController& controller, const Pose2& start,
                                              const KinematicLoopOptions& options);

//! Writes the trace as CSV (columns documented in docs/controller.md) to `file_path` via a
//! temporary file and rename, so that no half-written file is left behind.
//! A sample of the kinematic loop as a sample of the kinetic simulation (sim/simulation.hpp), so
//! that it can be written as `smoothsteer run`'s trace.csv (io::TraceCsvWriter; the demo does).
//! The kinematic car has no actuator and no tires: delta_actual* repeat delta_cmd*, side slip
//! and vy are 0, e_measured is e, and the yaw rate is v (tan(delta) / lambda_veh + kappa_d).
TraceSample kinematic_trace_sample(const KinematicTraceSample& sample,
                                   const KinematicLoopOptions& options) noexcept;

void write_kinematic_trace_csv(const KinematicLoopResult& result, const std::string& file_path);

}  // namespace smoothsteer
