#pragma once
//! \file newton_raphson_controller.hpp
//! Newton-Raphson flow tracking controller after Shivam, Buckley, Wardi, Seatzu, Egerstedt,
//! "Tracking control by the Newton-Raphson flow: applications to autonomous vehicles" (ECC 2019,
//! the paper's ref. newtonraphson): the input follows the flow
//!
//!   du/dt = alpha (dg/du)^-1 (r(t + T) - g(x(t), u(t)))
//!
//! where g(x, u) is the output predicted T seconds ahead with u held constant.
//!
//! Prediction model used here (documented in docs/baselines.md): the kinematic single-track
//! model of the rear axle with the steering angle u held, i.e. an exact circular arc of
//! curvature tan(u)/lambda and length |v| T. The output is scalar: the predicted rear-axle
//! position's signed offset from the reference point r(t + T) = path point |v| T ahead of the
//! current closest point, measured along that point's normal, so r - g = -offset. dg/du is
//! analytic (arc geometry). No side slip is modelled (Shivam et al. use a model with slip; this
//! is why our variant is compared as "NR flow, kinematic prediction").
//! The integrated u is clamped to the steering limits (angle and rate) inside the flow, so the
//! flow does not wind up against the actuator.

#include <memory>

#include "smoothsteer/baselines/path_tracking_baseline.hpp"
#include "smoothsteer/baselines/steering_limits.hpp"
#include "smoothsteer/controller/steering_controller.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct NewtonRaphsonParameters {
  double wheelbase_m = 2.7;    //!< lambda of the prediction model [m]
  double horizon_s = 1.0;      //!< T: prediction horizon [s]
  double gain_per_s = 4.0;     //!< alpha: speed-up of the flow [1/s]
  double min_speed_mps = 0.5;  //!< below this |v| the prediction is not informative: hold
  SteeringLimits limits;       //!< clamp of u and du/dt inside the flow

  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

//! Prediction of the rear axle over arc length `distance_m` with constant steering angle:
//! lateral and longitudinal displacement in the vehicle frame and their derivatives w.r.t. the
//! steering angle (exact circular arc, Taylor branch for |kappa d| < 1e-4).
struct ArcPrediction {
  double forward_m = 0.0;
  double left_m = 0.0;
  double heading_change_rad = 0.0;
  double d_forward_d_steering = 0.0;
  double d_left_d_steering = 0.0;
};
ArcPrediction predict_arc(double steering_angle_rad, double wheelbase_m,
                          double distance_m) noexcept;

class NewtonRaphsonController final : public PathTrackingBaseline<NewtonRaphsonParameters> {
 public:
  NewtonRaphsonController(const NewtonRaphsonParameters& parameters,
                          std::shared_ptr<const Path> path);

  Status reset(double measured_steering_angle_rad = 0.0) noexcept override;
  const char* name() const noexcept override { return "newton_raphson"; }

 protected:
  Status compute_command(const ControllerInput& input, ControllerOutput& output) noexcept override;

 private:
  double rate_ = 0.0;
};

}  // namespace smoothsteer
