#include "smoothsteer/controller/feedforward.hpp"

#include <algorithm>
#include <cmath>

#include "smoothsteer/controller/dubins_switching_law.hpp"
#include "smoothsteer/math/angles.hpp"

namespace smoothsteer {

TargetCurve stationary_rear_axle_target_curve(double curvature_before, double curvature,
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

CurvatureJet curvature_jet(double before, double at, double after) noexcept {
  constexpr double h = curvature_jet_step_m;
  return {at, (after - before) / (2.0 * h), (after - 2.0 * at + before) / (h * h)};
}

ChainInverse invert_chain(const CurvatureJet& rear, const double* wheelbases, int order) noexcept {
  // Stage i + 1 takes kappa_i as a jet in the rear's arc length s (value, d/ds, d2/ds2) and the
  // stretch g = ds_i / ds with its slope. sigma = kappa c with c = (1 + lambda^2 kappa^2)^(-1/2),
  // so sigma' = kappa' c^3 and sigma'' = kappa'' c^3 - 3 lambda^2 kappa kappa'^2 c^5; then
  // kappa_{i+1} = sigma + lambda sigma' / g (the stage's lag inverted, d/ds_i = (1/g) d/ds).
  ChainInverse inverse;
  double value = rear.value, slope = rear.slope, bend = rear.bend;
  double stretch = 1.0, stretch_slope = 0.0;
  for (int i = 0; i < order; ++i) {
    const double lambda = wheelbases[i];
    const double c = 1.0 / std::sqrt(1.0 + lambda * lambda * value * value);
    const double c3 = c * c * c;
    const double sigma = value * c;
    const double sigma_slope = slope * c3;
    const double sigma_bend =
        bend * c3 - 3.0 * lambda * lambda * value * slope * slope * c3 * c * c;
    inverse.angles[static_cast<std::size_t>(i)] = std::atan(lambda * value);
    const double next_value = sigma + lambda * sigma_slope / stretch;
    const double next_slope =
        sigma_slope +
        lambda * (sigma_bend * stretch - sigma_slope * stretch_slope) / (stretch * stretch);
    // ds_{i+1} / ds = g sec(delta_{i+1}) = g / c.
    stretch_slope = stretch_slope / c + stretch * lambda * lambda * value * slope * c;
    stretch /= c;
    value = next_value, slope = next_slope, bend = 0.0;  // the jet has no third derivative
  }
  inverse.lead_curvature = value;
  return inverse;
}

double chain_reach(const double* wheelbases, int order) noexcept {
  double reach = 0.0;
  for (int i = 0; i < order; ++i) reach += wheelbases[i];
  return reach;
}

TargetCurve rear_axle_target_curve(const Path& path, const PathProjection& lead,
                                   const CurvatureJet& rear, const double* wheelbases,
                                   int order) noexcept {
  const ChainInverse chain = invert_chain(rear, wheelbases, order);
  const PathPoint rear_point = path.evaluate(lead.arc_length_m - chain_reach(wheelbases, order));
  ChainGeometry geometry;
  chain_geometry(rear_point.position, rear_point.heading_rad, chain.angles, wheelbases, order,
                 geometry);
  const auto n = static_cast<std::size_t>(order);
  // The target point in the path's frame at `lead` (a along the tangent, b to the left), projected
  // onto the path's osculating circle there (curvature k; the forms below have no cancellation
  // for small k): offset (2 b - k (a^2 + b^2)) / (1 + hypot(k a, k b - 1)), the path's heading
  // turns by atan2(k a, 1 - k b) up to the foot, which lies that angle / |k| along the path.
  const Vec2 gap = geometry.position[n] - lead.closest_point;
  const Vec2 tangent = unit_from_heading(lead.heading_rad);
  const double a = dot(tangent, gap), b = cross(tangent, gap), k = lead.curvature;
  const double offset = (2.0 * b - k * (a * a + b * b)) / (1.0 + std::hypot(k * a, k * b - 1.0));
  const double turn = std::atan2(k * a, 1.0 - k * b);
  const double foot = std::abs(k * a) < 1e-9 ? a : turn / k;
  TargetCurve target;
  target.heading = wrap_angle(geometry.heading[n] - lead.heading_rad - turn);
  target.offset = offset - foot * std::tan(target.heading);
  target.curvature = chain.lead_curvature;
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
  // Envelopes of the three points (centre - offset, centre, centre + offset) in one pass.
  const double slope = 2.0 * rate_per_meter * spacing;  // per sample
  const long reach = static_cast<long>(
      std::min<double>(max_preview_samples, std::ceil(bound / (rate_per_meter * spacing))));
  // The distances from sample j to the points are whole numbers of samples, exact in double.
  const double gap = static_cast<double>(offset);
  double upper_before = sample(centre - offset), upper_at = sample(centre),
         upper_after = sample(centre + offset);
  double lower_before = upper_before, lower_at = upper_at, lower_after = upper_after;
  const long first = centre - offset - reach;
  double from_centre = static_cast<double>(first - centre);
  for (long j = first; j <= centre + offset + reach; ++j, from_centre += 1.0) {
    const double curvature = sample(j);
    const double before = slope * std::abs(from_centre + gap);
    const double at = slope * std::abs(from_centre);
    const double after = slope * std::abs(from_centre - gap);
    upper_before = std::min(upper_before, curvature + before);
    upper_at = std::min(upper_at, curvature + at);
    upper_after = std::min(upper_after, curvature + after);
    lower_before = std::max(lower_before, curvature - before);
    lower_at = std::max(lower_at, curvature - at);
    lower_after = std::max(lower_after, curvature - after);
  }
  return {0.5 * (upper_before + lower_before), 0.5 * (upper_at + lower_at),
          0.5 * (upper_after + lower_after)};
}

}  // namespace smoothsteer
