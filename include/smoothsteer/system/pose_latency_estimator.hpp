#pragma once
//! \file pose_latency_estimator.hpp
//! Stage of SteeringSystem::update(): how old the pose is when the driving stack does not say.
//! Localization delivers the pose 20-100 ms late and often at a lower rate than the control loop,
//! while the gyro is on time; a law that takes a late pose as current steers the car as it was
//! (a 60 ms late pose cost the 10 m/s lane change 0.14 m against 0.009 m when the age was
//! given). The estimator compares the heading turned between two pose updates with the gyro's
//! integral over the same span, shifted back by each candidate lag j periods (j = 0 ... the
//! history's reach). Per lag it keeps the forgetting, span-weighted variance of the difference
//! per second: a gyro bias adds the same rate to every difference and drops out with the mean,
//! where the plain sum of squares took a bias of 0.005 rad/s for a lag. A lag replaces
//! the current one only where its sum is below `switch_ratio` times the current lag's, so a
//! straight road, where every lag fits alike, keeps what was learned; on time (lag 0 fits to the
//! gyro's noise) it stays 0. The pose's age is then the lag (refined between the grid lags by a
//! parabola through the sums) plus the time since the pose last changed (a pose at 10 Hz ages
//! by a period each period until the next). update() is noexcept, allocation free, O(lags).

#include <array>
#include <cstddef>

namespace smoothsteer {

class PoseLatencyEstimator {
 public:
  //! One control period: the pose's heading as delivered [rad], whether it is a new pose (it
  //! changed since the last period), the gyro's yaw rate [rad/s] and the period [s]. Returns the
  //! pose's estimated age [s], within [0, max_age_s].
  double update(double heading_rad, bool new_pose, double yaw_rate_radps, double period_s,
                double max_age_s) noexcept;
  //! A new engagement: the history starts again, the lag learned so far stays (the stack's
  //! latency is the stack's, not the engagement's).
  void restart() noexcept {
    count_ = head_ = since_pose_ = 0;
    integral_ = last_rate_ = since_pose_s_ = 0.0;
    has_pose_ = false;
  }
  //! Forgets the lag too (a new localization source).
  void reset() noexcept { *this = PoseLatencyEstimator{}; }
  //! The lag between the pose's time and its delivery [s], without the time since the last pose.
  double latency_s() const noexcept { return latency_s_; }

  //! The gyro history in periods: the candidate lags and the span between two poses together.
  static constexpr std::size_t history = 64;
  //! Candidate lags 0 ... max_lags - 1 periods (0.5 s at 50 Hz).
  static constexpr std::size_t max_lags = 26;
  //! Per pose update, the sums keep this share of what they had (about 200 poses of memory).
  static constexpr double forgetting = 0.995;
  //! A lag is adopted only where its misfit is below this share of the current lag's, and below
  //! it by at least min_evidence: the gyro's noise (0.002 rad/s at 50 Hz) leaves about 5e-7
  //! (rad/s)^2 s per pose between two lags that fit alike, a 30 ms lag through a lane change at
  //! 10 m/s about 1e-5 over the manoeuvre.
  static constexpr double switch_ratio = 0.5;
  static constexpr double min_evidence = 5e-6;

 private:
  std::array<double, history> turned_{};  //!< the gyro's integral at each period [rad]
  std::size_t count_ = 0;                 //!< periods recorded, up to history
  std::size_t head_ = 0;                  //!< where the next period goes
  double integral_ = 0.0;                 //!< the gyro's integral so far (trapezoid) [rad]
  double last_rate_ = 0.0;                //!< the gyro's last yaw rate [rad/s]
  //! Forgetting sums over the poses of the span [s], and per lag of the span times the
  //! difference per second [rad] and times its square [rad^2/s].
  double weight_ = 0.0;
  std::array<double, max_lags> first_{}, second_{};
  std::size_t since_pose_ = 0;  //!< periods since the last new pose
  double last_pose_heading_ = 0.0;
  bool has_pose_ = false;
  std::size_t lag_ = 0;        //!< the current grid lag [periods]
  double latency_s_ = 0.0;     //!< the refined lag [s]
  double since_pose_s_ = 0.0;  //!< time since the last new pose [s]
};

}  // namespace smoothsteer
