// Reference for tests/test_update.py: LeadWheelController::update() in C++ on the inputs read
// from stdin, one "x y heading speed acceleration period" line per call, on the path and
// parameters given as arguments. Prints "status delta rate acceleration e e_front e_lead sigma"
// per call with 17 significant digits, so that Python's results can be compared exactly, or
// "invalid MESSAGE" once for parameters the controller rejects.
//
// usage: python_update_reference circle|waypoints ORDER KBAR K_ROB FF_SHARE DELAY_S

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "smoothsteer/smoothsteer.hpp"

int main(int argc, char** argv) {
  using namespace smoothsteer;
  if (argc != 7) {
    std::fprintf(stderr, "usage: %s circle|waypoints ORDER KBAR K_ROB FF_SHARE DELAY_S\n", argv[0]);
    return 2;
  }
  const std::string shape = argv[1];
  auto path = std::make_shared<const Path>(
      shape == "circle" ? Path::circle({0.0, 0.0}, 30.0)
                        : Path::from_waypoints({{0, 0}, {20, 5}, {40, -5}, {60, 10}, {80, 0}}));
  ControllerParameters parameters;
  parameters.chain.order = std::atoi(argv[2]);
  parameters.chain.lead_curvature_bound = std::strtod(argv[3], nullptr);
  parameters.law.k_rob = std::strtod(argv[4], nullptr);
  parameters.feedforward.share = std::strtod(argv[5], nullptr);
  parameters.delay_compensation.actuator_delay_s = std::strtod(argv[6], nullptr);
  parameters.delay_compensation.enabled = parameters.delay_compensation.actuator_delay_s != 0.0;
  const std::string invalid = parameters.validation_error();
  if (!invalid.empty()) {  // the constructor would throw this message
    std::printf("invalid %s\n", invalid.c_str());
    return 0;
  }
  LeadWheelController controller(parameters, path);
  ControllerInput input;
  while (std::scanf("%lf %lf %lf %lf %lf %lf", &input.rear_axle_position.x,
                    &input.rear_axle_position.y, &input.heading_rad, &input.speed_mps,
                    &input.acceleration_mps2, &input.period_s) == 6) {
    ControllerOutput out;
    const Status status = controller.update(input, out);
    const TrackingDiagnostics& d = out.diagnostics;
    std::printf("%s %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", to_string(status),
                out.steering_angle_rad, out.steering_rate_radps, out.steering_acceleration_radps2,
                d.lateral_error_m, d.front_lateral_error_m, d.lead_lateral_error_m,
                d.sliding_variable);
  }
  return 0;
}
