#include "smoothsteer/tuning/static_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "smoothsteer/tuning/invariant_bounds.hpp"
#include "smoothsteer/tuning/worst_case.hpp"

namespace smoothsteer {

std::optional<Violation> StaticMapOptions::first_violation() const noexcept {
  RuleChecker check("StaticMapOptions");
  check.require(ratio_min > 0.0 && ratio_min < 1.0, "ratio_min", ratio_min, "must be in (0, 1)");
  check.require(ratio_max > ratio_min && ratio_max < 1.0, "ratio_max", ratio_max,
                "must be in (ratio_min, 1)");
  check.require(ratio_samples >= 2 && ratio_samples <= 100000, "ratio_samples", ratio_samples,
                "must be in [2, 100000]");
  check.require(max_steering_angle_rad > 0.0 && max_steering_angle_rad < 1.5,
                "max_steering_angle_rad", max_steering_angle_rad,
                "must be in (0, 1.5) (the chain degenerates near pi/2)");
  check.require(angle_samples >= 2 && angle_samples <= 100000, "angle_samples", angle_samples,
                "must be in [2, 100000]");
  return check.first();
}

StaticMap::StaticMap(const StaticMapOptions& options) : options_(options) {
  options_.validate();
  const int angles = options_.angle_samples;
  q_.resize(static_cast<std::size_t>(angles) + 1);
  for (int j = 0; j <= angles; ++j) {
    q_[static_cast<std::size_t>(j)] = std::sin(options_.max_steering_angle_rad * j / angles);
  }
  table_.assign(static_cast<std::size_t>(options_.ratio_samples) * q_.size(), MapValue{});
  ControllerParameters base;
  base.k_rob = 0.0;
  for (int i = 0; i < options_.ratio_samples; ++i) {
    const double ratio = ratio_at(i);
    for (int j = 1; j <= angles; ++j) {
      // lambda_veh = 1: the worst case at (r, q) is the dimensionless value itself.
      const ControllerParameters p =
          second_order_parameters(base, 1.0, ratio, q_[static_cast<std::size_t>(j)], 0.0);
      const SteeringDerivatives worst = worst_case_steering_derivatives(p);
      table_[static_cast<std::size_t>(i) * q_.size() + static_cast<std::size_t>(j)] = {
          worst.rate_per_meter, worst.acceleration_per_meter2};
    }
  }
}

double StaticMap::ratio_at(int index) const noexcept {
  return options_.ratio_min +
         (options_.ratio_max - options_.ratio_min) * index / (options_.ratio_samples - 1);
}

MapValue StaticMap::lookup_node(int ratio_index, double q) const noexcept {
  const std::size_t columns = q_.size();
  const MapValue* row = table_.data() + static_cast<std::size_t>(ratio_index) * columns;
  if (!(q > 0.0)) return {};
  if (q >= q_.back()) return row[columns - 1];
  const auto upper =
      static_cast<std::size_t>(std::upper_bound(q_.begin(), q_.end(), q) - q_.begin());
  const std::size_t lower = upper - 1;
  const double t = (q - q_[lower]) / (q_[upper] - q_[lower]);
  return {row[lower].rate + t * (row[upper].rate - row[lower].rate),
          row[lower].acceleration + t * (row[upper].acceleration - row[lower].acceleration)};
}

MapValue StaticMap::lookup(double ratio, double q) const noexcept {
  const MapValue value = interpolate(ratio, q);
  return {lookup_safety_factor * value.rate, lookup_safety_factor * value.acceleration};
}

MapValue StaticMap::interpolate(double ratio, double q) const noexcept {
  const double position =
      (std::clamp(ratio, options_.ratio_min, options_.ratio_max) - options_.ratio_min) /
      (options_.ratio_max - options_.ratio_min) * (options_.ratio_samples - 1);
  const int low = std::clamp(static_cast<int>(std::floor(position)), 0, options_.ratio_samples - 1);
  const MapValue a = lookup_node(low, q);
  if (position - low < 1e-12 || low + 1 >= options_.ratio_samples) return a;
  const MapValue b = lookup_node(low + 1, q);
  return {std::max(a.rate, b.rate), std::max(a.acceleration, b.acceleration)};
}

MapValue StaticMap::lookup(double vehicle_wheelbase_m, double lead_wheelbase_m,
                           double lead_curvature_bound) const noexcept {
  const MapValue v =
      lookup(lead_wheelbase_m / vehicle_wheelbase_m, lead_curvature_bound * vehicle_wheelbase_m);
  return {v.rate / vehicle_wheelbase_m,
          v.acceleration / (vehicle_wheelbase_m * vehicle_wheelbase_m)};
}

}  // namespace smoothsteer
