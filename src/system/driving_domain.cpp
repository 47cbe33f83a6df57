#include "smoothsteer/system/driving_domain.hpp"

#include <algorithm>
#include <cmath>

namespace smoothsteer {

DrivingDomain DrivingDomain::for_vehicle(const VehicleParameters& vehicle) {
  vehicle.validate();
  DrivingDomain domain;
  const double wheelbase = vehicle.wheelbase_m();
  const double full_lock = std::tan(vehicle.max_steering_angle_rad) / wheelbase;
  domain.max_curvature_per_m = std::min(road_curvature_per_m, full_lock);
  domain.max_lateral_acceleration_mps2 =
      std::min(road_lateral_acceleration_mps2, vehicle.friction_limit_mps2());
  domain.max_curvature_rate_per_m2 = std::min(road_curvature_rate_per_m2, full_lock / wheelbase);
  domain.max_lateral_jerk_mps3 = road_lateral_jerk_mps3;
  return domain;
}

double DrivingDomain::curvature_at(double speed_mps) const noexcept {
  const double v2 = speed_mps * speed_mps;
  return v2 > 0.0 ? std::min(max_curvature_per_m, max_lateral_acceleration_mps2 / v2)
                  : max_curvature_per_m;
}

double DrivingDomain::curvature_rate_at(double speed_mps) const noexcept {
  const double v3 = std::abs(speed_mps * speed_mps * speed_mps);
  return v3 > 0.0 ? std::min(max_curvature_rate_per_m2, max_lateral_jerk_mps3 / v3)
                  : max_curvature_rate_per_m2;
}

std::optional<Violation> DrivingDomain::first_violation() const noexcept {
  RuleChecker check("DrivingDomain");
  check.require_positive({{"max_curvature_per_m", max_curvature_per_m},
                          {"max_lateral_acceleration_mps2", max_lateral_acceleration_mps2},
                          {"max_curvature_rate_per_m2", max_curvature_rate_per_m2},
                          {"max_lateral_jerk_mps3", max_lateral_jerk_mps3}});
  return check.first();
}

bool PathCurvatureDemand::beyond(const DrivingDomain& domain, double speed_mps) const noexcept {
  constexpr double slack = 1.0 + 1e-9;
  return max_curvature_per_m > domain.curvature_at(speed_mps) * slack ||
         max_curvature_rate_per_m2 > domain.curvature_rate_at(speed_mps) * slack;
}

PathCurvatureDemand curvature_demand(const Path& path) noexcept {
  PathCurvatureDemand demand;
  demand.max_curvature_per_m = path.max_abs_curvature();
  const std::span<const double> samples = path.curvature_samples();
  const double spacing = path.curvature_sample_spacing_m();
  for (std::size_t i = 1; i < samples.size(); ++i) {
    demand.max_curvature_rate_per_m2 =
        std::max(demand.max_curvature_rate_per_m2, std::abs(samples[i] - samples[i - 1]) / spacing);
  }
  return demand;
}

}  // namespace smoothsteer
