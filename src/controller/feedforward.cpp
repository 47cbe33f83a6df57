#include "smoothsteer/controller/feedforward.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/controller/dubins_switching_law.hpp"

namespace smoothsteer {

TargetCurve rear_axle_target_curve(double curvature_before, double curvature,
                                   double curvature_after, double step_m,
                                   double chain_length_squared) noexcept {
  const double before = rear_axle_cornering_offset(curvature_before, chain_length_squared);
  const double at = rear_axle_cornering_offset(curvature, chain_length_squared);
  const double after = rear_axle_cornering_offset(curvature_after, chain_length_squared);
  const double slope = (after - before) / (2.0 * step_m);
  const double bend = (after - 2.0 * at + before) / (step_m * step_m);
  const double scale = std::max(0.5, 1.0 - curvature * at);  // ds along the offset per ds
  TargetCurve target;
  target.offset = at;
  target.heading = std::atan(slope / scale);
  target.curvature = curvature / scale + bend;
  return target;
}

double frenet_feedforward_curvature(double target_curvature, double error_from_target,
                                    double heading_from_target) noexcept {
  constexpr double smallest_denominator = 0.5;
  return target_curvature * std::cos(heading_from_target) /
         std::max(smallest_denominator, 1.0 - target_curvature * error_from_target);
}

double preview_curvature(const Path& path, double arc_length_m, double rate_per_meter,
                         double bound) noexcept {
  auto sample = [&](double at) { return std::clamp(path.sampled_curvature(at), -bound, bound); };
  const double centre = sample(arc_length_m);
  if (!(rate_per_meter > 0.0) || !std::isfinite(rate_per_meter)) return centre;
  const double slope = 2.0 * rate_per_meter;
  const double spacing = path.curvature_sample_spacing_m();
  const int count = static_cast<int>(
      std::min<double>(max_preview_samples, std::ceil(2.0 * bound / slope / spacing)));
  double upper = centre, lower = centre;
  for (int k = 1; k <= count; ++k) {
    const double distance = k * spacing;
    for (const double at : {arc_length_m - distance, arc_length_m + distance}) {
      const double curvature = sample(at);
      upper = std::min(upper, curvature + slope * distance);
      lower = std::max(lower, curvature - slope * distance);
    }
  }
  return 0.5 * (upper + lower);
}

}  // namespace smoothsteer
