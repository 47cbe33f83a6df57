#pragma once
//! \file waypoint_conditioner.hpp
//! A driving stack's trajectory windows, fitted one after another (docs/controller.md, "Paths as
//! they come"). A planner sends a window every 0.1 s; its jitter is the planner's, the same from
//! window to window, while one window's estimate (estimate_waypoint_jitter) misses it by up to
//! 25 %. A tolerance below the jitter leaves its curvature in the path, which at motorway speed
//! costs far more than a tolerance above it (the road suite's motorway exit at 25 m/s, 5 mm of
//! jitter: 0.13 m of tracking error fitted at each window's own estimate, 0.02-0.04 m at the
//! pooled one). The conditioner pools the estimate over the windows and fits each at it, together
//! with the earlier windows' waypoints behind it (Parameters::history_m): a window starts a few
//! metres behind the car, where a fit of it alone is least sure of the road.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "smoothsteer/math/vec2.hpp"
#include "smoothsteer/path/path.hpp"
#include "smoothsteer/validation.hpp"

namespace smoothsteer {

class WaypointConditioner {
 public:
  struct Parameters {
    //! The windows the pooled estimate remembers: the mean of the estimated variances over the
    //! first ones, then an exponential memory of this many windows, in [1, 1e6].
    double memory_windows = 20.0;
    //! The least tolerance each window is fitted with [m] (WaypointSmoothing::tolerance_m), in
    //! [0, 10].
    double tolerance_m = 0.0;
    //! How far behind a jittered window's first waypoint the waypoints of the windows before it
    //! are fitted with it [m], in [0, 1000]; 0 fits each window alone. 20 m puts the car, 5 m
    //! into a window, inside the fit (docs/controller.md, "Paths as they come").
    double history_m = 20.0;

    //! The first rule broken (validation.hpp); is_valid(), validation_error(), validate() use it.
    std::optional<Violation> first_violation() const noexcept;
    bool is_valid() const noexcept { return !first_violation(); }
    std::string validation_error() const { return describe(first_violation()); }
    void validate() const { throw_if_violated(first_violation()); }
  };

  //! The default Parameters.
  WaypointConditioner();
  //! Throws std::invalid_argument naming the field, the value and the rule (validate()).
  explicit WaypointConditioner(Parameters parameters);

  //! Pools this window's jitter estimate and fits it: Path::from_waypoints at the tolerance
  //! max(tolerance_m, sqrt(2) jitter_m()), with the last windows' waypoints up to history_m
  //! behind its first one when it continues the last window (its first waypoint within 4
  //! tolerances + 2 cm of the last fit and ahead of the last window's start); the Path starts
  //! at its first waypoint. Clean windows keep the estimate at 0 and are interpolated exactly.
  //! Throws what Path::from_waypoints throws (the estimate is then not pooled). Set-up time
  //! (allocates), O(n).
  Path fit(const std::vector<Vec2>& waypoints);

  //! The pooled jitter per coordinate [m]; 0 before the first window.
  double jitter_m() const noexcept;
  //! The tolerance the last window was fitted with [m].
  double tolerance_m() const noexcept { return last_tolerance_m_; }
  //! Windows pooled so far.
  std::size_t windows() const noexcept { return windows_; }
  //! Forgets the estimate (another planner).
  void reset() noexcept;

  const Parameters& parameters() const noexcept { return parameters_; }

 private:
  std::vector<Vec2> history_behind(const std::vector<Vec2>& waypoints, double tolerance) const;
  Path fit_with_history(const std::vector<Vec2>& behind, const std::vector<Vec2>& waypoints,
                        double tolerance) const;

  Parameters parameters_;
  double pooled_variance_ = 0.0;  //!< [m^2]
  std::size_t windows_ = 0;
  double last_tolerance_m_ = 0.0;
  std::vector<Vec2> history_;   //!< earlier windows' waypoints behind the last one's start
  std::vector<Vec2> previous_;  //!< the last window's waypoints
  std::optional<Path> previous_path_;
};

}  // namespace smoothsteer
