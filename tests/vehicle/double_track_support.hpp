#pragma once
// Shared helpers of the double-track tests: a car with the double-track group, open-loop RK4.

#include <functional>

#include "smoothsteer/vehicle/double_track.hpp"

namespace smoothsteer::testing {

//! CommonRoad vehicle 2 (the defaults) with the double-track group's defaults.
inline VehicleParameters double_track_car() {
  VehicleParameters car;
  car.double_track.emplace();
  return car;
}

using Derivative = std::function<VehicleState(const VehicleState&, double time)>;

//! Classic RK4 of `f` from `state` over `duration` at step `h`; `each` sees every step's end.
inline VehicleState integrate_rk4(
    const Derivative& f, VehicleState state, double duration, double h,
    const std::function<void(const VehicleState&, double)>& each = {}) {
  const int steps = static_cast<int>(duration / h + 0.5);
  using Array = std::array<double, VehicleState::size>;
  auto eval = [&](const Array& y, double t) {
    return f(VehicleState::from_array(y), t).to_array();
  };
  auto shifted = [](const Array& y, const Array& k, double scale) {
    Array out = y;
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += scale * k[i];
    return out;
  };
  Array y = state.to_array();
  for (int n = 0; n < steps; ++n) {
    const double t = n * h;
    const Array k1 = eval(y, t);
    const Array k2 = eval(shifted(y, k1, 0.5 * h), t + 0.5 * h);
    const Array k3 = eval(shifted(y, k2, 0.5 * h), t + 0.5 * h);
    const Array k4 = eval(shifted(y, k3, h), t + h);
    for (std::size_t i = 0; i < y.size(); ++i) {
      y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    if (each) each(VehicleState::from_array(y), t + h);
  }
  return VehicleState::from_array(y);
}

inline VehicleState straight_at(double speed) {
  VehicleState s;
  s.vx_mps = speed;
  return s;
}

}  // namespace smoothsteer::testing
