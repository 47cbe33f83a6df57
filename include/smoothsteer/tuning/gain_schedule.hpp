#pragma once
//! \file gain_schedule.hpp
//! Velocity-dependent optimal parameters (paper Sec. III, objectives O1-O4, velocity regions 1-4)
//! and the gain schedule the controller interpolates online.
//!
//! At each grid speed v the tuner solves, with the constraints of eq. (kappalmax) and eq.
//! (cornering_constr) built into the parametrization kbar_l = sin(theta) / lambda_veh:
//!   C1  theta <= dbar_veh                                     (steering angle)
//!   O1  v R <= rate limit                                     (steering rate)
//!   O2  v^2 A + |dv/dt|_max R <= acceleration limit            (steering acceleration)
//!   O3  maximise kbar_l, then O4 minimise lambda_l,
//! in this priority order, with R, A the worst-case |delta_veh'|, |delta_veh''| of the static map.
//! Order n = 1 has no lambda_l and no acceleration bound: kbar_1 follows in closed form from C1
//! and O1. n >= 3 is not supported (docs/tuning.md says how far the generalization goes).

#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/system/driving_domain.hpp"
#include "smoothsteer/tuning/static_map.hpp"
#include "smoothsteer/tuning/vehicle_limits.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

//! Which certificate the tuner designs against (docs/tuning.md).
enum class Certificate {
  //! The paper's route: worst case over the invariant box; the path's curvature is a matched
  //! disturbance that k_rob covers; no feedforward.
  box,
  //! Curvature feedforward plus switching part (docs/feedforward.md): the feedforward covers the
  //! path's curvature and curvature rate, the switching part only the residual; the rate and
  //! acceleration bounds of steering_certificate.hpp.
  feedforward,
};

struct TuningOptions {
  Certificate certificate = Certificate::feedforward;
  int order = 2;  //!< n: 1 or 2
  //! Largest |dv/dt| the schedule must cover [m/s^2]; enters O2 as |dv/dt| R (paper: 0).
  double max_longitudinal_acceleration_mps2 = 0.0;
  //! kbar_l must not fall below this [1/m] (lead radius at most 1/this); else infeasible.
  double min_lead_curvature_bound = 1e-3;
  //! Matched disturbance kappa_d [1/m] and reference-path curvature bound [1/m] that k_rob must
  //! cover (Sec. III item 2, paper_notes §6).
  double matched_disturbance_curvature = 0.0;
  double path_curvature_bound = 0.0;
  //! Largest |d kappa / ds| of the reference path [1/m^2] (+inf: unknown or with jumps); the
  //! feedforward's rate limit L_ff covers it with feedforward_rate_margin where the budget allows.
  double path_curvature_rate_bound = std::numeric_limits<double>::infinity();
  //! The reference path itself, if known (apply_path_demand sets it): the feedforward's rate
  //! limit then covers the lead wheel's curvature rate on it (lead_curvature_rate_demand), which
  //! the rear-axle target asks for, with feedforward_rate_margin where the budget allows.
  std::shared_ptr<const Path> reference_path;
  //! kbar_ff = headroom * path_curvature_bound (where the friction and angle limits allow): the
  //! rear-axle target and the dynamics preview ask the lead wheel for more curvature than the
  //! path's own peak (docs/vehicle_dynamics.md). 1 = exactly the path's peak.
  double feedforward_headroom = 1.0;
  double feedforward_rate_margin = 1.25;  //!< L_ff = margin * path curvature rate ...
  double feedforward_rate_share = 0.8;    //!< ... but at most this share of the rate budget
  //! ... and at least kbar_path / this [m]: the feedforward can build up the path's curvature
  //! within this distance even on a path of constant curvature (a circle has K' = 0).
  double feedforward_ramp_length_m = 10.0;
  //! kbar_sw >= this share of kbar_n even where the path asks for more curvature than the
  //! friction or angle limit allows (the feedforward then saturates there).
  double switching_floor_share = 0.1;
  double k_rob_floor = 0.3;     //!< k_rob = max(floor, (kappa_d + kbar_path) / kbar_l)
  double k_rob_ceiling = 0.95;  //!< infeasible when the required k_rob reaches this
  //! Template for every other controller field (surface, cornering target, sub-steps).
  ControllerParameters base{};
  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

//! Paper Sec. III "velocity regions", labelled by which limits are active at the optimum.
enum class VelocityRegion {
  region1 = 1,  //!< only the steering angle binds: kbar_l maximal, lambda_l minimal
  region2 = 2,  //!< the acceleration limit binds: lambda_l grows, kbar_l still maximal
  region3 = 3,  //!< rate and acceleration bind: kbar_l decreases, lambda_l grows
  region4 = 4,  //!< only the acceleration binds at the lambda_l that minimises delta''
  //! Not in the paper: only the rate binds below the angle limit (always so for n = 1; for
  //! n = 2 when the rate limit is reached before the acceleration limit).
  rate_only = 5,
};
const char* to_string(VelocityRegion region) noexcept;

struct ScheduleEntry {
  double speed_mps = 0.0;
  VelocityRegion region = VelocityRegion::region1;
  double fictive_wheelbase_m = 0.0;   //!< lambda [m]
  double lead_wheelbase_m = 0.0;      //!< lambda_l [m] (0 for n = 1)
  double lead_curvature_bound = 0.0;  //!< kbar_l [1/m] (kbar_1 for n = 1)
  double k_rob = 0.0;
  double feedforward_curvature_bound = 0.0;  //!< kbar_ff [1/m] (0 on the box route)
  double feedforward_curvature_rate = 0.0;   //!< L_ff [1/m^2]
  //! Exact worst case at this speed (not from the table), for the report and Fig. param_v.
  double max_steering_angle_rad = 0.0;
  double max_steering_rate_radps = 0.0;
  double max_steering_acceleration_radps2 = 0.0;  //!< +inf for n = 1
};

class InfeasibleLimits : public std::runtime_error {
 public:
  InfeasibleLimits(const std::string& message, double speed_mps, std::string binding_limit)
      : std::runtime_error(message),
        speed_mps_(speed_mps),
        binding_limit_(std::move(binding_limit)) {}
  double speed_mps() const noexcept { return speed_mps_; }
  //! "steering angle", "steering rate", "steering acceleration", "steering rate and
  //! acceleration" or "robustness (k_rob)".
  const std::string& binding_limit() const noexcept { return binding_limit_; }

 private:
  double speed_mps_;
  std::string binding_limit_;
};

class GainSchedule {
 public:
  GainSchedule() = default;
  GainSchedule(VehicleLimits vehicle, TuningOptions options, std::vector<ScheduleEntry> entries);

  const VehicleLimits& vehicle() const noexcept { return vehicle_; }
  const TuningOptions& options() const noexcept { return options_; }
  const std::vector<ScheduleEntry>& entries() const noexcept { return entries_; }
  bool empty() const noexcept { return entries_.empty(); }
  //! Largest speed for which the limits are guaranteed: the last grid speed.
  double max_speed_mps() const noexcept {
    return entries_.empty() ? 0.0 : entries_.back().speed_mps;
  }

  //! Parameters for |v| (noexcept, no allocation). Conservative interpolation: with grid speeds
  //! v_0 < ... < v_N and v_{-1} = 0, a speed in [v_{k-1}, v_k] blends entries k and k+1 linearly
  //! (entry N+1 = entry N). Both were designed for a speed >= v_k >= |v|, and R, A grow with v,
  //! so each is valid at |v|; compute_gain_schedule() checks that the blends are too. Continuous
  //! in v. Above v_N the last entry is returned (no guarantee).
  ControllerParameters parameters_at(double speed_mps) const noexcept;

 private:
  VehicleLimits vehicle_;
  TuningOptions options_;
  std::vector<ScheduleEntry> entries_;
};

//! Called once per grid speed, after that speed's entry is solved, on the calling thread: a long
//! grid's progress (`smoothsteer tune`, docs/cli.md "Progress"). An exception it throws stops the
//! computation and propagates. The tuning library does no I/O of its own.
using SpeedSolved = std::function<void()>;

//! Solves O1-O4 at each speed (strictly increasing, > 0). Throws std::invalid_argument for bad
//! inputs and InfeasibleLimits naming the first speed and the limit that binds. The map must
//! cover the vehicle's steering angle (options().max_steering_angle_rad) for n = 2.
GainSchedule compute_gain_schedule(const VehicleLimits& vehicle, const TuningOptions& options,
                                   const std::vector<double>& speeds_mps, const StaticMap& map,
                                   const SpeedSolved& speed_solved = {});

//! The feedforward route (Certificate::feedforward, docs/tuning.md): at each speed the largest
//! switching authority kbar_sw, with kbar_ff covering the path's curvature within the angle and
//! friction limits and L_ff its curvature rate, such that steering_certificate.hpp's bounds meet
//! the rate and acceleration limits. Needs no static map. Same errors as compute_gain_schedule.
GainSchedule compute_feedforward_schedule(const VehicleLimits& vehicle,
                                          const TuningOptions& options,
                                          const std::vector<double>& speeds_mps,
                                          const SpeedSolved& speed_solved = {});

//! The feedforward route for a domain of paths instead of one (system/driving_domain.hpp): at
//! each speed the path bounds are the domain's there, domain.curvature_at(v) and
//! domain.curvature_rate_at(v); options.path_curvature_bound and path_curvature_rate_bound are
//! not used. std::invalid_argument for an invalid domain or a reference path in the options,
//! InfeasibleLimits as compute_feedforward_schedule.
GainSchedule compute_domain_schedule(const VehicleLimits& vehicle, const TuningOptions& options,
                                     const DrivingDomain& domain,
                                     const std::vector<double>& speeds_mps);

//! Certified parameters for a car (docs/tuning.md, "Parameters for your car"): the feedforward
//! route's entry for the top speed `speed_mps`. Valid at every lower speed too (the certified
//! maxima grow with v), so one fixed parameter set covers 0..speed_mps; a ScheduledController
//! gives more authority at low speed. The path enters through options.path_curvature_bound and
//! path_curvature_rate_bound (0 and +inf by default: a straight path). Throws
//! std::invalid_argument for invalid inputs and InfeasibleLimits naming the binding limit.
ControllerParameters parameters_for_vehicle(const VehicleLimits& vehicle, double speed_mps,
                                            const TuningOptions& options = {});

//! Parameters of a schedule entry for the options' order and template (both routes).
ControllerParameters schedule_entry_parameters(const TuningOptions& options,
                                               double vehicle_wheelbase_m,
                                               const ScheduleEntry& entry) noexcept;

//! Entry a + t (b - a) in every tuned parameter (the online blend of parameters_at()).
ScheduleEntry blend_entries(const ScheduleEntry& a, const ScheduleEntry& b, double t) noexcept;

//! Throws std::invalid_argument unless the speeds are finite, > 0 and strictly increasing.
void check_speed_grid(const std::vector<double>& speeds_mps);
//! The input checks both routes share: vehicle, options, speed grid, and no acceleration limit
//! for order 1 (which cannot bound it). Throws std::invalid_argument naming the field.
void check_schedule_inputs(const VehicleLimits& vehicle, const TuningOptions& options,
                           const std::vector<double>& speeds_mps);

//! Speeds first:step:last (inclusive up to rounding); throws for non-positive step or first.
std::vector<double> speed_grid(double first_mps, double last_mps, double step_mps);

}  // namespace smoothsteer
