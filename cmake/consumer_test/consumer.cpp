// Uses the installed headers and libraries: one closed loop onto a circle must converge, and
// the tuning module's steering-angle bound must invert its curvature bound.
#include <smoothsteer/smoothsteer.hpp>
#include <smoothsteer/tuning/invariant_bounds.hpp>

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
  ControllerParameters parameters;
  const double curvature = lead_curvature_bound_for_steering_angle(parameters, 0.4);
  parameters.lead_curvature_bound = curvature;
  const bool tuning_ok = std::abs(steering_angle_bound(parameters) - 0.4) < 1e-6;
  std::printf("consumer: tuning kbar_n = %.5f 1/m for |delta| <= 0.4 rad -> %s\n", curvature,
              tuning_ok ? "ok" : "FAILED");
  const bool converged =
      tuning_ok && result.status == Status::ok && std::abs(result.final_lateral_error_m) < 0.01;
  std::printf("consumer: final |e| = %.5f m -> %s\n", std::abs(result.final_lateral_error_m),
              converged ? "ok" : "FAILED");
  return converged ? 0 : 1;
}
