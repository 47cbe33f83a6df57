#pragma once
//! \file sensor_fault_gate.hpp
//! What keeps one bad gyro or accelerometer sample from poisoning SideSlipObserver
//! (docs/vehicle_dynamics.md, "sensor faults"). Three layers, in the order a sample meets them:
//!  1. plausibility (SensorPlausibility): a non-finite value is a dropped sample; a value beyond
//!     what the car can physically do is rejected: |a_y| beyond the tires' friction mu g plus a
//!     margin, |r| beyond both the kinematic yaw rate v tan(delta) / L and the friction's
//!     a_max / v, and a change from the last accepted sample (for r: from the filter's last
//!     estimate) faster than the tires' forces can turn or push the car; and a sample frozen
//!     at its previous value (bit for bit) while the wheels' kinematic yaw rate v tan(delta) / L
//!     (or its lateral acceleration v^2 tan(delta) / L) has moved by more than the noise margin
//!     since the freeze began: a stuck sensor;
//!  2. the innovation gate: a sample whose normalised innovation nu^2 / S (chi-square, one
//!     degree of freedom) exceeds SideSlipFaultGate::innovation_gate is rejected; the filter
//!     then only predicts that channel;
//!  3. recovery: an estimate at an implausible side slip (saturated), or one that no sample has
//!     corrected for a while, is not trusted (SteeringSystem then gives the law beta_r = 0), and
//!     after a while the filter restarts from the kinematic model (beta_r = 0, r from the gyro if
//!     it is plausible, else v tan(delta) / L).
//! The thresholds are far beyond the configured sensor noise: none fires on the shipped
//! scenarios' nominal runs (their traces are unchanged).

#include <cstdint>
#include <optional>

#include "smoothsteer/validation.hpp"

namespace smoothsteer {

struct SideSlipObserverParameters;
struct SideSlipMeasurement;

//! The observer's fault thresholds (SideSlipObserverParameters::fault_gate).
struct SideSlipFaultGate {
  //! nu^2 / S of one channel beyond which its sample is rejected: 25 = 5 sigma, which a
  //! Gaussian sample exceeds once in 1.7 million.
  double innovation_gate = 25.0;
  //! The plausibility bounds' margin on the friction's lateral acceleration mu g (load
  //! transfer, roll, a bump): a_max = (1 + margin) max(mu_f, mu_r) g [-].
  double friction_margin = 0.5;
  //! Multiples of the sensor noise's std added to every plausibility bound [-].
  double noise_margin = 6.0;
  //! |beta_r| beyond which the estimate is saturated and not trusted [rad]: far beyond the
  //! rear axle's peak slip angle, where a car no longer follows any path.
  double max_side_slip_rad = 0.3;
  //! Saturated this long [s]: the filter restarts from the kinematic model.
  double saturated_restart_s = 0.1;
  //! No correction accepted this long [s]: the estimate (the model's prediction alone) is not
  //! trusted ...
  double uncorrected_untrusted_s = 0.2;
  //! ... and after this long [s] the filter restarts from the kinematic model.
  double uncorrected_restart_s = 0.5;

  std::optional<Violation> first_violation(const char* owner, const char* prefix) const noexcept;
};

//! Why a sample was not used (bits; SideSlipObserverHealth::last_period).
enum SensorFault : std::uint32_t {
  fault_none = 0,
  fault_yaw_rate_dropped = 1u << 0,              //!< non-finite gyro sample
  fault_yaw_rate_implausible = 1u << 1,          //!< beyond the physical bounds
  fault_yaw_rate_innovation = 1u << 2,           //!< beyond the innovation gate
  fault_lateral_acceleration_dropped = 1u << 3,  //!< non-finite accelerometer sample
  fault_lateral_acceleration_implausible = 1u << 4,
  fault_lateral_acceleration_innovation = 1u << 5,
  fault_estimate_saturated = 1u << 6,  //!< |beta_r| beyond SideSlipFaultGate::max_side_slip_rad
  fault_uncorrected = 1u << 7,         //!< no correction for uncorrected_untrusted_s
  fault_restarted = 1u << 8,           //!< the filter restarted from the kinematic model
};

//! What the gates did: counts since reset() and the last period's faults.
struct SideSlipObserverHealth {
  std::uint64_t yaw_rate_dropped = 0;               //!< non-finite gyro samples
  std::uint64_t yaw_rate_rejected = 0;              //!< implausible or beyond the innovation gate
  std::uint64_t lateral_acceleration_dropped = 0;   //!< non-finite accelerometer samples
  std::uint64_t lateral_acceleration_rejected = 0;  //!< implausible or beyond the gate
  std::uint64_t restarts = 0;                       //!< re-initialisations from the model
  std::uint32_t last_period = fault_none;           //!< SensorFault bits of the last update()
  bool trusted = true;         //!< false: saturated or uncorrected; the law should not use it
  double saturated_s = 0.0;    //!< how long the estimate has been saturated [s]
  double uncorrected_s = 0.0;  //!< how long since a correction was accepted [s]
};

//! Layer 1: the physical bounds of one period's gyro and accelerometer samples. Remembers the
//! last accepted sample of each channel (the rate bounds). noexcept, allocation free.
class SensorPlausibility {
 public:
  explicit SensorPlausibility(const SideSlipObserverParameters& parameters) noexcept;

  struct Verdict {
    std::uint32_t faults = fault_none;  //!< the *_dropped and *_implausible bits
    bool use_yaw_rate = false;
    bool use_lateral_acceleration = false;
  };
  //! Judges the samples of `measurement` (speed and steering angle finite) after `period_s`.
  Verdict check(const SideSlipMeasurement& measurement, double period_s) noexcept;
  //! Forgets the last samples.
  void reset() noexcept;
  //! The gyro's rate bound then reads from the filter's yaw rate of the last period (which the
  //! accelerometer and the model keep near the truth while the gyro is rejected) instead of the
  //! last accepted sample: a sensor stuck far off stays rejected however long it sticks.
  void anchor_yaw_rate(double estimate_radps) noexcept { yaw_rate_ = {estimate_radps, 0.0, true}; }

  double max_lateral_acceleration_mps2() const noexcept { return max_lateral_acceleration_; }
  double max_yaw_acceleration_radps2() const noexcept { return max_yaw_acceleration_; }

 private:
  struct Channel {
    double value = 0.0;
    double elapsed_s = 0.0;  //!< since `value` was accepted
    bool known = false;
  };
  //! A channel's raw samples: the last one, and the kinematic reference when it froze.
  struct Freeze {
    double last = 0.0, reference = 0.0;
    bool known = false;
  };
  //! True while `value` repeats the previous sample bit for bit although `reference` moved by
  //! more than `noise` since the repetition began.
  static bool frozen(Freeze& freeze, double value, double reference, double noise) noexcept;
  //! Within `bound` and within `rate` * elapsed of the last accepted value (+ `noise`).
  static bool plausible(Channel& channel, double value, double bound, double rate, double noise,
                        double period_s) noexcept;

  double wheelbase_ = 0.0;
  double min_speed_ = 0.0;
  double max_lateral_acceleration_ = 0.0;  //!< a_max [m/s^2]
  double max_yaw_acceleration_ = 0.0;      //!< both axles at a_max, about the CG [rad/s^2]
  double max_lateral_jerk_ = 0.0;          //!< [m/s^3]
  double yaw_rate_noise_ = 0.0, lateral_acceleration_noise_ = 0.0;  //!< the noise margins
  Channel yaw_rate_, lateral_acceleration_;
  Freeze yaw_rate_freeze_, lateral_acceleration_freeze_;
};

}  // namespace smoothsteer
