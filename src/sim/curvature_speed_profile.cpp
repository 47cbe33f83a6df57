#include "smoothsteer/sim/curvature_speed_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

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
  if (!(cusp_rest_s > 0.0 && cusp_rest_s <= 60.0)) {
    return bad("cusp_rest_s", cusp_rest_s, "must be in (0, 60]");
  }
  return std::nullopt;
}

namespace {

//! Intervals of the grid on a path of `length`; std::invalid_argument before any allocation
//! when the grid would have more than max_speed_grid_points points (a 2e7 m line took 31 s and
//! 2.85 GB, and 1e8 m ended in std::bad_alloc).
double grid_intervals(double length, double spacing) {
  const double intervals = std::max(1.0, std::ceil(length / spacing));
  if (!(intervals < static_cast<double>(max_speed_grid_points))) {
    std::ostringstream message;
    message << "CurvatureSpeedLimits: the path is " << length << " m long, " << intervals
            << " grid intervals of spacing_m = " << spacing << " m; at most "
            << max_speed_grid_points << " grid points (a path of at most "
            << spacing * static_cast<double>(max_speed_grid_points - 1) << " m)";
    throw std::invalid_argument(message.str());
  }
  return intervals;
}

//! The limited speeds with v(0) <= first and v(end) <= last.
std::vector<double> limited_speeds(const Path& path, const CurvatureSpeedLimits& limits,
                                   double first, double last) {
  limits.validate();
  const double length = path.length();
  const auto intervals = static_cast<std::size_t>(grid_intervals(length, limits.spacing_m));
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
  v[0] = std::min(v[0], first);
  v.back() = std::min(v.back(), last);
  for (std::size_t i = 1; i <= intervals; ++i) {
    v[i] = std::min(v[i], std::sqrt(v[i - 1] * v[i - 1] + 2.0 * limits.max_acceleration_mps2 * ds));
  }
  for (std::size_t i = intervals; i-- > 0;) {
    v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2.0 * limits.max_deceleration_mps2 * ds));
  }
  return v;
}

//! Appends the knots of speeds `v` on a grid of `ds`, times `sign`, from the last knot's time
//! (whose speed is v[0]).
void append_knots(std::vector<SpeedKnot>& knots, const std::vector<double>& v, double ds,
                  double sign) {
  double t = knots.back().time_s;
  for (std::size_t i = 1; i < v.size(); ++i) {
    t += 2.0 * ds / (v[i - 1] + v[i]);
    knots.push_back({t, sign * v[i]});
  }
}

}  // namespace

std::vector<double> curvature_limited_speeds(const Path& path, const CurvatureSpeedLimits& limits) {
  return limited_speeds(path, limits, limits.initial_speed_mps.value_or(limits.max_speed_mps),
                        std::numeric_limits<double>::infinity());
}

SpeedProfile curvature_speed_profile(const Path& path, const CurvatureSpeedLimits& limits) {
  const std::vector<double> v = curvature_limited_speeds(path, limits);
  const double ds = path.length() / static_cast<double>(v.size() - 1);
  auto knots = std::make_shared<std::vector<SpeedKnot>>();
  knots->reserve(v.size());
  knots->push_back({0.0, v[0]});
  append_knots(*knots, v, ds, 1.0);
  SpeedProfile profile;
  profile.initial_speed_mps = v.front();
  profile.final_speed_mps = v.back();
  profile.knots = std::move(knots);
  profile.validate();
  return profile;
}

SpeedProfile curvature_speed_profile(const PathPlan& plan, const CurvatureSpeedLimits& limits) {
  limits.validate();
  // All pieces together on one grid budget, checked before any piece is sampled.
  double total_length = 0.0;
  for (std::size_t p = 0; p < plan.piece_count(); ++p) total_length += plan.piece(p).path->length();
  grid_intervals(total_length + limits.spacing_m * static_cast<double>(plan.piece_count()),
                 limits.spacing_m);
  auto knots = std::make_shared<std::vector<SpeedKnot>>();
  const bool stops = plan.cusp_count() > 0;
  for (std::size_t p = 0; p < plan.piece_count(); ++p) {
    const Path& path = *plan.piece(p).path;
    const double sign = gear_sign(plan.piece(p).gear);
    if (!(path.length() > 2.0 * limits.spacing_m)) {
      throw std::invalid_argument("CurvatureSpeedLimits: pieces[" + std::to_string(p) + "] is " +
                                  std::to_string(path.length()) +
                                  " m long; a piece between stops needs more than two grid "
                                  "spacings (spacing_m)");
    }
    const double first = p == 0 ? limits.initial_speed_mps.value_or(limits.max_speed_mps) : 0.0;
    const double last = stops ? 0.0 : std::numeric_limits<double>::infinity();
    const std::vector<double> v = limited_speeds(path, limits, first, last);
    const double ds = path.length() / static_cast<double>(v.size() - 1);
    if (p == 0) {
      knots->push_back({0.0, sign * v[0]});
    } else {
      knots->push_back({knots->back().time_s + limits.cusp_rest_s, 0.0});  // the gear change
    }
    append_knots(*knots, v, ds, sign);
  }
  SpeedProfile profile;
  profile.signed_speeds = true;
  profile.initial_speed_mps = knots->front().speed_mps;
  profile.final_speed_mps = knots->back().speed_mps;
  profile.knots = std::move(knots);
  profile.validate();
  return profile;
}

}  // namespace smoothsteer
