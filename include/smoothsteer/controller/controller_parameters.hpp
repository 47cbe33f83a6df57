#pragma once
//! \file controller_parameters.hpp
//! Parameters of the n-smooth lead-wheel controller (paper Sec. II and III). SI units throughout.

#include <array>
#include <limits>
#include <numbers>
#include <string>

namespace smoothsteer {

//! Which switching function drives the lead wheel.
enum class SlidingSurface {
  //! Globally convergent extension (docs/global_convergence.md). Equal in sign to the printed
  //! surface for cos(psi) > 0 and |e| < 1 / ((1 - k_rob) kbar); converges from any pose.
  global,
  //! Eq. (sigma) exactly as printed. Only converges for |e| < 2 / ((1 - k_rob) kbar) and
  //! cos(psi) > 0 (paper_notes §4). Kept for reproduction and comparison.
  paper,
};

//! What the lead wheel aims at on a curved path.
enum class CorneringTarget {
  //! The lead wheel runs on a parallel offset of the path such that, in stationary cornering,
  //! the REAR AXLE lies exactly on the path (docs/controller.md, "cornering offset").
  rear_axle,
  //! The lead wheel runs where the chain puts it while the rear axle runs EXACTLY on the path,
  //! also while the curvature changes: the chain's inverse (docs/feedforward.md, "exact
  //! rear-axle target"). Exact on smooth paths whose curvature the feedforward can follow; where
  //! the feedforward saturates (kbar_ff or L_ff) the stationary rear_axle target is more forgiving.
  rear_axle_exact,
  //! The lead wheel itself runs on the path, as in the paper. With the fictive wheelbase of
  //! eq. (cornering_constr) the real front wheel then lies on the path and the rear axle cuts
  //! the corner by about lambda_veh^2 / (2 R).
  lead_wheel,
};

//! How the exact rear-axle target previews the path's curvature (docs/feedforward.md, section 2).
//! Either way the feedforward stays clamped to +-kbar_ff and rate-limited at L_ff, so the
//! certificate is the same.
enum class CurvaturePreview {
  //! A jump becomes a ramp of slope L_ff centred on it (preview_curvature). Local and simple,
  //! but it leaves the rear axle about J S^2 / 24 off the path (S = J / L_ff).
  centred_ramp,
  //! Each jump of the path's curvature (Path::curvature_jumps: the joints of line and arc
  //! pieces) gets a planned lead curvature that counter-steers and overshoots so that the rear
  //! axle ends it on the path (jump_plan.hpp, section 2b). Needs cornering_target
  //! rear_axle_exact, order 1 or 2, a finite L_ff, and kbar_ff well above the path's
  //! curvature (the plan overshoots: 1.8 times on circle_sections, `tune --feedforward-headroom`).
  planned_jumps,
};

//! The steering governor (docs/governor.md): the car's rate and acceleration limits enforced on
//! the held command inside the control step, by choosing the lead curvature from the interval
//! that keeps them (eq. governor_interval), instead of certifying the worst case of the box for
//! a small switching authority. With it the law may use the whole authority the angle and
//! friction limits leave (kbar_n), split between feedforward and switching part along s.
struct SteeringGovernor {
  bool enabled = false;
  //! The car's limits, +inf = none. They are run-time inputs: the governor holds R and A on the
  //! command; governed_parameters() (steering_governor.hpp) widens kbar_n at each retune to what
  //! the angle and friction limits allow at the speed; a reset refuses an angle beyond the angle
  //! limit (LeadWheelController::reset, for a ScheduledController too); and the steering
  //! system's offset compensation keeps angle, R and A (car_steering_limits()).
  double max_steering_rate_radps = std::numeric_limits<double>::infinity();  //!< R [rad/s]
  //! A [rad/s^2]; for order 1 it bounds the change of the rate between sub-steps.
  double max_steering_acceleration_radps2 = std::numeric_limits<double>::infinity();
  double max_steering_angle_rad = std::numeric_limits<double>::infinity();         //!< [rad]
  double max_lateral_acceleration_mps2 = std::numeric_limits<double>::infinity();  //!< mu g
  // The law under the governor.
  //! |dv/dt| [m/s^2] the bound budgets for beyond the measured one (the speed changes between
  //! two control periods enter the held command's second difference as |dv/dt| |rate| / v).
  double max_longitudinal_acceleration_mps2 = 0.0;
  //! l [m]: length scale of the far law. Its boundary layer becomes epsilon = l kbar_sw / 2, so
  //! that the law's linear zone is the critically damped kappa_sw = -e / l^2 - 2 psi / l
  //! whatever the authority kbar_sw (docs/governor.md). Derived at every sub-step from the
  //! speed, R and the lead wheel's heading error (governed_law_length(), eq.
  //! governed_law_length), unless fixed_law_length: then law_length_m, in (0, 1000] m. Setting
  //! law_length_m through the field table (scenario key, Python) fixes it; there 0 = derived.
  bool fixed_law_length = false;
  double law_length_m = 0.0;
  //! Share of R and A kept in reserve for the variation of the chain within a sub-step.
  double margin = 0.02;
  //! How far [m] the far law's authority remembers the feedforward's demand (an envelope of
  //! |kappa_ff| that decays by kbar_n over this distance).
  static constexpr double demand_memory_m = 60.0;
  //! How far [m] the far law keeps the lead once an error called it (its share decays by 1 over
  //! this distance).
  static constexpr double far_law_memory_m = 50.0;
  //! The far law also takes over as the lead wheel's error leaves the larger of the near law's
  //! boundary layer and this share of the tires' slip lag (K_f + K_r) v^2 / g (fully at twice
  //! it). At speed the certified layer's linear zone is tens of metres long (23 m at 15 m/s for
  //! the passenger car), so a disturbance beyond kbar_sw (a gust, a stiffer tire) walks the car
  //! off the path while the near law's sliding variable stays inside its layer. Scaling with the
  //! slip lag keeps the far law, which rings against that lag at speed, away from the errors a
  //! lane change leaves; smaller shares cost the 15 m/s lane change (0.02: 0.030 -> 0.042 m) or
  //! the 19 m/s one with a mis-set slip observer (0.03: 0.32 -> 0.46 m) (docs/governor.md).
  static constexpr double far_law_slip_lag_share = 0.05;
  //! The near-path law's authority [1/m]: near the path the law steers with
  //! min(this, kbar_sw), so that a widened kbar_n does not stiffen the tracking the split
  //! certificate tuned (docs/governor.md, section 4). governed_parameters() lowers it to the
  //! certified kbar_sw before it widens kbar_n; +inf = the whole kbar_sw.
  double near_law_switching_bound = std::numeric_limits<double>::infinity();
};

//! Largest supported chain length. Fixed-size storage keeps update() allocation free.
inline constexpr int max_chain_order = 8;

//! The fictive trailer chain (paper Sec. II-C/D) and its integration.
struct ChainParameters {
  //! n: number of fictive wheels in front of the rear axle. The steering angle is C^(n-1) and
  //! its n-th derivative is bounded. n = 0 is the original (chattering) Dubins-car law.
  int order = 2;
  //! lambda_veh: wheelbase of the real vehicle [m].
  double vehicle_wheelbase_m = 2.7;
  //! lambda_1..lambda_n [m]. lambda_1 is the fictive wheelbase lambda (paper Sec. III item 3),
  //! lambda_n the lead wheelbase lambda_l (for n = 2). Only the first n entries are used.
  std::array<double, max_chain_order> wheelbases_m{2.5, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0};
  //! kbar_n: curvature bound of the lead wheel [1/m] (eq. kappan). The bounds of the wheels
  //! behind it follow from the invariant sets (paper_notes §2).
  double lead_curvature_bound = 0.2;
  //! Largest arc-length step [m] of the RK4 integration of the chain, relative to the shortest
  //! wheelbase. A control period is split into at most max_substeps steps.
  double max_substep_fraction = 0.1;
  int max_substeps = 64;
};

//! The switching law on the lead wheel (paper eq. sigma, docs/global_convergence.md).
struct SwitchingLawParameters {
  SlidingSurface surface = SlidingSurface::global;
  //! k_rob in [0, 1): robustness margin of the switching law (eq. sigma) against matched
  //! disturbances |kappa_d| <= k_rob kbar_sw, kbar_sw = (1 - feedforward.share) kbar_n: the
  //! switching part alone must cover them (docs/feedforward.md, section 4). With the paper's law
  //! (share = 0) that is k_rob kbar_n, and the path's curvature is such a disturbance; with the
  //! default share 0.5 it is half of it.
  //! ClosedLoopProperties.MatchedDisturbanceIsRejected tests up to 0.95 of this bound.
  double k_rob = 0.3;
  //! psi_max in (0, pi/2]: heading relative to the path with which the lead wheel approaches
  //! from far away. pi/2 gives the Dubins turn-straight-turn.
  double approach_angle_rad = std::numbers::pi / 2.0;
  //! epsilon >= 0: width of a boundary layer around the switching surface, in the units of the
  //! sliding variable (rad for the global law, m for the paper's). 0 is the paper's
  //! kappa_sw = kbar_sw sign(.); epsilon > 0 uses kbar_sw sat(./epsilon), which removes the
  //! discrete-time chattering of the command's acceleration at the cost of millimetres.
  //! |kappa_sw| <= kbar_sw either way, so every bound holds.
  double boundary_layer = 0.01;
};

//! The curvature feedforward (docs/feedforward.md): kappa_n = kappa_ff + kappa_sw.
struct FeedforwardParameters {
  //! Share of kbar_n given to the curvature feedforward, in [0, 1): kbar_ff = share * kbar_n.
  //! kappa_ff is the curvature the lead wheel needs to stay on its target curve (exact Frenet
  //! form), saturated at +-kbar_ff and rate limited, and kappa_sw the switching part with
  //! authority kbar_sw = kbar_n - kbar_ff. |kappa_n| <= kbar_n, so the paper's invariant sets and
  //! angle bounds hold unchanged. 0 is the paper's law (no feedforward): the path's curvature is
  //! then a disturbance that k_rob must cover.
  double share = 0.5;
  //! L_ff >= 0: largest |d kappa_ff / ds| per metre of rear-axle travel [1/m^2]. Finite values
  //! make the steering rate and acceleration certificate of steering_certificate.hpp finite;
  //! +inf lets the feedforward follow its target at once (then only the box bound holds).
  double curvature_rate = std::numeric_limits<double>::infinity();
  //! Catch-up g in [0, 1] (docs/feedforward.md, section 4): where the rate limit L_ff holds
  //! kappa_ff back from its target, the switching part adds up to g kbar_sw of the gap, inside
  //! its own bound kbar_sw. kappa_sw stays in +-kbar_sw, so the certificate is unchanged, and the
  //! residual that k_rob must cover never grows. 0 = off (kappa_ff alone follows its target).
  double catch_up = 0.0;
  CorneringTarget cornering_target = CorneringTarget::rear_axle;
  CurvaturePreview curvature_preview = CurvaturePreview::centred_ramp;
};

//! Each compensation below is an optional group: `enabled` switches it, and while it is off its
//! other fields must keep their defaults (validate() rejects them as inert otherwise). Beyond
//! the paper (its outlook: actuator compensation).

//! Smith predictor: the law acts on the pose predicted for the moment the new command takes
//! effect, integrated with the kinematic model from the measured pose and the commands still in
//! the pipe.
struct DelayCompensation {
  bool enabled = false;
  //! Known delay [s] between the command and the steering it produces (dead time, plus the
  //! group delay of the actuator's low-pass if desired), in (0, max_actuator_delay_s].
  double actuator_delay_s = 0.0;
};

//! Dynamics inversion of the feedforward (docs/vehicle_dynamics.md, section 3). On the linear
//! single-track model with yaw inertia m lf lr the rear axle's course curvature kappa follows
//! the steering as delta = L kappa + (K_f - K_r) v^2 kappa + L (K_f + K_r) v^2 kappa'
//! + L K_f K_r v^4 kappa'' (' = d/ds), with the slip gradients K_r = m lf / (L Cr) and
//! K_f = m lr / (L Cf). The feedforward therefore aims the chain at g kappa(s + d) plus a
//! second-order correction, g = 1 + (K_f - K_r) v^2 / L, d = (K_f + K_r) v^2 / g, reading the
//! path d + preview_time_s |v| metres further ahead. The result still passes the clamp to
//! +-kbar_ff and the rate limit L_ff, so the certificate holds unchanged.
//! Braking moves load from the rear axle to the front one (accelerating the other way), and a
//! tire's cornering stiffness grows with its load, so the slip gradients follow the measured
//! longitudinal acceleration a_x: K_f / (1 - a_x t_f) and K_r / (1 + a_x t_r), with the load
//! transfer coefficients t_f = h / (g lr), t_r = h / (g lf) (docs/vehicle_dynamics.md, section 3).
struct SingleTrackInversion {
  bool enabled = false;
  double rear_slip_gradient_s2pm = 0.0;   //!< K_r [rad / (m/s^2)] = [s^2/m], in [0, 0.1]
  double front_slip_gradient_s2pm = 0.0;  //!< K_f [rad / (m/s^2)] = [s^2/m], in [0, 0.1]
  //! t_f [s^2/m], in [0, 1]: the front axle's share of load lost per m/s^2 of acceleration.
  double front_load_transfer_s2pm = 0.0;
  //! t_r [s^2/m], in [0, 1]: the rear axle's share of load gained per m/s^2 of acceleration.
  double rear_load_transfer_s2pm = 0.0;
  double preview_time_s = 0.0;  //!< [s], in [0, max_actuator_delay_s]
  //! With the second-order term K_f K_r v^4 kappa'' of the inversion (true), or only its
  //! preview and gain (false). Near the friction limit the linear model over-corrects with it.
  bool second_order = true;
};

//! Disturbance estimation (docs/feedforward.md, "disturbances on the vehicle"): a curvature the
//! plant adds at the rear axle (understeer, a banked road, a steering offset) is estimated as the
//! measured course curvature minus the commanded one, low-passed over length_m, and the
//! feedforward aims the chain at the path's curvature minus it. The estimate enters only through
//! kappa_ff, so |kappa_ff| <= kbar_ff, its rate limit and the certificate hold.
struct DisturbanceEstimation {
  bool enabled = false;
  double length_m = 0.0;  //!< the running mean's longest memory [m], in [1, 1000]
  //! The car's block (make_steering_system, scenario files with derived_compensation): on, with
  //! 80 m. Shorter memories learn faster from a cold start but carry the sensors' noise into the
  //! feedforward, which the near law's long linear zone turns into an offset: at 2 m the 10 m/s
  //! lane change goes from 0.007 to 0.030 m; at 80 m every shipped manoeuvre stays within 10 %
  //! of its figure without the estimate (docs/studies/disturbance_estimate_by_default.md).
  static constexpr double car_length_m = 80.0;
};

//! Friction guard (docs/vehicle_dynamics.md): at speed v the lead wheel's curvature stays within
//! the curvature whose stationary rear-axle curvature is a_max / v^2, so the car never asks more
//! than a_max of its tires once the chain is stationary. kappa_ff moves into the shrunken range
//! at its rate limit L_ff; kappa_sw is clipped.
struct FrictionGuard {
  bool enabled = false;
  double max_lateral_acceleration_mps2 = std::numeric_limits<double>::infinity();  //!< a_max
};

//! Steering-actuator inversion (paper Outlook; Klauer et al. 2020): for an actuator of lag_count
//! equal first-order lags with time constant T, (1 + T s)^m, the command is delta + a1 delta' +
//! ... with a_k = C(m, k) T^k, using the chain's derivatives up to order n - 1 so that the
//! command keeps a certified rate bound (docs/vehicle_dynamics.md). Needs order >= 2. The dead
//! time is the Smith predictor's (DelayCompensation).
struct ActuatorInversion {
  bool enabled = false;
  double time_constant_s = 0.0;  //!< T = 1 / pole [s], in (0, 0.5]
  int lag_count = 3;             //!< m, in [1, 3]
};

//! Every setting of the lead-wheel controller, in groups (docs/controller.md, "Parameters"). The
//! field table (parameter_fields.hpp) names each field once for validation, the scenario keys,
//! the Python keywords and the docs.
struct ControllerParameters {
  static constexpr int max_order = max_chain_order;
  //! Range of lambda_veh and of every lambda_i [m]: no car-like chain has a wheel 1 cm from
  //! the next or 100 m away.
  static constexpr double min_wheelbase_m = 0.01;
  static constexpr double max_wheelbase_m = 100.0;
  static constexpr double max_actuator_delay_s = 1.0;
  static constexpr double max_slip_gradient_s2pm = 0.1;  //!< bound of K_r and K_f
  //! Shortest sub-step max_substep_fraction * min lambda_i allowed [m]. update() counts the
  //! sub-steps of a period as |v| dt / sub-step, at most 1e3 m/s * 1e3 s / 1e-3 m = 1e9 within
  //! ControllerInputRange: an int, before max_substeps caps it.
  static constexpr double min_substep_m = 1e-3;

  ChainParameters chain{};
  SwitchingLawParameters law{};
  FeedforwardParameters feedforward{};
  DelayCompensation delay_compensation{};
  SingleTrackInversion single_track{};
  DisturbanceEstimation disturbance_estimation{};
  FrictionGuard friction_guard{};
  ActuatorInversion actuator_inversion{};
  //! Off by default: the split certificate of steering_certificate.hpp alone.
  SteeringGovernor governor{};

  //! kbar_ff = feedforward.share * kbar_n [1/m].
  double feedforward_curvature_bound() const noexcept {
    return feedforward.share * chain.lead_curvature_bound;
  }
  //! kbar_sw = kbar_n - kbar_ff [1/m]: authority of the switching part.
  double switching_curvature_bound() const noexcept {
    return (1.0 - feedforward.share) * chain.lead_curvature_bound;
  }

  //! Throws std::invalid_argument naming the field, its value and the rule it breaks.
  void validate() const;
  //! Same checks without throwing: returns an empty string when valid, else the message.
  std::string validation_error() const;
  //! Same rules as validation_error(), for real-time use: noexcept and allocation free.
  bool is_valid() const noexcept;

  //! The paper's C^1 controller (n = 2) with the fictive wheelbase of eq. (cornering_constr):
  //! lambda = sqrt(lambda_veh^2 - lambda_l^2).
  static ControllerParameters paper_c1(double vehicle_wheelbase_m, double lead_wheelbase_m,
                                       double lead_curvature_bound, double k_rob);
  //! The C^0 controller (n = 1) acting on the front wheel, lambda = lambda_veh (eq. ext1).
  static ControllerParameters paper_c0(double vehicle_wheelbase_m, double front_curvature_bound,
                                       double k_rob);
};

}  // namespace smoothsteer
