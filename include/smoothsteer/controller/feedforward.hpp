#pragma once
//! \file feedforward.hpp
//! The curvature feedforward of the lead wheel (docs/feedforward.md): the curve the lead wheel
//! tracks, the curvature that keeps it there, and the preview that starts a rate-limited
//! feedforward ramp before a change of the path's curvature instead of after it.

#include "smoothsteer/controller/trailer_chain.hpp"
#include "smoothsteer/path/path.hpp"

namespace smoothsteer {

//! The curve the lead wheel tracks, relative to the reference path at its closest point.
struct TargetCurve {
  double offset = 0.0;     //!< lateral offset from the path [m], left positive
  double heading = 0.0;    //!< its heading relative to the path tangent [rad]
  double curvature = 0.0;  //!< its curvature [1/m]
};

//! The rear-axle target (CorneringTarget::rear_axle) from the path's curvature a step h before,
//! at and after the lead wheel's closest point: offset e0(kappa) = rear_axle_cornering_offset,
//! heading atan(e0' / (1 - kappa e0)) and curvature kappa / (1 - kappa e0) + e0'' with e0', e0''
//! by central differences over h (docs/feedforward.md, "moving offset"). Without the e0' and e0''
//! terms, a path whose curvature changes leaves them to the switching part.
TargetCurve stationary_rear_axle_target_curve(double curvature_before, double curvature,
                                              double curvature_after, double step_m,
                                              double chain_length_squared) noexcept;

//! The path's curvature at the rear axle and its first two derivatives along the arc length.
struct CurvatureJet {
  double value = 0.0;  //!< kappa [1/m]
  double slope = 0.0;  //!< d kappa / ds [1/m^2]
  double bend = 0.0;   //!< d2 kappa / ds2 [1/m^3]
};

//! Step of the central differences of the curvature jet [m] (the path's curvature samples are
//! 0.5 m apart): the controller and the tuner's demand (lead_curvature_rate_demand) use it both.
inline constexpr double curvature_jet_step_m = 0.5;
//! The jet from the curvature at s - curvature_jet_step_m, s and s + curvature_jet_step_m.
CurvatureJet curvature_jet(double before, double at, double after) noexcept;

//! The chain's state while the rear axle runs exactly on a path of curvature `rear` (docs/
//! feedforward.md, "exact rear-axle target"): each stage is the lag d sigma_{i-1} / d s_{i-1} =
//! (kappa_i - sigma_{i-1}) / lambda_i in sigma_{i-1} = sin(delta_i) / lambda_i, so it inverts to
//! kappa_i = sigma_{i-1} + lambda_i d sigma_{i-1} / d s_{i-1}, stage by stage from the rear, with
//! tan(delta_i) = lambda_i kappa_{i-1} and ds_i / ds_{i-1} = sec(delta_i). Each stage uses one more
//! derivative of the rear's curvature; the jet has two, so orders above 2 drop the third.
struct ChainInverse {
  ChainAngles angles{};         //!< delta_i [rad]
  double lead_curvature = 0.0;  //!< kappa_n [1/m]: the lead wheel's curvature
};
ChainInverse invert_chain(const CurvatureJet& rear, const double* wheelbases, int order) noexcept;

//! The exact rear-axle target (CorneringTarget::rear_axle_exact): where the lead wheel runs when
//! the rear axle is on the path. The rear axle sits a chain's reach behind the lead wheel's
//! closest point `lead`; the chain's pose there (invert_chain with the curvature jet `rear`, the
//! path's position and heading at that point) puts the lead wheel at a point whose offset from the
//! path, heading relative to it and curvature are the target's. That point lies centimetres from
//! `lead`, so the path is taken as its osculating circle at `lead` there; the offset is carried to
//! the lead wheel's own closest point along the target's heading. One Path::evaluate.
TargetCurve rear_axle_target_curve(const Path& path, const PathProjection& lead,
                                   const CurvatureJet& rear, const double* wheelbases,
                                   int order) noexcept;

//! The arc length by which the rear axle trails the lead wheel along a straight path: sum lambda_i.
double chain_reach(const double* wheelbases, int order) noexcept;

//! Curvature feedforward (docs/feedforward.md): the curvature with which a Dubins car at lateral
//! error e from a target curve of curvature kappa_t, heading psi relative to that curve, keeps
//! psi constant, from the Frenet equations d psi / ds = kappa_lead - kappa_t cos(psi) /
//! (1 - kappa_t e):  kappa_ff = kappa_t cos(psi) / (1 - kappa_t e). The denominator is kept
//! >= 1/2 (past half the radius towards the centre the projection itself becomes ambiguous);
//! the caller saturates the result at kbar_ff.
double frenet_feedforward_curvature(double target_curvature, double error_from_target,
                                    double heading_from_target) noexcept;

//! The path's curvature as the rate-limited feedforward should see it, at arc length s and
//! `step` before and after it: samples clamped to +-bound, then the midpoint of their upper and
//! lower Lipschitz envelopes with slope 2 rate (over the window bound / rate ahead and behind).
//! Where the path's curvature changes no faster than 2 rate this is the curvature itself; a jump
//! becomes a ramp of slope `rate` centred on it, which the rate limit follows exactly, so the
//! lead wheel starts turning half a ramp before the jump (zero phase). rate = +inf or <= 0: the
//! samples themselves. One pass over at most 2 max_preview_samples + 1 samples for the three
//! points: O(1) per call, no allocation.
struct PreviewedCurvature {
  double before = 0.0;  //!< at s - step
  double at = 0.0;      //!< at s
  double after = 0.0;   //!< at s + step
};
PreviewedCurvature preview_curvature(const Path& path, double arc_length_m, double step_m,
                                     double rate_per_meter, double bound) noexcept;
inline constexpr int max_preview_samples = 400;

}  // namespace smoothsteer
