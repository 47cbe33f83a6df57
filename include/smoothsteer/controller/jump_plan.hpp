#pragma once
//! \file jump_plan.hpp
//! The planned lead curvature over a jump of the path's curvature (docs/feedforward.md, section
//! 2b). A ramp centred on a jump of height J leaves the rear axle about J S^2 / 24 off the path
//! (S = J / L_ff, section 6). The plan instead counter-steers, ramps at the feedforward's rate
//! past the new curvature and comes back, timed so that the chain's lags (paper_notes §1: each
//! stage a first-order lag in arc length) deliver a rear-axle curvature that ends the jump with
//! neither a heading error nor an offset. The plan is only a target: the feedforward stays
//! clamped to +-kbar_ff and rate-limited at L_ff, so the certificate of section 5 is unchanged.

#include "smoothsteer/controller/feedforward.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer {

//! Counter-steer of the plan as a share of the jump: the linear programme of
//! studies/feedforward_bound.py counter-steers by 0.20-0.24 J on circle_sections' jumps.
inline constexpr double jump_plan_counter_share = 0.22;
//! The plan ramps at this share of L_ff, so that the nonlinear chain inverse of its lagged
//! response stays within the rate limit.
inline constexpr double jump_plan_rate_margin = 0.95;
//! The plan's extremes stay within this share of kbar_ff.
inline constexpr double jump_plan_bound_margin = 0.98;
//! A spline path's curvature is averaged over at most this width [m] (planned_rear_curvature_
//! jet): the average's cost grows with it, and a wider one blurs the road more than it helps.
inline constexpr double max_spline_rounding_m = 20.0;
//! At most this many jumps are planned at once; further ones within reach pass as steps.
inline constexpr int max_planned_jumps = 16;

//! The lead curvature planned over one jump, as a function of arc length: before + sign *
//! (piecewise linear through (at + x[i], value[i])), `before` ahead of x[0], `after` beyond x[3].
struct JumpPlan {
  double at_m = 0.0;    //!< arc length of the jump [m]
  double sign = 1.0;    //!< sign of after - before
  double height = 0.0;  //!< |after - before| [1/m]
  double x[4]{};        //!< breakpoints relative to the jump [m]
  double value[4]{};    //!< sign * (plan - before) at them [1/m]
  //! Both conditions of plan_jump met (false: the headroom to the bound did not suffice, and
  //! the plan only meets the first).
  bool balanced = false;
};

//! The plan for `jump`: counter-steer o1 = jump_plan_counter_share |J| (within `bound`), a ramp
//! at `rate` to after + o2 and back to `after`, at an offset c from the jump. With the chain's
//! mean reach m = sum lambda_i and variance V = sum lambda_i^2, the rear axle ends the jump on
//! the path with the path's heading when the deviation D = plan - step satisfies
//!   integral D ds = m J   (the lags' mean delay)   and   integral s D ds = (V - m^2) J / 2
//! (their variance). The first fixes c in closed form; the second o2 (bisection in [0, the
//! headroom to `bound`]; the closest end if the headroom does not suffice).
JumpPlan plan_jump(const Path::CurvatureJump& jump, double rate, double bound, double chain_reach,
                   double chain_length_squared) noexcept;

//! plan - step at arc length s [1/m]: zero outside [at + x[0], max(at, at + x[3])].
double jump_plan_deviation(const JumpPlan& plan, double arc_length_m) noexcept;

//! The rounding of a kink (a step `slope_step` of the curvature's slope, Path::CurvatureKink) over
//! a centred window of `width_m`, at `offset_m` from it [1/m]: the curvature averaged over the
//! window minus the curvature itself, slope_step ((x + w / 2)^2 / (2 w) - max(x, 0)) for |x| < w /
//! 2 and 0 outside. Its largest value, at the kink, is slope_step w / 8.
double kink_rounding(double slope_step, double width_m, double offset_m) noexcept;

//! The rear axle's curvature jet at arc length s when the lead wheel follows the planned
//! curvature: the path's curvature with every kink rounded over m |D| / rate (kink_rounding,
//! m = sum lambda_i) and every jump within reach replaced by its plan (rate
//! jump_plan_rate_margin L_ff, extremes within jump_plan_bound_margin kbar_ff), passed through
//! the chain's linearised lags over the last 8 max lambda_i metres (exact for inputs linear over
//! each 0.25 m step). Its chain inverse (invert_chain) is the plan again. Orders 1 and 2; no
//! allocation; O(log jumps + 8 max lambda_i / 0.25 m).
CurvatureJet planned_rear_curvature_jet(const Path& path, double arc_length_m,
                                        double feedforward_rate, double feedforward_bound,
                                        const double* wheelbases, int order,
                                        double kink_rate = 0.0) noexcept;

}  // namespace smoothsteer
