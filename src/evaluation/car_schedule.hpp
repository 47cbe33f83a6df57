#pragma once
// The certified route of another car (internal): a scenario's `controller.schedule:
// .../passenger_car_<X>.csv` becomes `.../<car>_<X>.csv`, the schedule that the same
// `smoothsteer tune` command gives with vehicles/<car>.yaml. Used by the comparisons that run a
// scenario with several cars (the road suite, the robustness comparison).

#include <string>
#include <vector>

namespace smoothsteer::detail {

//! The override "controller.schedule=<car's schedule>" for `scenario_file` run with `car` (a
//! vehicle file's stem); empty when the scenario has no passenger_car_* schedule. Throws
//! std::invalid_argument naming the missing file when the car's schedule does not exist.
std::vector<std::string> car_schedule(const std::string& scenario_file, const std::string& car);

}  // namespace smoothsteer::detail
