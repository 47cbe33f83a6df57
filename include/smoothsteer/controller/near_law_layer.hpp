#pragma once
//! \file near_law_layer.hpp
//! Part of the governor stage (governor_stage.hpp) of LeadWheelController::compute_command(): the
//! boundary layer of the near-path law (docs/governor.md, "Stiff on steady stretches").
//!
//! The certified near law keeps the split certificate's boundary layer epsilon, whose linear zone
//! kappa_sw = -e / l^2 - 2 psi / l has the length l = 2 epsilon / kbar_sw: 11 m at 10 m/s and
//! 23 m at 15 m/s for the passenger car's block. That softness is right while the path's
//! curvature moves (a stiffer law rings against the tires' slip lag: the 15 m/s lane change goes
//! from 0.030 to 0.099 m with a 2 m law throughout), but on a steady stretch it turns every
//! disturbance the estimate has not yet learned into an offset kappa_d l^2 that decays over tens
//! of metres (a 0.3 deg rack offset: 0.15 m on the 10 m/s lane change, 0.36 m at 15 m/s).
//!
//! So the layer follows the path's activity: the certified epsilon while the path's curvature at
//! the lead wheel moves (lateral jerk v^3 |d kappa / ds| at or above active_lateral_jerk_mps3,
//! with a memory of activity_memory_m), and on steady stretches the layer of the critically damped
//! linear zone whose heading time constant l / (2 v) is steady_time_constant_s, growing with the
//! speed above 13.3 m/s. It is never wider than the certified one and the authority stays the
//! certified kbar_sw, so |kappa_sw| <= kbar_sw as before; the governor holds the car's rate and
//! acceleration limits on the held command.
//!
//! The certified epsilon's softness is what a reversal of the path's curvature asks for (the
//! lane change's ringing). A tight corner without one ahead or just behind (a hairpin) takes at
//! most single_corner_layer instead: the block's 0.03 lets the car run wide where the tires'
//! slip builds up later than the linear model says (the 12 m hairpin at 6 m/s^2: 0.078 ->
//! 0.050 m), and 0.01 throughout rang in the 15 m/s lane change (0.030 -> 0.052 m;
//! docs/governor.md, "A tight single corner takes a stiffer layer").

#include <algorithm>
#include <cmath>
#include <limits>

#include "smoothsteer/path/path.hpp"

namespace smoothsteer {

class NearLawLayer {
 public:
  //! Heading time constant l / (2 v) of the near law on steady stretches [s]: l = 2 m at 10 m/s.
  //! 0.07 s was better still against a rack offset (10 m/s lane change 0.025 m against 0.033 m)
  //! and 0.2 s gives most of it away (0.059 m); 0.1 s keeps the law slower than the 10 Hz
  //! actuator's lag by a factor of about two.
  static constexpr double steady_time_constant_s = 0.1;
  //! Above 13.3 m/s the time constant grows with the speed, 7.5 ms per m/s (0.225 s at 30 m/s):
  //! the car's yaw mode is less damped at speed, and the motorway run at 30 / 35 m/s rang
  //! (0.28 / 0.60 m) with 0.1 s throughout, 0.22 / 0.26 m with 3.75 ms per m/s and 0.042 /
  //! 0.062 m with 5 ms per m/s, as with the certified layer (0.041 / 0.066 m).
  static constexpr double steady_time_constant_per_speed_s2pm = 0.0075;
  //! The shortest steady law [m]: at walking pace the law does not get shorter than this.
  static constexpr double min_steady_length_m = 1.0;
  //! Lateral jerk of the path at the lead wheel at and above which the path counts as moving
  //! [m/s^3], the threshold of the road-design comfort band (0.5-0.6 m/s^3).
  static constexpr double active_lateral_jerk_mps3 = 0.5;
  //! How far the activity is remembered [m]: its envelope decays by e over this distance, so a
  //! manoeuvre's 5 m/s^3 is forgotten about 25 m after it. 30 m kept the law soft for 7 s after
  //! the 10 m/s lane change (the 0.13 m a biased side-slip estimate then holds, instead of
  //! 0.02 m); 5-10 m changed no shipped figure by more than 1 cm.
  static constexpr double activity_memory_m = 10.0;

  //! How far ahead a reversal of the path's curvature keeps the certified layer [s of travel]:
  //! the lane change's next lobe is within reach from the start of the one before.
  static constexpr double reversal_lookahead_s = 3.0;
  //! How far past the last reversal seen ahead the certified layer stays [m]: the slip's
  //! transient of the last lobe (a stiff law switched on in the last lobe rang: 15 m/s lane
  //! change 0.046 m; 20 and 40 m gave the same figures).
  static constexpr double reversal_memory_m = 20.0;
  //! Curvature below which a sign does not count as the path turning that way [1/m] (a 500 m
  //! radius).
  static constexpr double reversal_curvature_per_m = 0.002;
  //! The near law's layer on a corner without a reversal: ControllerParameters' default
  //! boundary layer.
  static constexpr double single_corner_layer = 0.01;
  //! The lateral acceleration from which a corner takes single_corner_layer [m/s^2]: where the
  //! tires' slip gradient has grown by a tenth (the passenger car's Magic Formula: 1.1x at
  //! 3 m/s^2, 1.5x at 6 m/s^2). Below it the path's own noise decides more than the tires (a
  //! planner's windows jittered by 2 cm: the rural road at 22 m/s 0.03 -> 0.08 m with the stiff
  //! layer on its gentle bends).
  static constexpr double single_corner_lateral_acceleration_mps2 = 3.0;

  //! What the path within a reach ahead of the lead wheel asks of the near law's layer.
  struct PathAhead {
    bool reversal = false;  //!< the curvature takes both signs beyond reversal_curvature_per_m
    bool gentle = false;    //!< its lateral acceleration stays below the single corner's
  };
  //! The path within `reach_m` ahead of `arc_length_m` at `speed_mps`, read from its curvature
  //! samples at 13 points (O(1) each).
  static PathAhead path_ahead(const Path& path, double arc_length_m, double reach_m,
                              double speed_mps) noexcept {
    const double spacing = path.curvature_sample_spacing_m();
    bool left = false, right = false;
    double largest = 0.0;
    for (int i = 0; i <= 12; ++i) {
      const double s = arc_length_m + reach_m * static_cast<double>(i) / 12.0;
      const double curvature = path.curvature_sample(std::lround(s / spacing));
      left = left || curvature > reversal_curvature_per_m;
      right = right || curvature < -reversal_curvature_per_m;
      largest = std::max(largest, std::abs(curvature));
    }
    return {.reversal = left && right,
            .gentle = speed_mps * speed_mps * largest < single_corner_lateral_acceleration_mps2};
  }

  //! A new engagement: no memory of the path's activity (the law starts stiff on a steady path)
  //! or of its reversals.
  void reset() noexcept {
    activity_mps3_ = 0.0;
    has_previous_ = false;
    travelled_m_ = 0.0;
    certified_until_m_ = -std::numeric_limits<double>::infinity();
    tight_until_m_ = -std::numeric_limits<double>::infinity();
  }
  //! Once per control period, with observe(): the path ahead (path_ahead()). Both a reversal
  //! and a tight corner are remembered for reversal_memory_m of travel after they leave the
  //! reach (the transient of the last lobe, or of a corner's exit).
  void observe_ahead(const PathAhead& ahead, double travelled_m) noexcept {
    travelled_m_ += travelled_m;
    if (ahead.reversal) certified_until_m_ = travelled_m_ + reversal_memory_m;
    if (!ahead.gentle) tight_until_m_ = travelled_m_ + reversal_memory_m;
  }
  //! The layer the near law is certified with here: the certified epsilon within reach of a
  //! reversal or on a gentle path, at most single_corner_layer on a tight corner.
  double certified_layer(double certified) const noexcept {
    const bool tight = travelled_m_ > certified_until_m_ && travelled_m_ <= tight_until_m_;
    return tight ? std::min(certified, single_corner_layer) : certified;
  }
  //! Once per control period: the path's curvature at the lead wheel's closest point [1/m]
  //! (the path's own, free of the sensors' noise) after travelling travelled_m at speed_mps.
  void observe(double path_curvature, double travelled_m, double speed_mps) noexcept {
    if (has_previous_ && travelled_m > 0.0) {
      const double v = std::abs(speed_mps);
      const double jerk = v * v * v * std::abs(path_curvature - previous_curvature_) / travelled_m;
      activity_mps3_ = std::max(jerk, activity_mps3_ * std::exp(-travelled_m / activity_memory_m));
    }
    previous_curvature_ = path_curvature;
    has_previous_ = true;
  }
  //! The path's activity: a decaying envelope of its lateral jerk at the lead wheel [m/s^3].
  double activity_mps3() const noexcept { return activity_mps3_; }
  //! The near law's boundary layer for the certified layer epsilon and authority kbar_sw at
  //! speed_mps: epsilon while the path moves, the steady law's l kbar_sw / 2 (at most epsilon)
  //! where it is steady, blended linearly in between.
  double layer(double certified_layer, double switching_bound, double speed_mps) const noexcept {
    const double v = std::abs(speed_mps);
    const double time_constant =
        std::max(steady_time_constant_s, steady_time_constant_per_speed_s2pm * v);
    const double length = std::max(min_steady_length_m, 2.0 * time_constant * v);
    const double steady = std::min(certified_layer, 0.5 * length * switching_bound);
    const double moving = std::clamp(activity_mps3_ / active_lateral_jerk_mps3, 0.0, 1.0);
    return moving * certified_layer + (1.0 - moving) * steady;
  }

 private:
  double activity_mps3_ = 0.0;
  double previous_curvature_ = 0.0;
  bool has_previous_ = false;
  double travelled_m_ = 0.0;  //!< since the engagement [m]
  double certified_until_m_ = -std::numeric_limits<double>::infinity();
  double tight_until_m_ = -std::numeric_limits<double>::infinity();
};

}  // namespace smoothsteer
