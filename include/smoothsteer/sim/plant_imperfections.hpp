#pragma once
//! \file plant_imperfections.hpp
//! Where the simulated car differs from what its controller is told (docs/simulation.md,
//! "Model error and imperfections"): plant-only scales of the vehicle and of the actuator, the
//! road's crossfall and a side force (crosswind, a gust step). The controller is built from the
//! scenario's vehicle and actuator blocks and is told none of this.

#include <memory>

#include "smoothsteer/vehicle/steering_actuator.hpp"
#include "smoothsteer/vehicle/vehicle_model.hpp"

namespace smoothsteer {

//! Factors (and a shift) applied to the plant's vehicle only (kinetic single-track and
//! double-track plants; the kinematic plant has no masses or tires and refuses them).
struct PlantScales {
  //! Mass factor. The axle cornering stiffnesses [N/rad] stay (the Magic Formula's B is divided
  //! by it: a load the tires' stiffness does not follow), the friction limit in g stays, so the
  //! understeer gradient K = m/L (lr/Cf - lf/Cr) grows with the factor; in [0.5, 2].
  double mass = 1.0;
  double yaw_inertia = 1.0;          //!< Iz factor; in [0.5, 2]
  double cornering_stiffness = 1.0;  //!< factor on B of both axles (C_alpha = B C mu Fz); [0.5, 2]
  //! Factor on mu (lateral, and the double track's longitudinal); B is divided by it so that
  //! the cornering stiffness stays and only the force's peak changes; in [0.1, 1.5].
  double friction = 1.0;
  //! Shift of the CG toward the front axle, as a fraction of the wheelbase (lf - shift L,
  //! lr + shift L, the wheelbase and Iz stay; the static axle loads follow); in [-0.25, 0.25].
  double cg_position = 0.0;

  bool identity() const noexcept {
    return mass == 1.0 && yaw_inertia == 1.0 && cornering_stiffness == 1.0 && friction == 1.0 &&
           cg_position == 0.0;
  }
};

//! Factors applied to the simulated actuator only; the controller's delay compensation keeps
//! the scenario's actuator block. Each in [0.5, 1.5].
struct PlantActuatorScales {
  //! Dead-time factor; the product is rounded to the nearest plant sub-step (the delay line is
  //! exact in whole sub-steps).
  double dead_time = 1.0;
  double bandwidth = 1.0;  //!< factor on bandwidth_hz

  bool identity() const noexcept { return dead_time == 1.0 && bandwidth == 1.0; }
};

//! A lateral force at the CG and a yaw moment on the plant's body, from start_s on (steady
//! crosswind: start_s = 0; a gust step: later). Positive toward the car's left (+y) and
//! counter-clockwise.
struct SideForce {
  double force_n = 0.0;        //!< |.| <= 1e5 N
  double yaw_moment_nm = 0.0;  //!< |.| <= 1e6 N m
  double start_s = 0.0;        //!< in [0, 3600] s

  bool active() const noexcept { return force_n != 0.0 || yaw_moment_nm != 0.0; }
};

//! The plant's vehicle: `truth` with the scales applied. Throws std::invalid_argument naming
//! SimulationParameters.plant_scales.<field> when the result describes no car (an axle behind
//! the CG, a parameter outside VehicleParameters' rules).
VehicleParameters scaled_plant_vehicle(const VehicleParameters& truth, const PlantScales& scales);

//! The simulated actuator: `told` with the scales applied (dead time rounded to `substep_s`).
//! Throws std::invalid_argument naming SimulationParameters.plant_actuator_scales when the
//! result breaks ActuatorParameters' rules.
ActuatorParameters scaled_plant_actuator(const ActuatorParameters& told,
                                         const PlantActuatorScales& scales, double substep_s);

//! The lateral acceleration a crossfall of `grade` (tan phi; positive: the road falls to the
//! car's right) gives a car whose tires hold it: -g sin(phi) [m/s^2] in the body's lateral
//! equation.
double crossfall_lateral_acceleration(double grade, double gravity_mps2) noexcept;

//! The plant model the closed loop integrates: `given` itself when `scales` is the identity,
//! else a copy of it with scaled_plant_vehicle() kept in `storage`. Throws std::invalid_argument
//! for a model that cannot be rebuilt (the kinematic plant, a user's model).
const VehicleModel& plant_model(const VehicleModel& given, const PlantScales& scales,
                                std::unique_ptr<VehicleModel>& storage);

}  // namespace smoothsteer
