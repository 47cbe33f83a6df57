// Uses the installed headers and libraries the way the README's ten lines do: certified
// parameters for a car from the tuning module, then a closed loop onto a circle that must
// converge with the steering rate within the car's limit; then a gain schedule written and read
// back through io's schedule files.
#include <smoothsteer/io/schedule_files.hpp>
#include <smoothsteer/smoothsteer.hpp>
#include <smoothsteer/tuning/gain_schedule.hpp>

#include <filesystem>

#include <cmath>
#include <cstdio>
#include <memory>

int main() {
  using namespace smoothsteer;
  const VehicleLimits car{.wheelbase_m = 2.9,
                          .max_steering_angle_rad = 0.6,
                          .max_steering_rate_radps = 0.5,
                          .max_steering_acceleration_radps2 = 5.0};
  // A circle: curvature 1/40, curvature rate 0 (the feedforward still ramps up within 10 m).
  const TuningOptions route{.path_curvature_bound = 1.0 / 40.0, .path_curvature_rate_bound = 0.0};
  const ControllerParameters parameters = parameters_for_vehicle(car, 10.0, route);
  auto path = std::make_shared<const Path>(Path::circle({0.0, 0.0}, 40.0));
  LeadWheelController controller(parameters, path);
  KinematicLoopOptions options;
  options.wheelbase_m = car.wheelbase_m;
  options.speed_mps = 10.0;
  options.duration_s = 60.0;
  const KinematicLoopResult result =
      run_kinematic_closed_loop(controller, {{0.0, -41.0}, 0.0}, options);
  const bool within = result.max_abs_steering_difference_rate_radps <= car.max_steering_rate_radps;
  std::printf("consumer: tuned kbar_n = %.5f 1/m, held rate max %.3f rad/s (limit %.1f) -> %s\n",
              parameters.chain.lead_curvature_bound, result.max_abs_steering_difference_rate_radps,
              car.max_steering_rate_radps, within ? "ok" : "FAILED");
  const bool converged =
      within && result.status == Status::ok && std::abs(result.final_lateral_error_m) < 0.01;
  std::printf("consumer: final |e| = %.5f m -> %s\n", std::abs(result.final_lateral_error_m),
              converged ? "ok" : "FAILED");
  // The schedule CSV round trip: io's header exposes tuning's GainSchedule.
  const GainSchedule schedule = compute_feedforward_schedule(car, route, {5.0, 10.0, 15.0});
  const std::string csv =
      (std::filesystem::temp_directory_path() / "smoothsteer_consumer_schedule.csv").string();
  io::write_schedule_csv(schedule, csv);
  const GainSchedule read = io::read_schedule_csv(csv);
  std::filesystem::remove(csv);
  const bool same = read.entries().size() == 3 &&
                    std::abs(read.parameters_at(10.0).chain.lead_curvature_bound -
                             schedule.parameters_at(10.0).chain.lead_curvature_bound) < 1e-9;
  std::printf("consumer: schedule CSV round trip -> %s\n", same ? "ok" : "FAILED");
  return converged && same ? 0 : 1;
}
