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

PreviewedCurvature preview_curvature(const Path& path, double arc_length_m, double step_m,
                                     double rate_per_meter, double bound) noexcept {
  const double spacing = path.curvature_sample_spacing_m();
  const long centre = std::lround(arc_length_m / spacing);
  const long offset = std::max(1L, std::lround(step_m / spacing));  // s +- step in samples
  auto sample = [&](long index) { return std::clamp(path.curvature_sample(index), -bound, bound); };
  if (!(rate_per_meter > 0.0) || !std::isfinite(rate_per_meter)) {
    return {sample(centre - offset), sample(centre), sample(centre + offset)};
  }
  // Envelopes of the three points at once: sample j lies |j - (centre + p)| samples from point p.
  const double slope = 2.0 * rate_per_meter * spacing;  // per sample
  const long reach = static_cast<long>(
      std::min<double>(max_preview_samples, std::ceil(bound / (rate_per_meter * spacing))));
  double upper[3], lower[3];
  for (int p = 0; p < 3; ++p) upper[p] = lower[p] = sample(centre + (p - 1) * offset);
  for (long j = centre - offset - reach; j <= centre + offset + reach; ++j) {
    const double curvature = sample(j);
    for (int p = 0; p < 3; ++p) {
      const double distance = slope * static_cast<double>(std::labs(j - centre - (p - 1) * offset));
      upper[p] = std::min(upper[p], curvature + distance);
      lower[p] = std::max(lower[p], curvature - distance);
    }
  }
  return {0.5 * (upper[0] + lower[0]), 0.5 * (upper[1] + lower[1]), 0.5 * (upper[2] + lower[2])};
}

}  // namespace smoothsteer
