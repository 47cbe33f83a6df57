#pragma once
//! \file driving_domain.hpp
//! The paths a steering system is built for when no path is known at set-up: a driving stack
//! starts with none and hands over a new trajectory every 0.1 s (set_path()). The domain bounds
//! the path's curvature and curvature rate at each speed, and shrinks with speed the way roads
//! do: a road's curvature is at most its design lateral acceleration over v^2, and its curvature
//! rate at most its lateral jerk over v^3 (a clothoid driven at v turns its lateral acceleration
//! v^2 kappa at v^3 d kappa / ds). The tuner certifies the gain schedule for the domain at each
//! speed (make_steering_system(car, options), docs/steering_system.md); a path beyond it is
//! followed as well as the limits allow and flagged (limit_path_beyond_domain).

#include <optional>
#include <string>

#include "smoothsteer/path/path.hpp"
#include "smoothsteer/validation.hpp"
#include "smoothsteer/vehicle/vehicle_parameters.hpp"

namespace smoothsteer {

struct DrivingDomain {
  //! Largest |kappa| of a path at any speed [1/m] (at low speed: parking, hairpins).
  double max_curvature_per_m = road_curvature_per_m;
  //! Largest lateral acceleration a path asks of the car [m/s^2]: |kappa| <= this / v^2.
  double max_lateral_acceleration_mps2 = road_lateral_acceleration_mps2;
  //! Largest |d kappa / ds| of a path at any speed [1/m^2] (a curvature jump has none: the
  //! feedforward plans it as a ramp, docs/feedforward.md).
  double max_curvature_rate_per_m2 = road_curvature_rate_per_m2;
  //! Largest lateral jerk a path asks [m/s^3]: |d kappa / ds| <= this / v^3.
  double max_lateral_jerk_mps3 = road_lateral_jerk_mps3;

  //! The roads a planner sends, as for_vehicle() caps them. A wider domain costs switching
  //! authority on every path (docs/steering_system.md measures it); a path beyond it is flagged.
  //! 4 m/s^2 (0.4 g): beyond it a passenger car's tires leave their linear range.
  static constexpr double road_lateral_acceleration_mps2 = 4.0;
  //! Road clothoids keep below 1 m/s^3; the urban turn, the roundabout and the hairpins of the
  //! road suite ask up to 5; the ISO double lane change, an evasive manoeuvre, 21 at 15 m/s.
  static constexpr double road_lateral_jerk_mps3 = 5.0;
  //! A 5 m radius at the rear axle: a passenger car's turning circle.
  static constexpr double road_curvature_per_m = 0.2;
  //! Full road curvature within 4 m.
  static constexpr double road_curvature_rate_per_m2 = 0.05;

  //! The road domain for `vehicle`: each road bound above, capped by what the car can do (its
  //! full steering angle tan(max_steering_angle) / (lf + lr), that over one wheelbase as the
  //! curvature rate, its tires' friction limit mu g).
  static DrivingDomain for_vehicle(const VehicleParameters& vehicle);

  //! Largest |kappa| at |v| = speed_mps [1/m]: min(max_curvature, a / v^2).
  double curvature_at(double speed_mps) const noexcept;
  //! Largest |d kappa / ds| at |v| = speed_mps [1/m^2]: min(max_curvature_rate, j / v^3).
  double curvature_rate_at(double speed_mps) const noexcept;

  //! The first rule broken (validation.hpp): every field finite and > 0.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  std::string validation_error() const { return describe(first_violation()); }
  void validate() const { throw_if_violated(first_violation()); }
};

//! What a path asks at its worst: its largest |kappa| and |d kappa / ds| (from its curvature
//! samples, Path::curvature_samples(); a jump counts as jump / sample spacing).
struct PathCurvatureDemand {
  double max_curvature_per_m = 0.0;
  double max_curvature_rate_per_m2 = 0.0;
  //! True where the path asks more than `domain` allows at |v| = speed_mps (1e-9 relative slack).
  bool beyond(const DrivingDomain& domain, double speed_mps) const noexcept;
};

//! The demand of `path`, from its curvature samples: O(samples), no allocation (set_path() time).
PathCurvatureDemand curvature_demand(const Path& path) noexcept;

}  // namespace smoothsteer
