#pragma once
//! \file trailer_chain.hpp
//! Kinematics of the fictive trailer chain (paper Sec. II-C/D, paper_notes §1).
//!
//! Wheel 0 is the rear axle, wheel i sits lambda_i ahead of wheel i-1 along the heading of
//! wheel i-1, and delta_i is the angle between the headings of wheels i-1 and i. Wheel n is the
//! lead wheel. With s the rear-axle arc length and s_i the arc length of wheel i:
//!   curvature of wheel i-1:  kappa_{i-1} = tan(delta_i) / lambda_i
//!   arc length:              ds_i = ds_{i-1} / cos(delta_i)
//!   dynamics:                d delta_i / d s_{i-1} = kappa_i / cos(delta_i) -
//!   tan(delta_i)/lambda_i
//! with kappa_n the control. All functions take arrays of length n (index 0 = wheel 1).

#include <array>

#include "smoothsteer/controller/controller_parameters.hpp"
#include "smoothsteer/math/vec2.hpp"

namespace smoothsteer {

using ChainAngles = std::array<double, ControllerParameters::max_order>;

//! Bounds implied by the invariant sets |delta_i| <= asin(kbar_i lambda_i) (paper_notes §2).
struct ChainBounds {
  //! kbar_0..kbar_n: curvature bound of each wheel [1/m]; index 0 is the rear axle.
  std::array<double, ControllerParameters::max_order + 1> curvature{};
  //! delta-bar_1..delta-bar_n: invariant-set half-width of each chain angle [rad] (index 0 =
  //! wheel 1).
  ChainAngles angle{};
  //! Bound on |delta_veh| [rad]: atan(lambda_veh kbar_0).
  double steering_angle_rad = 0.0;
  //! Bound on |d delta_veh / ds| [rad/m] over the invariant sets; +inf for n = 0.
  //! Multiply by |v| for the steering-rate bound in rad/s.
  double steering_rate_per_meter = 0.0;
};

//! d delta_veh / d delta_1 for delta_veh = atan(r tan(delta_1)), r = lambda_veh / lambda_1
//! (paper_notes §3): r / (cos^2 delta_1 + r^2 sin^2 delta_1).
double vehicle_angle_gain(double front_angle, double ratio) noexcept;
//! The same from cos(delta_1) and sin(delta_1), where the caller has them.
double vehicle_angle_gain(double front_cosine, double front_sine, double ratio) noexcept;
//! d gain / d delta_1 = -gain^2 sin(2 delta_1) (r^2 - 1) / r.
double vehicle_angle_gain_slope(double front_angle, double ratio) noexcept;
//! The same with the gain at delta_1 already known.
double vehicle_angle_gain_slope(double front_angle, double ratio, double gain) noexcept;

//! Propagates kbar_n down the chain: kbar_{i-1} = kbar_i / sqrt(1 - kbar_i^2 lambda_i^2).
//! Requires valid parameters.
ChainBounds compute_chain_bounds(const ControllerParameters& parameters);
//! The same without the rate supremum (steering_rate_per_meter stays 0): the invariant sets only.
ChainBounds compute_invariant_sets(const ControllerParameters& parameters) noexcept;

//! The trigonometry of one chain state that chain_rates and front_angle_derivatives read. Both
//! are affine in kappa_n at a given state, so evaluations at several lead curvatures (the
//! governor's two, eq. governor_interval) share it.
struct ChainTrigonometry {
  ChainAngles tangent{};       //!< tan(delta_i), i = 1..n
  double front_cosine = 1.0;   //!< cos(delta_1), for n >= 2
  double second_cosine = 1.0;  //!< cos(delta_2), for n >= 2
  double front_sine = 0.0;     //!< sin(delta_1), for n >= 2
};
ChainTrigonometry chain_trigonometry(const ChainAngles& delta, int order) noexcept;

//! d delta_i / ds for i = 1..n (derivatives with respect to the REAR arc length s).
void chain_rates(const ChainAngles& delta, const double* wheelbases, int order,
                 double lead_curvature, ChainAngles& rates) noexcept;
void chain_rates(const ChainTrigonometry& trigonometry, const double* wheelbases, int order,
                 double lead_curvature, ChainAngles& rates) noexcept;

//! First and second derivative of delta_1 with respect to s. The second derivative exists for
//! n >= 2 (for n = 2 piecewise, between switches of kappa_n).
struct FrontAngleDerivatives {
  double first = 0.0;   //!< delta_1' [rad/m]
  double second = 0.0;  //!< delta_1'' [rad/m^2] (0 for n < 2)
};
FrontAngleDerivatives front_angle_derivatives(const ChainAngles& delta, const double* wheelbases,
                                              int order, double lead_curvature) noexcept;
FrontAngleDerivatives front_angle_derivatives(const ChainTrigonometry& trigonometry,
                                              const double* wheelbases, int order,
                                              double lead_curvature) noexcept;

//! Pose of every wheel of the chain, from the rear-axle pose.
struct ChainGeometry {
  std::array<Vec2, ControllerParameters::max_order + 1> position{};   //!< index 0 = rear axle
  std::array<double, ControllerParameters::max_order + 1> heading{};  //!< psi_i
};
void chain_geometry(Vec2 rear_position, double rear_heading, const ChainAngles& delta,
                    const double* wheelbases, int order, ChainGeometry& geometry) noexcept;

//! Chain angles of stationary cornering with front angle delta_1: every d delta_i/ds = 0, i.e.
//! tan(delta_{i+1}) = lambda_{i+1} sin(delta_i) / lambda_i. Used to initialise the chain from a
//! measured steering angle. The result lies inside the invariant sets when delta_1 does.
void stationary_chain(double front_angle, const double* wheelbases, int order,
                      ChainAngles& delta) noexcept;

//! One RK4 step of the chain over rear arc length ds with constant lead curvature, integrated in
//! tan(delta_i) (no trigonometry inside the stages). Afterwards every angle is clamped to
//! max(its invariant set, its value before the step): the exact flow never leaves the set, so
//! this only removes the integration error at the boundary; and an angle that a retune left
//! outside a shrunken set is never moved inward by a jump, only by the flow, which points inward
//! there (LeadWheelController::retune).
void integrate_chain(ChainAngles& delta, const double* wheelbases, int order, double lead_curvature,
                     double ds, const ChainAngles& angle_bound) noexcept;
//! The same with a lead curvature that changes linearly from lead_curvature to
//! lead_curvature_end over the step (the rate-limited feedforward, docs/feedforward.md).
void integrate_chain(ChainAngles& delta, const double* wheelbases, int order, double lead_curvature,
                     double lead_curvature_end, double ds, const ChainAngles& angle_bound) noexcept;

}  // namespace smoothsteer
