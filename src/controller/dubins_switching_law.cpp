#include "smoothsteer/controller/dubins_switching_law.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {

double paper_sliding_variable(double lateral_error, double relative_heading, double curvature_bound,
                              double k_rob) noexcept {
  const double effective_bound = (1.0 - k_rob) * curvature_bound;
  return -lateral_error -
         (1.0 - std::cos(relative_heading)) / effective_bound * sign(std::sin(relative_heading));
}

double global_reference_heading(double lateral_error, double curvature_bound, double k_rob,
                                double approach_angle) noexcept {
  const double effective_bound = (1.0 - k_rob) * curvature_bound;
  const double arc_cosine =
      std::max(1.0 - effective_bound * std::abs(lateral_error), std::cos(approach_angle));
  return -sign(lateral_error) * std::acos(std::min(1.0, arc_cosine));
}

SwitchingResult dubins_switching_law(double lateral_error, double relative_heading,
                                     double curvature_bound,
                                     const ControllerParameters& parameters) noexcept {
  return dubins_switching_law(lateral_error, relative_heading, curvature_bound,
                              parameters.law.boundary_layer, parameters);
}

SwitchingResult dubins_switching_law(double lateral_error, double relative_heading,
                                     double curvature_bound, double boundary_layer,
                                     const ControllerParameters& parameters) noexcept {
  SwitchingResult result;
  if (parameters.law.surface == SlidingSurface::paper) {
    result.sliding_variable = paper_sliding_variable(lateral_error, relative_heading,
                                                     curvature_bound, parameters.law.k_rob);
  } else {
    double reference = global_reference_heading(
        lateral_error, curvature_bound, parameters.law.k_rob, parameters.law.approach_angle_rad);
    if (boundary_layer > 0.0) {
      // Near the path the finite-time curve psi ~ -sign(e) sqrt(2 k |e|) has infinite slope; a
      // linear zone psi_ref = -e / l with l = 4 epsilon / kbar (four heading time constants of
      // the boundary layer) makes the approach exponential there and the loop smooth.
      const double linear = -lateral_error * curvature_bound / (4.0 * boundary_layer);
      if (std::abs(linear) < std::abs(reference)) reference = linear;
    }
    result.sliding_variable = wrap_angle(reference - relative_heading);
  }
  if (boundary_layer > 0.0) {
    result.curvature =
        curvature_bound * std::clamp(result.sliding_variable / boundary_layer, -1.0, 1.0);
  } else {
    result.curvature = curvature_bound * sign(result.sliding_variable);  // eq. (cntrllaw)
  }
  return result;
}

double rear_axle_cornering_offset(double path_curvature, double chain_length_squared) noexcept {
  // -(sqrt(1 + k^2 L^2) - 1) / k rewritten without cancellation for small k.
  const double q = path_curvature * path_curvature * chain_length_squared;
  return -path_curvature * chain_length_squared / (std::sqrt(1.0 + q) + 1.0);
}

}  // namespace smoothsteer
