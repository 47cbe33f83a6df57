#include "smoothsteer/sim/curvature_speed_profile.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace smoothsteer {

std::optional<Violation> CurvatureSpeedLimits::first_violation() const noexcept {
  auto bad = [](const char* field, double value, const char* rule) {
    return Violation{"CurvatureSpeedLimits", "", field, value, rule};
  };
  if (!(max_speed_mps > 0.0 && max_speed_mps <= 100.0)) {
    return bad("max_speed_mps", max_speed_mps, "must be in (0, 100]");
  }
  if (!(max_lateral_acceleration_mps2 > 0.0 && max_lateral_acceleration_mps2 <= 20.0)) {
    return bad("max_lateral_acceleration_mps2", max_lateral_acceleration_mps2,
               "must be in (0, 20]");
  }
  if (!(max_acceleration_mps2 > 0.0 && max_acceleration_mps2 <= 20.0)) {
    return bad("max_acceleration_mps2", max_acceleration_mps2, "must be in (0, 20]");
  }
  if (!(max_deceleration_mps2 > 0.0 && max_deceleration_mps2 <= 20.0)) {
    return bad("max_deceleration_mps2", max_deceleration_mps2, "must be in (0, 20]");
  }
  if (initial_speed_mps && !(*initial_speed_mps > 0.0 && *initial_speed_mps <= 100.0)) {
    return bad("initial_speed_mps", *initial_speed_mps, "must be in (0, 100]");
  }
  if (!(spacing_m >= 0.01 && spacing_m <= 10.0)) {
    return bad("spacing_m", spacing_m, "must be in [0.01, 10]");
  }
  return std::nullopt;
}

std::vector<double> curvature_limited_speeds(const Path& path, const CurvatureSpeedLimits& limits) {
  limits.validate();
  const double length = path.length();
  const auto intervals =
      static_cast<std::size_t>(std::max(1.0, std::ceil(length / limits.spacing_m)));
  const double ds = length / static_cast<double>(intervals);
  // The largest |kappa| within one spacing of each grid point, sampled at ds / 8.
  constexpr int kFine = 8;
  std::vector<double> fine(intervals * kFine + 1);
  for (std::size_t j = 0; j < fine.size(); ++j) {
    fine[j] =
        std::abs(path.evaluate(std::min(length, ds * static_cast<double>(j) / kFine)).curvature);
  }
  // A jump exactly at a grid point: both sides count.
  for (const Path::CurvatureJump& jump : path.curvature_jumps()) {
    const double at = std::clamp(jump.arc_length_m, 0.0, length);
    const auto j = static_cast<std::size_t>(std::lround(at / ds * kFine));
    if (j < fine.size()) fine[j] = std::max({fine[j], std::abs(jump.before), std::abs(jump.after)});
  }
  std::vector<double> v(intervals + 1);
  for (std::size_t i = 0; i <= intervals; ++i) {
    const std::size_t from = i == 0 ? 0 : (i - 1) * kFine;
    const std::size_t to = std::min(fine.size() - 1, (i + 1) * kFine);
    const double kappa = *std::max_element(fine.begin() + static_cast<long>(from),
                                           fine.begin() + static_cast<long>(to) + 1);
    v[i] = kappa > 0.0 ? std::min(limits.max_speed_mps,
                                  std::sqrt(limits.max_lateral_acceleration_mps2 / kappa))
                       : limits.max_speed_mps;
  }
  if (limits.initial_speed_mps) v[0] = std::min(v[0], *limits.initial_speed_mps);
  for (std::size_t i = 1; i <= intervals; ++i) {
    v[i] = std::min(v[i], std::sqrt(v[i - 1] * v[i - 1] + 2.0 * limits.max_acceleration_mps2 * ds));
  }
  for (std::size_t i = intervals; i-- > 0;) {
    v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2.0 * limits.max_deceleration_mps2 * ds));
  }
  return v;
}

SpeedProfile curvature_speed_profile(const Path& path, const CurvatureSpeedLimits& limits) {
  const std::vector<double> v = curvature_limited_speeds(path, limits);
  const double ds = path.length() / static_cast<double>(v.size() - 1);
  auto knots = std::make_shared<std::vector<SpeedKnot>>();
  knots->reserve(v.size());
  double t = 0.0;
  knots->push_back({0.0, v[0]});
  for (std::size_t i = 1; i < v.size(); ++i) {
    t += 2.0 * ds / (v[i - 1] + v[i]);
    knots->push_back({t, v[i]});
  }
  SpeedProfile profile;
  profile.initial_speed_mps = v.front();
  profile.final_speed_mps = v.back();
  profile.knots = std::move(knots);
  profile.validate();
  return profile;
}

}  // namespace smoothsteer
