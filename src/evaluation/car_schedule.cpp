#include "car_schedule.hpp"

#include <filesystem>
#include <stdexcept>

#include "smoothsteer/runner/scenario.hpp"

namespace smoothsteer::detail {

std::vector<std::string> car_schedule(const std::string& scenario_file, const std::string& car) {
  const runner::Scenario scenario = runner::load_scenario(scenario_file);
  const YAML::Node schedule = scenario.controller["schedule"];
  if (!schedule || !schedule.IsScalar()) return {};
  const std::filesystem::path given(schedule.Scalar());
  const std::string name = given.filename().string();
  const std::string prefix = "passenger_car_";
  if (name.rfind(prefix, 0) != 0) return {};
  const std::filesystem::path own = given.parent_path() / (car + "_" + name.substr(prefix.size()));
  const std::filesystem::path resolved =
      own.is_relative() ? std::filesystem::path(scenario_file).parent_path() / own : own;
  if (!std::filesystem::is_regular_file(resolved)) {
    throw std::invalid_argument(scenario_file + ": the certified route of " + car + " needs " +
                                resolved.string() + " (smoothsteer tune with vehicles/" + car +
                                ".yaml, as the scenario's schedule was made)");
  }
  return {"controller.schedule=" + own.string()};
}

}  // namespace smoothsteer::detail
