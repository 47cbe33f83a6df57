#pragma once
//! \file simulation.hpp
//! Closed-loop simulation: a steering controller sampled at its own period with a zero-order
//! hold, the steering actuator (dead time, third-order low-pass, saturation) and a vehicle model
//! (by default the actuator solved exactly and the vehicle by Dormand-Prince 5(4) with error
//! control, restarted every period; or RK4 at a fixed sub-step). Optional seeded Gaussian pose
//! noise on the measurement and a matched curvature disturbance. Definitions: docs/simulation.md.

#include <array>
#include <bit>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/path/path_plan.hpp"
#include "smoothsteer/sim/planner_windows.hpp"
#include "smoothsteer/sim/plant_imperfections.hpp"
#include "smoothsteer/sim/speed_profile.hpp"
#include "smoothsteer/system/steering_system.hpp"
#include "smoothsteer/vehicle/side_slip_observer.hpp"
#include "smoothsteer/vehicle/steering_actuator.hpp"
#include "smoothsteer/vehicle/vehicle_model.hpp"

namespace smoothsteer {

//! How the plant is integrated between control instants (docs/simulation.md).
enum class PlantIntegrator {
  //! RK4 of vehicle and actuator at the fixed sub-step (the method of earlier releases).
  fixed_rk4,
  //! The actuator solved exactly (its rate and angle saturation included) + Runge-Kutta-
  //! Fehlberg 7(8) with error control, restarted at every control instant.
  rkf78,
  //! The same with Dormand-Prince 5(4): the default (at tolerance 1e-6, 7-9 model evaluations
  //! per 20 ms period against RK4's 80 on the shipped scenarios; docs/benchmarks.md).
  dopri5,
};

//! dopri5 where the library was built with Boost.Odeint (Debian libboost-dev), else fixed_rk4
//! (the only method such a build has).
PlantIntegrator default_plant_integrator() noexcept;

//! Where the controller's ControllerInput::rear_axle_side_slip_rad comes from (docs/
//! vehicle_dynamics.md).
enum class SideSlipSource {
  none,      //!< 0: the kinematic assumption (course = heading)
  truth,     //!< the plant's true rear-axle slip (an ideal slip sensor)
  observer,  //!< SideSlipObserver on measured yaw rate, lateral acceleration, speed and delta
};

//! Side-slip estimation in the closed loop.
struct SideSlipEstimation {
  SideSlipSource source = SideSlipSource::none;
  //! The observer's belief relative to the vehicle file (robustness study): cornering
  //! stiffnesses and mass/yaw inertia times these factors.
  double cornering_stiffness_scale = 1.0;
  double mass_scale = 1.0;
  //! The observer's tire model (side_slip_observer.hpp): linear, or the Magic Formula near the
  //! friction limit.
  ObserverTireModel tire_model = ObserverTireModel::linear;
  //! Gaussian noise on the simulated sensors (the observer assumes the same stds, at least
  //! its defaults).
  double yaw_rate_noise_std_radps = 0.0;
  double lateral_acceleration_noise_std_mps2 = 0.0;
  //! The observer's steering-offset state: its bound (0: off) and random walk
  //! (SideSlipObserverParameters).
  double max_steering_offset_rad = SideSlipObserverParameters{}.max_steering_offset_rad;
  double steering_offset_process_std_radps =
      SideSlipObserverParameters{}.steering_offset_process_std_radps;
  //! The held command makes up for the learned offset through the controller's actuator model
  //! (SteeringSystemParameters::compensate_steering_offset).
  bool compensate_steering_offset = true;
  //! The system learns what the slip estimate gets wrong about the course from the pose
  //! (SteeringSystemParameters::course_error, its defaults); false: off.
  bool estimate_course_error = true;
};

struct SimulationParameters {
  double control_period_s = 0.02;  //!< controller period (50 Hz) [s]; a multiple of substep_s
  //! Delay-line resolution [s]; the step of fixed_rk4 (the adaptive integrators choose theirs).
  double substep_s = 0.001;
  PlantIntegrator integrator = default_plant_integrator();
  //! Absolute local error tolerance of rkf78 / dopri5 (per state component, m, rad, m/s). At
  //! 1e-6 every metric of every shipped scenario stays within 0.035 mm and 1e-6 rad of
  //! converged references (docs/benchmarks.md).
  double integrator_tolerance = 1e-6;
  double duration_s = 60.0;  //!< longest simulated time [s]
  //! Stop once the rear axle's closest point is this far beyond the end of an open path [m]
  //! (negative: before the end). Ignored for closed paths.
  double stop_beyond_path_end_m = 0.0;
  bool stop_at_path_end = true;
  //! Matched curvature disturbance kappa_d [1/m]. A controller that accepts
  //! SteeringController::set_matched_disturbance (the lead-wheel controllers, paper Sec. III
  //! item 2) gets it there; for any other it bends the rear-axle path:
  //! tan(delta_eff) = tan(delta) + L kappa_d.
  double matched_disturbance = 0.0;
  //! Curvature disturbance kappa_d [1/m] on the PLANT's rear axle, whatever the controller
  //! (understeer, a banked road, a steering offset): tan(delta_eff) = tan(delta) + L kappa_d.
  double plant_curvature_disturbance = 0.0;
  //! Constant offset of the road wheels from the angle the actuator delivers [rad] (a
  //! misaligned rack or wheel alignment): the plant steers delta + offset; |offset| <= 0.1.
  double steering_offset_rad = 0.0;
  //! Model error and imperfections of the car, given to the plant and the sensors only
  //! (plant_imperfections.hpp, docs/simulation.md): the controller is told none of them.
  PlantScales plant_scales;                   //!< the plant's vehicle (kinetic plants only)
  PlantActuatorScales plant_actuator_scales;  //!< the simulated actuator
  //! Crossfall of the road as a grade tan(phi), |.| <= 0.1; positive: the road falls to the
  //! car's right, which pushes it right (a_y = -g sin(phi); kinetic plants only).
  double crossfall = 0.0;
  SideForce side_force;  //!< crosswind or a gust step on the body (kinetic plants only)
  //! The pose (rear-axle position and heading) is delivered this late [s], in [0, 0.5]; speed,
  //! gyro, accelerometer and steering angle stay on time. Between control instants the pose is
  //! interpolated linearly; before t = 0 it is the straight drive the run starts from.
  double pose_latency_s = 0.0;
  //! The pose updates at this rate [Hz] in [1, 1 / control_period_s] and is held in between
  //! (still pose_latency_s late): at t the pose sampled at floor((t - latency) f) / f. Absent:
  //! every control step.
  std::optional<double> pose_rate_hz;
  //! The system is told the delivered pose's age (SteeringSystemInput::pose_age_s): the
  //! latency plus the time held at a low pose rate, which together must stay within
  //! ControllerInput::max_pose_age_s. false: the pose arrives late unannounced.
  bool pose_age_known = false;
  //! The measured road-wheel angle reads this much more than the actuator delivers [rad],
  //! |.| <= 0.1 (the rack itself true; steering_offset_rad is the opposite case).
  double steering_angle_sensor_offset_rad = 0.0;
  double gyro_bias_radps = 0.0;        //!< added to the measured yaw rate [rad/s], |.| <= 0.5
  double position_noise_std_m = 0.0;   //!< std of Gaussian noise on x and y of the rear axle [m]
  double heading_noise_std_rad = 0.0;  //!< std of Gaussian noise on psi [rad]
  std::uint64_t noise_seed = 1;        //!< seed of the noise generator (runs are reproducible)
  SideSlipEstimation side_slip;        //!< what the controller gets as the rear axle's slip
  //! Stack mode: the road arrives as a planner's windows by set_path() (planner_windows.hpp);
  //! its jitter has a generator of its own, so the sensors' noise stays the same.
  PlannerWindows planner;

  //! Caps on what the input controls (so that no input can make a run allocate without bound):
  //! control steps of one run (duration_s / control_period_s) and plant sub-steps (duration_s /
  //! substep_s).
  static constexpr double max_control_steps = 1e7;
  static constexpr double max_substeps = 1e8;
  static constexpr double max_pose_latency_s = 0.5;
  static constexpr double min_pose_rate_hz = 1.0;

  //! The first rule broken (validation.hpp); is_valid(), validation_error(), validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else a message naming the field, value and rule.
  std::string validation_error() const;
  void validate() const;  //!< throws std::invalid_argument
};

//! One row per control step (docs/cli.md lists the CSV columns).
struct TraceSample {
  double time_s = 0.0;
  double distance_m = 0.0;                //!< travelled distance of the rear axle
  Pose2 rear_axle;                        //!< true rear-axle pose
  double speed_mps = 0.0;                 //!< vx
  double acceleration_mps2 = 0.0;         //!< speed-profile dv/dt
  double path_arc_length_m = 0.0;         //!< s of the rear axle's closest point (true pose)
  double path_curvature = 0.0;            //!< at the rear axle's closest point
  double lateral_error_m = 0.0;           //!< true e of the rear axle
  double heading_error_rad = 0.0;         //!< true psi - path heading at the rear axle
  double front_lateral_error_m = 0.0;     //!< true e of the real front axle
  double lead_lateral_error_m = 0.0;      //!< e_lead reported by the controller (measured pose)
  double measured_lateral_error_m = 0.0;  //!< e reported by the controller
  double sliding_variable = 0.0;
  double lead_curvature = 0.0;
  double steering_command_rad = 0.0;         //!< delta_cmd
  double steering_command_rate_radps = 0.0;  //!< controller's derivative, else finite difference
  double steering_command_acceleration_radps2 = 0.0;
  double steering_actual_rad = 0.0;  //!< actuator output delta_actual
  double steering_actual_rate_radps = 0.0;
  double steering_actual_acceleration_radps2 = 0.0;
  double side_slip_rad = 0.0;             //!< atan(vy / vx) at the CG
  double rear_side_slip_rad = 0.0;        //!< true beta_r = atan((vy - lr r) / vx)
  double rear_side_slip_input_rad = 0.0;  //!< beta_r given to the controller (estimate)
  double lateral_velocity_mps = 0.0;
  double yaw_rate_radps = 0.0;
  //! The controller's estimate of the plant's disturbance [1/m] (TrackingDiagnostics).
  double disturbance_curvature = 0.0;
  //! What the system's course error estimator learned (SideSlipDiagnostics): the slip's
  //! relative error a and the course bias c [rad].
  double slip_error = 0.0;
  double course_bias_rad = 0.0;
};

//! Number of values of a TraceSample: every field is a double.
inline constexpr std::size_t trace_sample_size = sizeof(TraceSample) / sizeof(double);
static_assert(trace_sample_size * sizeof(double) == sizeof(TraceSample),
              "TraceSample must hold doubles only (trace_values reads it as an array)");
//! Every value of the sample in declaration order, for finiteness checks; a field added later is
//! included. The CSV columns, their names and order belong to io (smoothsteer/io/trace_csv.hpp).
inline std::array<double, trace_sample_size> trace_values(const TraceSample& sample) noexcept {
  return std::bit_cast<std::array<double, trace_sample_size>>(sample);
}

struct SimulationResult {
  Status status = Status::ok;  //!< first non-ok controller status (the run stops there)
  std::vector<TraceSample> trace;
  VehicleState final_state;
  //! A NaN/inf appeared in the plant state or in a sample (the run stops before emitting it).
  bool non_finite = false;
  std::string stop_reason;  //!< "duration", "path_end", "controller_error" or "non_finite"
  //! Why a run stopped early, for people: the time, the controller's status and the input
  //! value outside ControllerInputRange, or the first non-finite value. Empty otherwise.
  std::string stop_detail;
  std::uint64_t model_evaluations = 0;  //!< calls of VehicleModel::derivative (cost measure)
  //! Control periods that rkf78 / dopri5 left to fixed_rk4 because the exact actuator solution
  //! needed more segments than fit (src/sim/exact_actuator.hpp); expected 0.
  std::uint64_t plant_fallback_periods = 0;
};

//! Receives every trace sample as it is produced.
using TraceObserver = std::function<void(const TraceSample&)>;

//! Runs the closed loop from the rear-axle pose `start` (vehicle driving straight at the
//! profile's initial speed, actuator settled at 0). The controller is reset first. A sample
//! with a non-finite value is never emitted: the run stops before it with stop_reason
//! "non_finite" (a non-finite value is never reported with status ok). With an `observer`
//! (e.g. a CSV writer and a metrics accumulator) the run streams: every sample goes to it and
//! result.trace stays empty, so memory does not grow with the duration; without one the trace
//! is stored in result.trace. The same holds for every overload below.
SimulationResult simulate(const Path& path, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringController& controller, const TraceObserver& observer = {});

//! The car's steering system that the controller overloads drive: `controller` with the
//! slip input of parameters.side_slip (none: kinematic, truth: the plant's slip as a sensor,
//! observer: SideSlipObserver believing the vehicle file times the scales, with the tire model,
//! and trusting its sensors as much as their simulated noise says), and `actuator` as the
//! actuator's model the held command makes up for the steering offset through.
SteeringSystemParameters steering_system_parameters(const SideSlipEstimation& slip,
                                                    const VehicleParameters& vehicle,
                                                    const ActuatorParameters& actuator);

//! Runs the closed loop with a car's steering system (the one wiring: the controller overloads
//! build one with steering_system_parameters() and call this). The system is reset first. Its
//! own slip input decides what it reads; parameters.side_slip gives only the simulated
//! sensors' noise (its source, scales and tire model configure the controller overloads'
//! system). The sensors: rear-axle pose (pose noise), speed, dv/dt of the profile, yaw rate and
//! lateral acceleration at the CG (noise drawn only for an observer), the actuator's angle as
//! the measured steering angle and the plant's rear-axle slip as the slip sensor.
SimulationResult simulate(const Path& path, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringSystem& system, const TraceObserver& observer = {});

//! A path with gear changes (path_plan.hpp, docs/cusps.md) driven by a signed tabulated speed
//! profile (SpeedProfile::signed_speeds) that comes to rest at every cusp
//! (check_gear_changes(), gear_changes.hpp, throws std::invalid_argument otherwise). The
//! controller starts on piece 0 and gets the next piece by set_path() at the first control
//! instant of each rest, where the plant's vx is set to the profile's exact 0; errors and
//! metrics refer to the active piece, the heading error to the direction of travel. The run
//! ends at the end of the last piece or once the profile has come to its final rest.
SimulationResult simulate(const PathPlan& plan, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringController& controller, const TraceObserver& observer = {});
//! The same with a car's steering system (as the path overloads above).
SimulationResult simulate(const PathPlan& plan, const VehicleModel& vehicle,
                          const ActuatorParameters& actuator, const SpeedProfile& speed,
                          const SimulationParameters& parameters, const Pose2& start,
                          SteeringSystem& system, const TraceObserver& observer = {});

}  // namespace smoothsteer
