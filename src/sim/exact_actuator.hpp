#pragma once
// The steering actuator's exact solution over one control period (internal to src/sim), rate
// and angle saturation included. The three equal lags
//   x0' = p (u - x0),  x1' = p (x0 - x1),  x2' = sat(p (x1 - x2))
// (SteeringActuator::derivative: the rate of the output x2 is clipped to +-R, and it is 0 while
// x2 sits at the angle limit +-A and would move outward) are, for a constant delayed input u,
// solved in closed form in each of five modes:
//   linear:      x2 follows the lags, x2 = u + (e2 + e1 q + e0 q^2 / 2) e^{-q};
//   rate +-:     x2 moves at +-R, x2 = x2(start) +- R tau;
//   angle +-:    x2 rests at +-A;
// with q = p tau and e_i = x_i(start) - u. x0 and x1 never saturate. A mode ends where its
// condition first fails (exp_polynomial.hpp locates that instant exactly); the period is split
// there, and at every change of the delayed input, into segments.

#include <array>

#include "smoothsteer/vehicle/steering_actuator.hpp"

namespace smoothsteer::detail {

enum class ActuatorMode { linear, rate_up, rate_down, angle_up, angle_down };

class ExactActuatorPeriod {
 public:
  //! Room for the segments of one period: at most two stretches of constant input (a held
  //! command behind a delay line of whole sub-steps) of a few modes each.
  static constexpr int max_segments = 24;

  //! Solves the period [0, substeps * substep_s] from the actuator state `start` with the
  //! delayed input inputs[j] on sub-step j. False if the segments do not fit (then nothing is
  //! usable; not reached on the shipped scenarios or in the tests).
  bool solve(const ActuatorParameters& parameters, const SteeringActuator::State& start,
             const double* inputs, int substeps, double substep_s) noexcept;

  //! State at time tau in [0, period] (tau past a segment's end extends that segment).
  SteeringActuator::State state(double tau) const noexcept;
  double angle(double tau) const noexcept { return state(tau)[2]; }
  int segments() const noexcept { return count_; }
  //! Offset of segment i in the period and its mode (for tests and the docs).
  double segment_start(int i) const noexcept { return segments_[index(i)].start_s; }
  ActuatorMode segment_mode(int i) const noexcept { return segments_[index(i)].mode; }

 private:
  struct Segment {
    double start_s = 0.0;
    ActuatorMode mode = ActuatorMode::linear;
    double input = 0.0;
    std::array<double, 3> deviation{};  //!< x_i(start) - input
    double output_start = 0.0;          //!< x2(start)
  };
  static std::size_t index(int i) noexcept { return static_cast<std::size_t>(i); }
  SteeringActuator::State at(const Segment& segment, double tau) const noexcept;
  //! Where `segment`'s mode ends within [0, length] (local time) and the mode after it;
  //! length + something when it lasts the whole stretch.
  double mode_end(const Segment& segment, double length, ActuatorMode& next) const noexcept;

  double pole_ = 0.0, max_rate_ = 0.0, max_angle_ = 0.0;
  std::array<Segment, max_segments> segments_{};
  int count_ = 0;
};

//! The mode the reference derivative (SteeringActuator::derivative) is in at state x.
ActuatorMode classify_actuator_mode(const SteeringActuator::State& x, double pole, double max_rate,
                                    double max_angle) noexcept;

}  // namespace smoothsteer::detail
