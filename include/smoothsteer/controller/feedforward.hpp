#pragma once
//! \file feedforward.hpp
//! The curvature feedforward of the lead wheel (docs/feedforward.md): the curve the lead wheel
//! tracks, the curvature that keeps it there, and the preview that starts a rate-limited
//! feedforward ramp before a change of the path's curvature instead of after it.

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
TargetCurve rear_axle_target_curve(double curvature_before, double curvature,
                                   double curvature_after, double step_m,
                                   double chain_length_squared) noexcept;

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
