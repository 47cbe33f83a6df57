// Uses the installed headers and library: one closed loop onto a circle must converge.
#include <smoothsteer/smoothsteer.hpp>

#include <cmath>
#include <cstdio>
#include <memory>

int main() {
  using namespace smoothsteer;
  auto path = std::make_shared<const Path>(Path::circle({0.0, 0.0}, 30.0));
  LeadWheelController controller(ControllerParameters{}, path);
  KinematicLoopOptions options;
  options.duration_s = 60.0;
  const KinematicLoopResult result =
      run_kinematic_closed_loop(controller, {{0.0, 0.0}, 0.0}, options);
  const bool converged =
      result.status == Status::ok && std::abs(result.final_lateral_error_m) < 0.01;
  std::printf("consumer: final |e| = %.5f m -> %s\n", std::abs(result.final_lateral_error_m),
              converged ? "ok" : "FAILED");
  return converged ? 0 : 1;
}
