#pragma once
//! \file static_map.hpp
//! The static map of paper Sec. III items 4-5 for n = 2: the worst-case |delta_veh'| and
//! |delta_veh''| per unit path length as a function of (lambda_l, kbar_l), with lambda from eq.
//! (cornering_constr), tabulated for fast lookup.
//!
//! Scaling all lengths by c scales d/ds by 1/c, so the table is dimensionless:
//!   rate_per_meter * lambda_veh            = R(r, q)
//!   acceleration_per_meter2 * lambda_veh^2 = A(r, q),   r = lambda_l / lambda_veh,
//!                                                        q = kbar_l lambda_veh = sin(dbar_veh).
//! Nodes: r on a uniform grid in [ratio_min, ratio_max], q = sin(theta) on a uniform grid of the
//! real steering-angle bound theta in [0, max_steering_angle_rad] (q = 0 gives 0).
//! Lookup: linear in q between nodes, then the larger of the two neighbouring r nodes, times
//! lookup_safety_factor (the first two steps alone can underestimate by ~0.1 %).
//! tests/tuning checks the table never underestimates the exact worst case.

#include <vector>
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct StaticMapOptions {
  double ratio_min = 0.02;               //!< smallest lambda_l / lambda_veh
  double ratio_max = 0.98;               //!< largest lambda_l / lambda_veh (< 1)
  int ratio_samples = 97;                //!< r nodes (step 0.01 with the defaults)
  double max_steering_angle_rad = 1.45;  //!< largest tabulated dbar_veh (< pi/2)
  int angle_samples = 48;                //!< theta nodes above 0
  //! The first rule broken (validation.hpp); is_valid(), validation_error() and validate() use it.
  std::optional<Violation> first_violation() const noexcept;
  bool is_valid() const noexcept { return !first_violation(); }
  //! Empty when valid, else "<Struct>: <field> = <value> <rule>".
  std::string validation_error() const { return describe(first_violation()); }
  //! Throws std::invalid_argument with validation_error().
  void validate() const { throw_if_violated(first_violation()); }
};

struct MapValue {
  double rate = 0.0;          //!< R: worst |d delta_veh / ds| * lambda_veh
  double acceleration = 0.0;  //!< A: worst |d2 delta_veh / ds2| * lambda_veh^2
};

class StaticMap {
 public:
  //! Builds the table (exact worst case at every node; about 5000 2-D optimisations).
  explicit StaticMap(const StaticMapOptions& options = {});

  const StaticMapOptions& options() const noexcept { return options_; }
  int ratio_count() const noexcept { return options_.ratio_samples; }
  double ratio_at(int index) const noexcept;
  //! Largest tabulated q = sin(max_steering_angle_rad).
  double max_q() const noexcept { return q_.back(); }

  //! Relative margin on every lookup. Chord interpolation in q and the larger r neighbour are
  //! upper bounds only where R and A are convex in q and monotone in r between nodes; near
  //! lambda_l ~ 0.9 lambda_veh they are not quite, by up to ~0.1 % (found by the property test at
  //! 400 cases). 1 % covers that with margin; tests/tuning checks it over many random states.
  static constexpr double lookup_safety_factor = 1.01;

  //! Dimensionless lookup, scaled by lookup_safety_factor; r is clamped into
  //! [ratio_min, ratio_max], q into [0, max_q()].
  MapValue lookup(double ratio, double q) const noexcept;
  //! Lookup at the r node `index` (no interpolation in r).
  MapValue lookup_node(int ratio_index, double q) const noexcept;
  //! Dimensional: worst |d delta_veh/ds| [rad/m] and |d2 delta_veh/ds2| [rad/m^2].
  MapValue lookup(double vehicle_wheelbase_m, double lead_wheelbase_m,
                  double lead_curvature_bound) const noexcept;

 private:
  MapValue interpolate(double ratio, double q) const noexcept;

  StaticMapOptions options_;
  std::vector<double> q_;        //!< angle_samples + 1 nodes, q_[0] = 0
  std::vector<MapValue> table_;  //!< [ratio_index * q_.size() + q_index]
};

}  // namespace smoothsteer
